// MainWindow's file handling: new (with a starting point), open (a scenario or a package),
// reload, save, save as, export a package, recent files and recovering autosaved work. The rest of the window is in main_window.cpp.

#include "main_window.h"

#include <QCoreApplication>
#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QLocale>
#include <QMenu>
#include <QMessageBox>
#include <QPushButton>
#include <QSettings>
#include <QStatusBar>

#include "editor/script_trust.h"
#include "editor/autosave.h"
#include "editor/error_dialog.h"
#include "editor/export_motion_dialog.h"
#include "editor/export_package_dialog.h"
#include "editor/qt_conversions.h"
#include "editor/new_document.h"
#include "startup.h"

namespace thespis::studio {

namespace {
constexpr int kMaxRecentFiles = 8;
const QString kRecentFilesKey = QStringLiteral("recentFiles");
} // namespace

bool MainWindow::openScenario(const QString& path)
{
    core::Result<std::unique_ptr<editor::Document>> document = editor::Document::open(path);
    if (!document) {
        editor::showError(this, document.error(),
                          tr("Could not open “%1”.").arg(QFileInfo(path).fileName()));
        statusBar()->showMessage(tr("Could not open %1").arg(QDir::toNativeSeparators(path)), 10000);
        return false;
    }
    setDocument(std::move(*document));
    addRecentFile(this->document()->sourceFile());
    return true;
}

void MainWindow::onOpen()
{
    const QString start = document() && !document()->filePath().isEmpty()
                              ? QFileInfo(document()->filePath()).absolutePath()
                              : QString();
    const QString path = QFileDialog::getOpenFileName(this, tr("Open Scenario"), start,
                                                      tr("Thespis scenarios and packages (*.thespis *.thespkg);;All files (*)"));
    if (!path.isEmpty())
        openScenario(path);
}

void MainWindow::onReload()
{
    if (!document() || document()->filePath().isEmpty())
        return;
    // A copy: opening replaces the document that owns the path.
    const QString path = document()->filePath();
    const core::Tick time = m_clock->time();
    if (openScenario(path))
        m_clock->seek(time);
}

void MainWindow::onNew()
{
    if (!maybeSave())
        return;
    QMessageBox ask(QMessageBox::Question, tr("New Scenario"), tr("What should the new scenario start with?"),
                    QMessageBox::Cancel, this);
    ask.setObjectName(QStringLiteral("newScenarioQuestion"));
    ask.setInformativeText(tr("Either way, File ▸ Import Motion… brings in motion capture, Character ▸ Add "
                              "Character… more characters, and View ▸ Lighting… a light probe."));
    QPushButton* withCharacter = ask.addButton(tr("One Character, Standing"), QMessageBox::AcceptRole);
    withCharacter->setObjectName(QStringLiteral("newWithCharacter"));
    QPushButton* empty = ask.addButton(tr("Empty"), QMessageBox::AcceptRole);
    empty->setObjectName(QStringLiteral("newEmpty"));
    ask.setDefaultButton(withCharacter);
    ask.exec();
    if (ask.clickedButton() != withCharacter && ask.clickedButton() != empty)
        return;
    newScenario(ask.clickedButton() == withCharacter);
}

void MainWindow::newScenario(bool withCharacter)
{
    auto document = editor::newDocument(withCharacter, defaultScenarioPath(QCoreApplication::applicationDirPath()),
                                        QDir::homePath());
    if (!document) {
        editor::showError(this, document.error(), tr("Could not start a new scenario."));
        return;
    }
    setDocument(std::move(*document));
}

bool MainWindow::save()
{
    if (!document())
        return false;
    if (document()->filePath().isEmpty())
        return onSaveAs();
    return saveAs(document()->filePath());
}

bool MainWindow::saveAs(const QString& path)
{
    if (!document())
        return false;
    if (auto saved = document()->saveAs(path); !saved) {
        editor::showError(this, saved.error(), tr("Could not save “%1”.").arg(QFileInfo(path).fileName()));
        return false;
    }
    m_autosaver->discard();
    editor::ScriptTrust::trust(document()->filePath()); // the user's own file now
    addRecentFile(document()->filePath());
    m_reloadAction->setEnabled(true);
    statusBar()->showMessage(tr("Saved %1").arg(QDir::toNativeSeparators(document()->filePath())), 5000);
    updateTitle();
    return true;
}

bool MainWindow::onSaveAs()
{
    if (!document())
        return false;
    QString path = QFileDialog::getSaveFileName(this, tr("Save Scenario As"), document()->filePath(),
                                                tr("Thespis scenarios (*.thespis)"));
    if (path.isEmpty())
        return false;
    if (!path.endsWith(QStringLiteral(".thespis")))
        path += QStringLiteral(".thespis");
    return saveAs(path);
}

void MainWindow::onExportPackage()
{
    if (!document())
        return;
    editor::ExportPackageDialog dialog(*document(), this);
    connect(&dialog, &editor::ExportPackageDialog::exported, this, [this](const QString& path) {
        statusBar()->showMessage(tr("Exported %1").arg(QDir::toNativeSeparators(path)), 5000);
    });
    dialog.exec();
}

void MainWindow::onExportMotion()
{
    if (!document())
        return;
    editor::ExportMotionDialog dialog(*document(), currentCharacter(), this);
    connect(&dialog, &editor::ExportMotionDialog::exported, this, [this](const QString& path) {
        statusBar()->showMessage(tr("Exported %1").arg(QDir::toNativeSeparators(path)), 5000);
    });
    dialog.exec();
}

bool MainWindow::maybeSave()
{
    if (!document() || !document()->isModified())
        return true;
    const auto answer = QMessageBox::question(this, tr("Unsaved Changes"),
                                              tr("“%1” has changes that are not saved. Save them?").arg(document()->fileName()),
                                              QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel, QMessageBox::Save);
    if (answer == QMessageBox::Save)
        return save();
    return answer == QMessageBox::Discard;
}

void MainWindow::addRecentFile(const QString& path)
{
    QSettings settings;
    QStringList files = settings.value(kRecentFilesKey).toStringList();
    files.removeAll(path);
    files.prepend(path);
    while (files.size() > kMaxRecentFiles)
        files.removeLast();
    settings.setValue(kRecentFilesKey, files);
    updateRecentMenu();
}

void MainWindow::updateRecentMenu()
{
    if (!m_recentMenu)
        return;
    m_recentMenu->clear();
    const QStringList files = QSettings().value(kRecentFilesKey).toStringList();
    for (const QString& file : files)
        m_recentMenu->addAction(QFileInfo(file).fileName(), this, [this, file] {
            if (maybeSave())
                openScenario(file);
        })->setStatusTip(QDir::toNativeSeparators(file));
    m_recentMenu->setEnabled(!files.isEmpty());
}

bool MainWindow::offerRecovery()
{
    const QList<editor::Autosaver::Recovery> found = editor::Autosaver::pendingRecoveries();
    if (found.isEmpty())
        return false;
    const editor::Autosaver::Recovery& newest = found.front();
    const QString source = newest.originalPath.isEmpty() ? newest.packagePath : newest.originalPath;
    const QString name = source.isEmpty() ? tr("an unsaved scenario") : QFileInfo(source).fileName();
    const auto answer = QMessageBox::question(
        this, tr("Recover Unsaved Work"),
        tr("Thespis Studio did not close properly. Recover the changes to %1 autosaved at %2?")
            .arg(name, QLocale().toString(newest.savedAt.toLocalTime(), QLocale::ShortFormat)),
        QMessageBox::Yes | QMessageBox::Discard, QMessageBox::Yes);
    bool recovered = false;
    if (answer == QMessageBox::Yes) {
        auto document = editor::Document::recover(newest.recoveryFile, newest.originalPath, newest.baseDir, newest.packagePath);
        if (document) {
            setDocument(std::move(*document));
            statusBar()->showMessage(tr("Recovered %1; save it to keep it.").arg(name));
            recovered = true;
        } else {
            editor::showError(this, document.error(), tr("Could not recover %1.").arg(name));
        }
    }
    for (const editor::Autosaver::Recovery& recovery : found)
        editor::Autosaver::removeRecovery(recovery);
    return recovered;
}

} // namespace thespis::studio
