// A glTF character's face mapping table in the studio: the character's Properties page shows the
// "Face mapping" row for RobotExpressive (../shared/data) and not for the built-in humanoid; Edit…
// opens the Face Mapping dialog on the table recognised from the model's names, a coefficient
// edited and a target the model lacks named under the table; OK asks where to save (the character
// has no table yet), writes the file and sets the character's table in one undo step, which
// undoes back to the recognised table; edited again, OK saves over the same file and tells the
// views without an undo step. Choose… picks a file, Automatic clears it, each one step.
// The dialog's screenshot is left in <build>/screenshots/face_mapping_dialog.png.

#include <QApplication>
#include <QComboBox>
#include <QDir>
#include <QFileDialog>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QSignalSpy>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QTest>
#include <QUndoStack>

#include "edit/content_edits.h"
#include "editor/character_properties.h"
#include "editor/document.h"
#include "editor/face_mapping_dialog.h"
#include "gui_support.h"
#include "scene/face_mapping.h"

using namespace thespis;
using test::saveScreenshot;
using test::whenModal;

namespace {

QString robotPath()
{
    return QStringLiteral(THESPIS_SHARED_DATA "/characters/RobotExpressive/RobotExpressive.glb");
}

// Answers a file dialog with `path` typed in its file name field.
void answerFileDialog(const QString& path)
{
    whenModal<QFileDialog>([path](QFileDialog* files) {
        files->setDirectory(QFileInfo(path).absolutePath());
        files->findChild<QLineEdit*>(QStringLiteral("fileNameEdit"))->setText(QFileInfo(path).fileName());
        QMetaObject::invokeMethod(files, "accept");
    });
}

int rowOfTarget(const QTableWidget* table, const QString& target)
{
    for (int row = 0; row < table->rowCount(); ++row)
        if (qobject_cast<QComboBox*>(table->cellWidget(row, 0))->currentText() == target)
            return row;
    return -1;
}

} // namespace

class FaceMappingDialogTest : public QObject {
    Q_OBJECT
private slots:
    void init();
    void cleanup();
    void theRowIsForGltfModelsOnly();
    void editedTableIsSavedAndSetInOneUndoStep();
    void chooseAndAutomaticAreOneStepEach();

private:
    std::unique_ptr<QTemporaryDir> m_folder;
    std::unique_ptr<editor::Document> m_document;
    std::unique_ptr<editor::CharacterProperties> m_page;
};

void FaceMappingDialogTest::init()
{
    m_folder = std::make_unique<QTemporaryDir>();
    QVERIFY(m_folder->isValid());
    core::scenario::Scenario scenario;
    scenario.name = "faces";
    scenario.characters.push_back(core::edit::newCharacter("Robot", robotPath().toStdString(), "model"));
    scenario.characters.push_back(core::edit::newCharacter("Ann", "", "hanim-25"));
    auto document = editor::Document::fromScenario(scenario, m_folder->path());
    QVERIFY2(document, document ? "" : document.error().message.c_str());
    m_document = std::move(document).value();
    m_page = std::make_unique<editor::CharacterProperties>();
    m_page->show(m_document.get(), 0);
    // As the Properties panel does: the page follows every change, undo and redo too.
    connect(m_document.get(), &editor::Document::edited, m_page.get(),
            [this] { m_page->show(m_document.get(), m_page->character()); });
    m_page->resize(520, 420);
    m_page->QWidget::show();
}

void FaceMappingDialogTest::cleanup()
{
    m_page.reset();
    m_document.reset();
    m_folder.reset();
}

void FaceMappingDialogTest::theRowIsForGltfModelsOnly()
{
    QVERIFY(m_page->faceMappingLabel()->isVisible());
    QCOMPARE(m_page->faceMappingLabel()->text(), QStringLiteral("Recognised from the model's names"));
    QVERIFY(m_page->editFaceMappingButton()->isVisible());
    QVERIFY(!m_page->automaticFaceButton()->isEnabled()); // already automatic
    saveScreenshot(m_page.get(), QStringLiteral("face_mapping_properties.png"));
    m_page->show(m_document.get(), 1);
    QVERIFY(!m_page->faceMappingLabel()->isVisible());
    QVERIFY(!m_page->editFaceMappingButton()->isVisible());
}

