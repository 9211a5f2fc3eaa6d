#pragma once
// What the studio checks and decides before its window exists: which scenario to open, and
// whether there is a display to open a window on (and, when there is none, what to tell the
// user instead of letting Qt abort).

#include <QString>
#include <QStringList>

#include <string>

namespace thespis::studio {

/// The built-in demo scenario: next to an installed binary (../share/thespis/demo.thespis),
/// else in the source tree the binary was built from. `applicationDir` is the binary's folder.
QString defaultScenarioPath(const QString& applicationDir);

/// A file shipped beside the demo (`relative` to its folder, e.g. "motion/cmu_standing.idle",
/// which "Idle" in the clip library plays); empty when it is missing.
QString shippedResource(const QString& applicationDir, const QString& relative);

/// The folder of the running binary (before any QCoreApplication exists).
QString executableDir(const char* argv0);

/// Empty when a window can probably be opened: QT_QPA_PLATFORM or a -platform argument chooses
/// the platform, or DISPLAY / WAYLAND_DISPLAY is set (always empty off Linux). Otherwise the
/// reason, for noDisplayHelp().
QString missingDisplayReason(const QStringList& arguments);

/// Where thespis-cli is for a studio binary in `applicationDir` (installed or build tree), or
/// plain "thespis-cli" when it is not there.
QString commandLinePath(const QString& applicationDir);

/// The text printed instead of a window: how to get a display, or how to use the command line
/// instead. The paths are used in the example commands, with the scenario's first character's
/// name when it can be read.
QString noDisplayHelp(const QString& reason, const QString& scenarioPath, const QString& studioPath,
                      const QString& cliPath);

/// Installs a Qt message handler that, while the QApplication is being constructed, turns
/// Qt's fatal "could not connect to display" into noDisplayHelp() and exit code 3 instead of an
/// abort. Call before constructing QApplication; call finish…() once it exists.
void installDisplayFailureHandler(const QString& scenarioPath, const QString& studioPath, const QString& cliPath);
void finishDisplayFailureHandler();

/// Exit code when no display is available (also used by scripts/run-studio.sh).
inline constexpr int NoDisplayExitCode = 3;

} // namespace thespis::studio
