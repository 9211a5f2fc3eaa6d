#include "editor/error_dialog.h"

#include <QCoreApplication>
#include <QMessageBox>

#include "editor/qt_conversions.h"

namespace thespis::editor {

namespace {
// QT_TRANSLATE_NOOP marks the literals for lupdate; localized() looks them up at run time.
constexpr const char* kContext = "thespis::editor::ErrorDialog";
QString localized(const char* text)
{
    return QCoreApplication::translate(kContext, text);
}
} // namespace

QString errorTitle(core::ErrorCode code)
{
    switch (code) {
    case core::ErrorCode::FileNotFound: return localized(QT_TRANSLATE_NOOP("thespis::editor::ErrorDialog", "File not found"));
    case core::ErrorCode::NotOurFormat: return localized(QT_TRANSLATE_NOOP("thespis::editor::ErrorDialog", "Not a Thespis file"));
    case core::ErrorCode::CorruptData: return localized(QT_TRANSLATE_NOOP("thespis::editor::ErrorDialog", "The file is damaged"));
    case core::ErrorCode::NewerVersion: return localized(QT_TRANSLATE_NOOP("thespis::editor::ErrorDialog", "Made by a newer Thespis"));
    case core::ErrorCode::NotFound: return localized(QT_TRANSLATE_NOOP("thespis::editor::ErrorDialog", "Not found"));
    case core::ErrorCode::InvalidArgument: return localized(QT_TRANSLATE_NOOP("thespis::editor::ErrorDialog", "Invalid value"));
    case core::ErrorCode::InvalidSchedule: return localized(QT_TRANSLATE_NOOP("thespis::editor::ErrorDialog", "The schedule cannot be built"));
    case core::ErrorCode::IoError: return localized(QT_TRANSLATE_NOOP("thespis::editor::ErrorDialog", "Reading or writing failed"));
    case core::ErrorCode::Cancelled: return localized(QT_TRANSLATE_NOOP("thespis::editor::ErrorDialog", "Cancelled"));
    case core::ErrorCode::Internal: return localized(QT_TRANSLATE_NOOP("thespis::editor::ErrorDialog", "Internal error"));
    }
    return localized(QT_TRANSLATE_NOOP("thespis::editor::ErrorDialog", "Error"));
}

QMessageBox* showError(QWidget* parent, const core::Error& error, const QString& context)
{
    const QString title = errorTitle(error.code);
    auto* box = new QMessageBox(parent);
    box->setObjectName(QStringLiteral("errorMessageBox"));
    box->setAttribute(Qt::WA_DeleteOnClose);
    box->setIcon(error.code == core::ErrorCode::NewerVersion ? QMessageBox::Warning : QMessageBox::Critical);
    box->setWindowTitle(title);
    box->setText(context.isEmpty() ? title : context);
    box->setInformativeText(fromUtf8(error.message));
    if (!error.detail.empty())
        box->setDetailedText(fromUtf8(error.detail));
    box->setStandardButtons(QMessageBox::Ok);
    box->open();
    return box;
}

} // namespace thespis::editor
