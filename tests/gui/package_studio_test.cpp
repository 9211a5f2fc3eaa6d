// Scenario packages in the studio, as a user goes: the demo open, File ▸ Export ▸ Package… lists
// what goes in with sizes, exports with progress, and the package opens with File ▸ Open like a
// scenario (playing from the package: the same scenario, the window titled by it); Save As
// writes the scenario and the package's files into a folder, byte-identical. A scenario naming
// a file that is missing says which field, and Export waits. Screenshots of each step.

#include <QAction>
#include <QCheckBox>
#include <QApplication>
#include <QDir>
#include <QJsonDocument>
#include <QJsonObject>
#include <QFile>
#include <QLabel>
#include <QLineEdit>
#include <QProgressBar>
#include <QPushButton>
#include <QSettings>
#include <QStandardPaths>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QTest>
#include <QTimer>

#include <functional>

#include "edit/document_edits.h"
#include "editor/autosave.h"
#include "editor/document.h"
#include "editor/export_package_dialog.h"
#include "editor/translations.h"
#include "gui_support.h"
#include "main_window.h"
#include "scenario/package.h"
#include "scenario/package_export_job.h"
#include "scenario/scenario_io.h"

using namespace thespis;
using test::saveScreenshot;
using test::whenModal;

namespace {

QByteArray bytesOf(const QString& path)
{
    QFile file(path);
    return file.open(QIODevice::ReadOnly) ? file.readAll() : QByteArray();
}

} // namespace

class PackageStudioTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void init();
    void cleanup();
    void exportOpenAndSaveAPackage();
    void aMissingFileIsSaidBeforeExporting();
    void bakesTheLightingFirstWhenAsked();
    void recoveredWorkPlaysFromItsPackageAgain();

private:
    std::unique_ptr<studio::MainWindow> m_window;
    QTemporaryDir m_dir;
};

void PackageStudioTest::initTestCase()
{
    editor::installTranslators(*QCoreApplication::instance(), QLocale(QLocale::English));
}

void PackageStudioTest::init()
{
    QStandardPaths::setTestModeEnabled(true);
    QSettings().clear();
    m_window = std::make_unique<studio::MainWindow>();
    m_window->resize(1400, 900);
    m_window->show();
    QVERIFY(QTest::qWaitForWindowExposed(m_window.get()));
}

void PackageStudioTest::cleanup()
{
    m_window.reset();
}

