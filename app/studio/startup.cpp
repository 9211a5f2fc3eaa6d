#include "startup.h"

#include <QDir>
#include <QFileInfo>
#include <QtGlobal>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <system_error>

#include "editor/document.h"
#include "editor/qt_conversions.h"

namespace thespis::studio {

QString defaultScenarioPath(const QString& applicationDir)
{
    const QString installed = QDir(applicationDir).filePath(QStringLiteral("../share/thespis/demo.thespis"));
    if (QFileInfo::exists(installed))
        return QDir::cleanPath(installed);
    return QStringLiteral(THESPIS_SOURCE_RESOURCES "/demo.thespis");
}

QString shippedResource(const QString& applicationDir, const QString& relative)
{
    const QString path = QFileInfo(defaultScenarioPath(applicationDir)).dir().filePath(relative);
    return QFileInfo::exists(path) ? QDir::cleanPath(path) : QString();
}

QString executableDir(const char* argv0)
{
#ifdef Q_OS_LINUX
    // The real binary, also when started through a symbolic link or from the PATH.
    std::error_code error;
    const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", error);
    if (!error)
        return editor::fromFsPath(self.parent_path());
#endif
    return QFileInfo(QString::fromLocal8Bit(argv0)).absolutePath();
}

QString missingDisplayReason(const QStringList& arguments)
{
#ifdef Q_OS_LINUX
    if (!qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM") || arguments.contains(QStringLiteral("-platform")))
        return {};
    if (!qEnvironmentVariableIsEmpty("DISPLAY") || !qEnvironmentVariableIsEmpty("WAYLAND_DISPLAY"))
        return {};
    return QStringLiteral("neither DISPLAY nor WAYLAND_DISPLAY is set");
#else
    Q_UNUSED(arguments)
    return {};
#endif
}

QString commandLinePath(const QString& applicationDir)
{
    // Beside the studio when installed; app/cli/ next to app/studio/ in a build tree.
    for (const QString& candidate : {QStringLiteral("thespis-cli"), QStringLiteral("../cli/thespis-cli")}) {
        const QString path = QDir(applicationDir).filePath(candidate);
        if (QFileInfo(path).isExecutable())
            return QDir::cleanPath(path);
    }
    return QStringLiteral("thespis-cli");
}

QString noDisplayHelp(const QString& reason, const QString& scenarioPath, const QString& studioPath,
                      const QString& cliPath)
{
    // Plain English on purpose: this is printed before any translator is installed.
    const QString scenario = scenarioPath.isEmpty() ? QStringLiteral("resources/demo.thespis") : scenarioPath;
    // A real character name makes the bake-motion example runnable as printed.
    QString character = editor::Document::firstCharacterName(scenario);
    if (character.isEmpty())
        character = QStringLiteral("NAME");
    return QStringLiteral(
               "thespis: cannot open the studio window: no display (%1).\n"
               "\n"
               "To get a display:\n"
               "  - run it on a virtual X server:  xvfb-run -a scripts/studio.sh\n"
               "                                   (or xvfb-run -a %4 %2)\n"
               "  - log in with X forwarding:      ssh -X user@this-machine, then scripts/studio.sh\n"
               "  - or set DISPLAY / WAYLAND_DISPLAY to a running display, or QT_QPA_PLATFORM to a Qt\n"
               "    platform (QT_QPA_PLATFORM=offscreen runs without showing anything, for tests).\n"
               "\n"
               "Or use the engine without a window, from the command line:\n"
               "  %5 validate %2\n"
               "  %5 info %2\n"
               "  %5 bake-motion %2 --character %3 --fps 30 --out motion.bvh\n"
               "  (info lists the characters, clips and actions; open motion.bvh in Blender)\n")
        .arg(reason, scenario, character, studioPath.isEmpty() ? QStringLiteral("thespis") : studioPath,
             cliPath.isEmpty() ? QStringLiteral("thespis-cli") : cliPath);
}

namespace {

QString g_scenarioPath, g_studioPath, g_cliPath;
bool g_constructing = false;
QtMessageHandler g_previousHandler = nullptr;

void displayFailureHandler(QtMsgType type, const QMessageLogContext& context, const QString& message)
{
    if (type == QtFatalMsg && g_constructing) {
        // Qt could not initialise its platform plugin (e.g. DISPLAY points to nothing). Say
        // what to do and exit, instead of Qt's abort() and core dump.
        std::fprintf(stderr, "%s\n\n%s", qPrintable(message),
                     qPrintable(noDisplayHelp(QStringLiteral("Qt could not connect to one"), g_scenarioPath,
                                               g_studioPath, g_cliPath)));
        std::fflush(stderr);
        std::_Exit(NoDisplayExitCode);
    }
    if (g_previousHandler)
        g_previousHandler(type, context, message);
    else
        std::fprintf(stderr, "%s\n", qPrintable(qFormatLogMessage(type, context, message)));
}

} // namespace

void installDisplayFailureHandler(const QString& scenarioPath, const QString& studioPath, const QString& cliPath)
{
    g_scenarioPath = scenarioPath;
    g_studioPath = studioPath;
    g_cliPath = cliPath;
    g_constructing = true;
    g_previousHandler = qInstallMessageHandler(displayFailureHandler);
}

void finishDisplayFailureHandler()
{
    g_constructing = false;
    qInstallMessageHandler(g_previousHandler);
}

} // namespace thespis::studio
