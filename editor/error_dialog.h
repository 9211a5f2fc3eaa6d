#pragma once
// The one way the studio shows a core::Error to the user (STYLE.md §3): the error code becomes a
// translated title, the message the text, the detail goes behind "Show Details…".

#include <QString>

#include "util/error.h"

class QMessageBox;
class QWidget;

namespace thespis::editor {

/// Translated title for an error code ("The file is damaged").
QString errorTitle(core::ErrorCode code);

/// Opens a window-modal message box over `parent` and returns at once (the box deletes itself
/// when closed), so that callers, timers and tests keep running. `context` says what was being
/// done ("Could not open “demo.thespis”."); empty: the title is used.
QMessageBox* showError(QWidget* parent, const core::Error& error, const QString& context = {});

} // namespace thespis::editor