void PackageStudioTest::exportOpenAndSaveAPackage()
{
    const QString demo = QStringLiteral(THESPIS_RESOURCES "/demo.thespis");
    QVERIFY(m_window->openScenario(demo));
    const core::scenario::Scenario original = m_window->document()->scenario();
    const QString package = m_dir.filePath(QStringLiteral("antigone.thespkg"));

    // File ▸ Export ▸ Package…: the dialog lists the scenario, its two motion files and the bot
    // its script hands Antigone to.
    bool exported = false;
    whenModal<editor::ExportPackageDialog>([&](editor::ExportPackageDialog* dialog) {
        QTableWidget* table = dialog->contentsTable();
        QCOMPARE(table->rowCount(), 4);
        QCOMPARE(table->item(0, 0)->text(), QStringLiteral("demo.thespis"));
        QCOMPARE(table->item(1, 0)->text(), QStringLiteral("motion/cmu_standing.idle"));
        QVERIFY(table->item(1, 2)->text().contains(QStringLiteral("idle.database")));
        QCOMPARE(table->item(2, 0)->text(), QStringLiteral("motion/cmu_postures.pca"));
        QVERIFY(!table->item(2, 1)->text().isEmpty());
        QCOMPARE(table->item(3, 0)->text(), QStringLiteral("dialogue/antigone/antigone.aiml"));
        QVERIFY(dialog->exportButton()->isEnabled());
        saveScreenshot(dialog, QStringLiteral("package_export_dialog.png"));
        dialog->setOutput(m_dir.filePath(QStringLiteral("antigone")));
        QCOMPARE(QDir::fromNativeSeparators(dialog->outputEdit()->text()), package);
        QTest::mouseClick(dialog->exportButton(), Qt::LeftButton);
        QTRY_VERIFY_WITH_TIMEOUT(!dialog->isExporting(), 30000);
        QVERIFY2(dialog->messageLabel()->text().startsWith(QStringLiteral("Wrote ")), qPrintable(dialog->messageLabel()->text()));
        QCOMPARE(dialog->progressBar()->text(), QStringLiteral("Exported"));
        saveScreenshot(dialog, QStringLiteral("package_exported.png"));
        exported = true;
        dialog->reject();
    });
    m_window->findChild<QAction*>(QStringLiteral("exportPackage"))->trigger();
    QVERIFY(exported);
    auto opened = core::scenario::Package::open(package.toStdString());
    QVERIFY2(opened, opened ? "" : opened.error().message.c_str());
    QCOMPARE(int((*opened)->manifest().entries.size()), 4);

    // File ▸ Open on the package: the scenario plays from it, the window named by it.
    QVERIFY(m_window->openScenario(package));
    editor::Document* document = m_window->document();
    QCOMPARE(document->packagePath(), package);
    QVERIFY(document->filePath().isEmpty());
    QCOMPARE(document->fileName(), QStringLiteral("antigone.thespkg"));
    QCOMPARE(document->scenario(), original);
    QCOMPARE(m_window->findChild<QLabel*>(QStringLiteral("fileLabel"))->text(), QStringLiteral("antigone.thespkg"));
    m_window->clock()->seek(core::secondsToTicks(3.0));
    QTest::qWait(200);
    saveScreenshot(m_window.get(), QStringLiteral("package_opened.png"));

    // Save As writes the scenario and the package's files beside it.
    const QString saved = m_dir.filePath(QStringLiteral("saved/antigone.thespis"));
    QVERIFY(QDir().mkpath(m_dir.filePath(QStringLiteral("saved"))));
    QVERIFY(m_window->saveAs(saved));
    QVERIFY(m_window->document()->packagePath().isEmpty());
    for (const char* name : {"motion/cmu_standing.idle", "motion/cmu_postures.pca", "dialogue/antigone/antigone.aiml"})
        QCOMPARE(bytesOf(m_dir.filePath(QStringLiteral("saved/") + QLatin1String(name))),
                 bytesOf(QStringLiteral(THESPIS_RESOURCES "/") + QLatin1String(name)));
    auto reloaded = core::scenario::loadScenario(saved.toStdString());
    QVERIFY(reloaded);
    QCOMPARE(*reloaded, original);
    QVERIFY(m_window->openScenario(saved));
}

void PackageStudioTest::aMissingFileIsSaidBeforeExporting()
{
    core::scenario::Scenario scenario;
    scenario.name = "missing";
    core::scenario::Character character;
    character.name = "Creon";
    character.bake = "bakes/creon.prt";
    scenario.characters.push_back(character);
    auto document = editor::Document::fromScenario(scenario, m_dir.path());
    QVERIFY(document);
    editor::ExportPackageDialog dialog(**document, m_window.get());
    dialog.show();
    QVERIFY(QTest::qWaitForWindowExposed(&dialog));
    const QLabel* summary = dialog.findChild<QLabel*>(QStringLiteral("packageSummary"));
    QVERIFY2(summary->text().contains(QStringLiteral("characters[Creon].bake names bakes/creon.prt")), qPrintable(summary->text()));
    QVERIFY(!dialog.exportButton()->isEnabled());
    QVERIFY(!dialog.exportPackage());
    saveScreenshot(&dialog, QStringLiteral("package_missing_file.png"));
}