void FaceMappingDialogTest::editedTableIsSavedAndSetInOneUndoStep()
{
    const QString saved = QDir(m_folder->path()).filePath(QStringLiteral("robot_face.json"));
    bool seen = false;
    whenModal<editor::FaceMappingDialog>([&](editor::FaceMappingDialog* dialog) {
        seen = true;
        QTableWidget* drives = dialog->drivesTable();
        // The recognised table: RobotExpressive's expression targets.
        const int angry = rowOfTarget(drives, QStringLiteral("Angry"));
        QVERIFY(angry >= 0);
        QCOMPARE(qobject_cast<QComboBox*>(drives->cellWidget(angry, 1))->currentText(), QStringLiteral("anger"));
        QVERIFY(dialog->missingLabel()->text().contains(QStringLiteral("Every morph target")));
        auto* coefficient = qobject_cast<QLineEdit*>(drives->cellWidget(angry, 2));
        coefficient->selectAll();
        QTest::keyClicks(coefficient, QStringLiteral("0.5"));
        // A row for a target the robot lacks is named under the table.
        for (QPushButton* button : dialog->findChildren<QPushButton*>())
            if (button->text() == QStringLiteral("Add Drive"))
                button->click();
        const int added = drives->rowCount() - 1;
        qobject_cast<QComboBox*>(drives->cellWidget(added, 0))->setCurrentText(QStringLiteral("Smile_Wide"));
        QVERIFY2(dialog->missingLabel()->text().contains(QStringLiteral("“Smile_Wide”")),
                 qPrintable(dialog->missingLabel()->text()));
        saveScreenshot(dialog, QStringLiteral("face_mapping_dialog.png"));
        answerFileDialog(saved);
        dialog->accept();
    });
    const int steps = m_document->undoStack()->count();
    m_page->editFaceMappingButton()->click();
    QVERIFY(seen);
    QCOMPARE(m_document->scenario().characters[0].faceMapping, std::string("robot_face.json"));
    QCOMPARE(m_document->undoStack()->count(), steps + 1);
    QCOMPARE(m_page->faceMappingLabel()->text(), QStringLiteral("robot_face.json"));
    auto table = core::scene::loadFaceMapping(saved.toStdString());
    QVERIFY2(table, table ? "" : table.error().message.c_str());
    const auto angry = std::find_if(table->drives.begin(), table->drives.end(),
                                    [](const core::scene::FaceMappingDrive& d) { return d.target == "Angry"; });
    QVERIFY(angry != table->drives.end());
    QCOMPARE(angry->coefficient, 0.5);
    QCOMPARE(table->drives.back().target, std::string("Smile_Wide"));

    // One undo gives back the recognised table; redo the file again.
    m_document->undoStack()->undo();
    QVERIFY(m_document->scenario().characters[0].faceMapping.empty());
    QCOMPARE(m_page->faceMappingLabel()->text(), QStringLiteral("Recognised from the model's names"));
    m_document->undoStack()->redo();
    QCOMPARE(m_document->scenario().characters[0].faceMapping, std::string("robot_face.json"));

    // Edited again, the dialog starts from the file, and OK saves it there without asking.
    whenModal<editor::FaceMappingDialog>([&](editor::FaceMappingDialog* dialog) {
        QTableWidget* drives = dialog->drivesTable();
        QCOMPARE(qobject_cast<QLineEdit*>(drives->cellWidget(rowOfTarget(drives, QStringLiteral("Angry")), 2))->text(),
                 QStringLiteral("0.5"));
        drives->setCurrentCell(rowOfTarget(drives, QStringLiteral("Smile_Wide")), 0);
        for (QPushButton* button : dialog->findChildren<QPushButton*>())
            if (button->text() == QStringLiteral("Remove Drive"))
                button->click();
        QVERIFY(dialog->missingLabel()->text().contains(QStringLiteral("Every morph target")));
        dialog->accept();
    });
    QSignalSpy edited(m_document.get(), &editor::Document::edited);
    const int before = m_document->undoStack()->count();
    m_page->editFaceMappingButton()->click();
    QCOMPARE(edited.count(), 1); // the views read the table anew
    QCOMPARE(m_document->undoStack()->count(), before); // nothing in the document to undo
    table = core::scene::loadFaceMapping(saved.toStdString());
    QVERIFY(table);
    QVERIFY(std::none_of(table->drives.begin(), table->drives.end(),
                         [](const core::scene::FaceMappingDrive& d) { return d.target == "Smile_Wide"; }));
}

void FaceMappingDialogTest::chooseAndAutomaticAreOneStepEach()
{
    QDir(m_folder->path()).mkpath(QStringLiteral("tables"));
    const QString file = QDir(m_folder->path()).filePath(QStringLiteral("tables/joy.json"));
    core::scene::FaceMapping mapping;
    mapping.drives = {{"Surprised", core::scene::expressionChannel(1), 1.0, core::scene::MorphDrive::Side::Both}};
    QVERIFY(core::scene::saveFaceMapping(file.toStdString(), mapping));
    const int steps = m_document->undoStack()->count();
    answerFileDialog(file);
    m_page->chooseFaceMappingButton()->click();
    QCOMPARE(m_document->scenario().characters[0].faceMapping, std::string("tables/joy.json"));
    QCOMPARE(m_document->undoStack()->count(), steps + 1);
    QCOMPARE(m_page->faceMappingLabel()->text(), QDir::toNativeSeparators(QStringLiteral("tables/joy.json")));
    QVERIFY(m_page->automaticFaceButton()->isEnabled());
    m_page->automaticFaceButton()->click();
    QVERIFY(m_document->scenario().characters[0].faceMapping.empty());
    QCOMPARE(m_document->undoStack()->count(), steps + 2);
    m_document->undoStack()->undo();
    QCOMPARE(m_document->scenario().characters[0].faceMapping, std::string("tables/joy.json"));
    m_document->undoStack()->undo();
    QVERIFY(m_document->scenario().characters[0].faceMapping.empty());
}

QTEST_MAIN(FaceMappingDialogTest)
#include "face_mapping_dialog_test.moc"