void PackageStudioTest::bakesTheLightingFirstWhenAsked()
{
    QVERIFY(m_window->openScenario(QStringLiteral(THESPIS_RESOURCES "/demo.thespis")));
    const QString package = m_dir.filePath(QStringLiteral("baked.thespkg"));
    bool exported = false;
    whenModal<editor::ExportPackageDialog>([&](editor::ExportPackageDialog* dialog) {
        QVERIFY(!dialog->bakeCheck()->isChecked());
        dialog->bakeCheck()->setChecked(true);
        dialog->setOutput(package);
        QTest::mouseClick(dialog->exportButton(), Qt::LeftButton);
        QVERIFY(!dialog->bakeCheck()->isEnabled());
        QTRY_VERIFY_WITH_TIMEOUT(!dialog->isExporting(), 300000);
        const QString message = dialog->messageLabel()->text();
        QVERIFY2(message.contains(QStringLiteral("Baked the lighting of Creon: it had none.")), qPrintable(message));
        QVERIFY2(message.contains(QStringLiteral("Baked the lighting of Antigone: it had none.")), qPrintable(message));
        saveScreenshot(dialog, QStringLiteral("package_baked.png"));
        exported = true;
        dialog->reject();
    });
    m_window->findChild<QAction*>(QStringLiteral("exportPackage"))->trigger();
    QVERIFY(exported);
    auto opened = core::scenario::Package::open(package.toStdString());
    QVERIFY2(opened, opened ? "" : opened.error().message.c_str());
    QStringList names;
    for (const core::scenario::PackageEntry& entry : (*opened)->manifest().entries)
        names << QString::fromStdString(entry.name);
    QVERIFY2(names.contains(QStringLiteral("bakes/Creon.prt")) && names.contains(QStringLiteral("bakes/Antigone.prt")),
             qPrintable(names.join(QLatin1Char(' '))));
    QVERIFY(!QFileInfo::exists(QStringLiteral(THESPIS_RESOURCES "/bakes")));
}

void PackageStudioTest::recoveredWorkPlaysFromItsPackageAgain()
{
    const QString package = m_dir.filePath(QStringLiteral("recover.thespkg"));
    core::scenario::ExportPackageJob job;
    job.scenario = core::scenario::loadScenario(THESPIS_RESOURCES "/demo.thespis").value();
    job.assets = core::scenario::Assets(THESPIS_RESOURCES);
    job.scenarioEntry = "demo.thespis";
    job.output = package.toStdString();
    core::JobContext context;
    QVERIFY(job.run(context));

    QVERIFY(m_window->openScenario(package));
    editor::Document* document = m_window->document();
    editor::Autosaver saver;
    saver.setDocument(document);
    const std::vector<core::edit::ActionPath> first{{0, 0, 1}};
    QVERIFY(document->edit(core::edit::moveActions(document->scenario(), first, core::TicksPerSecond), QStringLiteral("Move")));
    QVERIFY(saver.saveNow());
    QFile sidecar(QFileInfo(saver.recoveryFile()).absolutePath() + QLatin1Char('/') +
                  QFileInfo(saver.recoveryFile()).completeBaseName() + QStringLiteral(".json"));
    QVERIFY(sidecar.open(QIODevice::ReadOnly));
    QCOMPARE(QJsonDocument::fromJson(sidecar.readAll()).object().value(QStringLiteral("package")).toString(), package);

    // Recovered, the work plays from the package again (its idle database and posture bases are
    // inside it), unsaved, named by the package.
    auto recovered = editor::Document::recover(saver.recoveryFile(), QString(), document->baseDir(), package);
    QVERIFY2(recovered, recovered ? "" : recovered.error().message.c_str());
    QCOMPARE((*recovered)->packagePath(), package);
    QVERIFY((*recovered)->isModified());
    QCOMPARE((*recovered)->fileName(), QStringLiteral("recover.thespkg"));
    QVERIFY((*recovered)->scenario() == document->scenario());
    QVERIFY((*recovered)->warnings().isEmpty());
    saver.discard();
}

QTEST_MAIN(PackageStudioTest)
#include "package_studio_test.moc"
