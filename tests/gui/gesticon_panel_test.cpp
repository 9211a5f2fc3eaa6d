// The gesticon editor (GesticonPanel over GesticonModel) on the demo scenario: the table lists
// each character's gestures; add, rename, fades, clip, body part and the dependent-joint filter
// are one undoable edit each, refused edits change nothing and say why, remove takes one step
// however many rows, and undoing everything gives back the original document. Preview plays a
// gesture on the character in a real 3D view (Xvfb + Mesa): the arm inside the gesture's mask
// moves, the other arm does not, and the document's own motion comes back when the gesture ends,
// when the clock is paused, on Stop and on any edit. Before / After plays it without, then with,
// the dependent-joint filter.

#include <QComboBox>
#include <QDir>
#include <QDoubleSpinBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QSignalSpy>
#include <QTableView>
#include <QTest>
#include <QToolButton>
#include <QUndoStack>

#include <algorithm>
#include <cmath>

#include "editor/document.h"
#include "editor/gesticon_model.h"
#include "editor/gesticon_panel.h"
#include "editor/playback_clock.h"
#include "editor/scene_preview.h"
#include "editor/session.h"
#include "editor/translations.h"
#include "render/character_node.h"
#include "scene/fap.h"
#include "studio_support.h"
#include "util/tick.h"
#include "widgets/osg_viewport.h"

using namespace thespis;
using test::angleBetween;
using test::rotationOf;
using editor::GesticonModel;
using editor::GesticonPanel;

namespace {

QString demoPath() { return QStringLiteral(THESPIS_RESOURCES "/demo.thespis"); }

void saveScreenshot(QWidget* widget, const QString& name)
{
    QDir().mkpath(QStringLiteral(THESPIS_SCREENSHOT_DIR));
    QVERIFY(widget->grab().save(QStringLiteral(THESPIS_SCREENSHOT_DIR "/") + name));
}

QString cell(const GesticonModel& model, int row, int column, int role = Qt::DisplayRole)
{
    return model.data(model.index(row, column), role).toString();
}

std::unique_ptr<editor::Document> openDemo()
{
    auto document = editor::Document::open(demoPath());
    if (!document)
        qFatal("cannot open the demo: %s", document.error().message.c_str());
    return std::move(document).value();
}

float largestDistance(std::span<const core::anim::Vec3> a, std::span<const core::anim::Vec3> b)
{
    float largest = 0;
    for (std::size_t i = 0; i < std::min(a.size(), b.size()); ++i) {
        const float dx = a[i].x - b[i].x, dy = a[i].y - b[i].y, dz = a[i].z - b[i].z;
        largest = std::max(largest, std::sqrt(dx * dx + dy * dy + dz * dz));
    }
    return largest;
}

} // namespace

class GesticonPanelTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void listsEachCharactersGestures();
    void everyEditIsOneUndoStepAndUndoAllRestores();
    void editorsInTheTableEditTheDocument();
    void previewIsDisabledWithoutASession();
    void previewPlaysTheGestureOnTheCharacter();
    void aFaceGesturePreviewsOnTheFace();
};

void GesticonPanelTest::initTestCase()
{
    // English text and numbers ("0.40"), whatever the machine's locale.
    QLocale::setDefault(QLocale(QLocale::English, QLocale::UnitedStates));
    editor::installTranslators(*QCoreApplication::instance(), QLocale(QLocale::English));
}

void GesticonPanelTest::listsEachCharactersGestures()
{
    auto document = openDemo();
    GesticonPanel panel;
    panel.resize(640, 280);
    panel.setDocument(document.get());
    panel.show();
    QVERIFY(QTest::qWaitForWindowExposed(&panel));
    const GesticonModel& model = *panel.model();

    QCOMPARE(panel.currentCharacter(), 0);
    QCOMPARE(panel.characterCombo()->currentText(), QStringLiteral("Creon"));
    QCOMPARE(model.rowCount(), 3);
    QCOMPARE(model.columnCount(), 9);
    QCOMPARE(model.headerData(GesticonModel::MaskColumn, Qt::Horizontal).toString(), QStringLiteral("Body part"));
    QCOMPARE(cell(model, 0, GesticonModel::NameColumn), QStringLiteral("greet"));
    QCOMPARE(cell(model, 0, GesticonModel::ClipColumn), QStringLiteral("wave"));
    QCOMPARE(cell(model, 0, GesticonModel::MaskColumn), QStringLiteral("rightArm"));
    QCOMPARE(cell(model, 0, GesticonModel::FadeInColumn), QStringLiteral("0.40"));
    QCOMPARE(cell(model, 0, GesticonModel::FadeOutColumn), QStringLiteral("0.50"));
    QCOMPARE(model.data(model.index(0, GesticonModel::FadeInColumn), Qt::EditRole).toDouble(), 0.4);
    QCOMPARE(model.data(model.index(0, GesticonModel::FilterColumn), Qt::CheckStateRole).value<Qt::CheckState>(),
             Qt::Checked);
    QCOMPARE(cell(model, 0, GesticonModel::BandColumn), QStringLiteral("30–40"));
    QCOMPARE(cell(model, 1, GesticonModel::BandColumn), QStringLiteral("20–30")); // the paper's, greyed: filter off
    QCOMPARE(cell(model, 1, GesticonModel::NameColumn), QStringLiteral("agree"));
    QCOMPARE(cell(model, 1, GesticonModel::ClipColumn), QStringLiteral("nod"));
    QCOMPARE(cell(model, 1, GesticonModel::MaskColumn), QStringLiteral("head"));
    QCOMPARE(model.data(model.index(1, GesticonModel::FilterColumn), Qt::CheckStateRole).value<Qt::CheckState>(),
             Qt::Unchecked);
    QVERIFY(model.flags(model.index(1, GesticonModel::FilterColumn)) & Qt::ItemIsUserCheckable);
    QVERIFY(model.flags(model.index(1, GesticonModel::NameColumn)) & Qt::ItemIsEditable);
    QCOMPARE(cell(model, 2, GesticonModel::NameColumn), QStringLiteral("point")); // BML's POINT
    QCOMPARE(cell(model, 2, GesticonModel::ClipColumn), QStringLiteral("point"));
    QCOMPARE(cell(model, 2, GesticonModel::MaskColumn), QStringLiteral("rightArm"));
    QCOMPARE(model.clipNames(), QStringList({"creon_idle", "wave", "nod", "point", "blink", "stern"}));
    QCOMPARE(model.maskNames(), QStringList({"head", "leftArm", "rightArm"}));
    // The first gesture is selected, so Preview / Rename / Remove have something to act on.
    QCOMPARE(panel.selectedRows(), QList<int>{0});
    saveScreenshot(&panel, QStringLiteral("gesticon_panel.png"));

    panel.setCurrentCharacter(1);
    QCOMPARE(panel.currentCharacter(), 1);
    QCOMPARE(model.rowCount(), 1);
    QCOMPARE(cell(model, 0, GesticonModel::NameColumn), QStringLiteral("agree"));
    QCOMPARE(cell(model, 0, GesticonModel::FadeInColumn), QStringLiteral("0.20"));
    QCOMPARE(cell(model, 0, GesticonModel::FadeOutColumn), QStringLiteral("0.30"));
    QCOMPARE(model.clipNames(), QStringList({"antigone_idle", "wave", "nod", "antigone_blinks", "smile"}));
}

void GesticonPanelTest::everyEditIsOneUndoStepAndUndoAllRestores()
{
    auto document = openDemo();
    const core::scenario::Scenario original = document->scenario();
    QUndoStack& undo = *document->undoStack();
    GesticonPanel panel;
    panel.resize(640, 300);
    panel.setDocument(document.get());
    panel.show();
    QVERIFY(QTest::qWaitForWindowExposed(&panel));
    GesticonModel& model = *panel.model();
    const auto gestures = [&] { return document->scenario().characters[0].gestures; };
    const int n = model.rowCount(); // the demo's gestures: greet, agree, point
    QCOMPARE(n, 3);

    // Add: the first clip, the whole body, a unique name; selected.
    panel.addGesture();
    QCOMPARE(undo.count(), 1);
    QCOMPARE(undo.text(0), QStringLiteral("Add Gesture"));
    QCOMPARE(model.rowCount(), n + 1);
    QCOMPARE(gestures()[n].name, std::string("gesture"));
    QCOMPARE(gestures()[n].clip, std::string("creon_idle"));
    QVERIFY(gestures()[n].mask.empty());
    QCOMPARE(cell(model, n, GesticonModel::MaskColumn), QStringLiteral("Whole body"));
    QCOMPARE(panel.selectedRows(), QList<int>{n});
    panel.addGesture();
    QCOMPARE(undo.count(), 2);
    QCOMPARE(gestures()[n + 1].name, std::string("gesture 2"));
    QCOMPARE(panel.selectedRows(), QList<int>{n + 1});

    // Rename through the model: one step.
    QVERIFY(model.setData(model.index(n, GesticonModel::NameColumn), QStringLiteral("beckon")));
    QCOMPARE(undo.count(), 3);
    QCOMPARE(undo.text(2), QStringLiteral("Rename Gesture"));
    QCOMPARE(gestures()[n].name, std::string("beckon"));
    QCOMPARE(cell(model, n, GesticonModel::NameColumn), QStringLiteral("beckon"));

    // Renaming to a name the character has is refused: nothing changes, the message says why.
    const core::scenario::Scenario beforeRefusal = document->scenario();
    QSignalSpy failed(&model, &GesticonModel::editFailed);
    QVERIFY(!model.setData(model.index(n, GesticonModel::NameColumn), QStringLiteral("greet")));
    QCOMPARE(failed.count(), 1);
    QVERIFY(document->scenario() == beforeRefusal);
    QCOMPARE(undo.count(), 3);
    QVERIFY2(panel.message().contains(QStringLiteral("already has a gesture named \"greet\"")), qPrintable(panel.message()));
    QVERIFY(panel.findChild<QLabel*>(QStringLiteral("gesticonMessage"))->isVisible());
    saveScreenshot(&panel, QStringLiteral("gesticon_panel_refused.png"));
    // A clip the character does not have and a mask the scenario does not have are refused too.
    QVERIFY(!model.setData(model.index(n, GesticonModel::ClipColumn), QStringLiteral("antigone_idle")));
    QVERIFY(!model.setData(model.index(n, GesticonModel::MaskColumn), QStringLiteral("tail")));
    QVERIFY(document->scenario() == beforeRefusal);
    QCOMPARE(undo.count(), 3);

    // Fade in, in seconds: the ticks change; the message line clears after an edit that works.
    QVERIFY(model.setData(model.index(0, GesticonModel::FadeInColumn), 0.75));
    QCOMPARE(gestures()[0].fadeIn, core::secondsToTicks(0.75));
    QCOMPARE(gestures()[0].fadeOut, core::secondsToTicks(0.5));
    QCOMPARE(undo.count(), 4);
    QCOMPARE(undo.text(3), QStringLiteral("Change Gesture Fade In"));
    QVERIFY(panel.message().isEmpty());
    QCOMPARE(cell(model, 0, GesticonModel::FadeInColumn), QStringLiteral("0.75"));
    QVERIFY(model.setData(model.index(0, GesticonModel::FadeOutColumn), 1.25));
    QCOMPARE(gestures()[0].fadeOut, core::secondsToTicks(1.25));
    QCOMPARE(undo.count(), 5);
    // Setting the same value again pushes nothing.
    QVERIFY(model.setData(model.index(0, GesticonModel::FadeOutColumn), 1.25));
    QCOMPARE(undo.count(), 5);

    // The dependent-joint filter.
    QVERIFY(model.setData(model.index(1, GesticonModel::FilterColumn), Qt::Checked, Qt::CheckStateRole));
    QVERIFY(gestures()[1].dependentJointFilter);
    QCOMPARE(undo.count(), 6);
    QCOMPARE(undo.text(5), QStringLiteral("Turn Dependent-Joint Filter On"));
    QCOMPARE(model.data(model.index(1, GesticonModel::FilterColumn), Qt::CheckStateRole).value<Qt::CheckState>(),
             Qt::Checked);
    // Its band: written as two PC numbers; one out of order or not numbers is refused, saying how.
    QSignalSpy failures(&model, &GesticonModel::editFailed);
    QVERIFY(model.setData(model.index(1, GesticonModel::BandColumn), QStringLiteral("25-35")));
    QCOMPARE(gestures()[1].filterFadeFrom, 25);
    QCOMPARE(gestures()[1].filterMuteAbove, 35);
    QCOMPARE(undo.text(6), QStringLiteral("Change Filter Band"));
    QVERIFY(!model.setData(model.index(1, GesticonModel::BandColumn), QStringLiteral("35–25")));
    QVERIFY(!model.setData(model.index(1, GesticonModel::BandColumn), QStringLiteral("lots")));
    QCOMPARE(failures.count(), 2);
    QVERIFY2(failures.at(0).at(0).toString().contains(QStringLiteral("not below")), qPrintable(failures.at(0).at(0).toString()));
    QVERIFY2(failures.at(1).at(0).toString().contains(QStringLiteral("30–40")), qPrintable(failures.at(1).at(0).toString()));
    QCOMPARE(undo.count(), 7);

    // Clip and body part.
    QVERIFY(model.setData(model.index(n + 1, GesticonModel::ClipColumn), QStringLiteral("nod")));
    QVERIFY(model.setData(model.index(n + 1, GesticonModel::MaskColumn), QStringLiteral("head")));
    QCOMPARE(gestures()[n + 1].clip, std::string("nod"));
    QCOMPARE(gestures()[n + 1].mask, std::string("head"));
    QCOMPARE(undo.count(), 9);

    // How speech fits it to its words: held at its stroke, marked 0.4 s into the clip; "none" below 0.
    QCOMPARE(cell(model, n + 1, GesticonModel::StrokeColumn), QStringLiteral("none"));
    QVERIFY(model.setData(model.index(n + 1, GesticonModel::HoldColumn), Qt::Checked, Qt::CheckStateRole));
    QVERIFY(model.setData(model.index(n + 1, GesticonModel::StrokeColumn), 0.4));
    QVERIFY(gestures()[n + 1].hold);
    QCOMPARE(gestures()[n + 1].stroke, 0.4);
    QCOMPARE(undo.text(10), QStringLiteral("Mark Gesture Stroke"));
    QVERIFY(model.setData(model.index(n + 1, GesticonModel::StrokeColumn), -0.5));
    QCOMPARE(gestures()[n + 1].stroke, -1.0);
    QVERIFY(!model.setData(model.index(n + 1, GesticonModel::StrokeColumn), QStringLiteral("soon")));
    for (int i = 0; i < 3; ++i)
        undo.undo();
    QCOMPARE(undo.count(), 12);
    QVERIFY(!gestures()[n + 1].hold);

    // Remove two selected gestures: one step.
    panel.table()->clearSelection();
    panel.table()->selectionModel()->select(model.index(n, 0),
                                            QItemSelectionModel::Select | QItemSelectionModel::Rows);
    panel.table()->selectionModel()->select(model.index(n + 1, 0),
                                            QItemSelectionModel::Select | QItemSelectionModel::Rows);
    QCOMPARE(panel.selectedRows(), QList<int>({n, n + 1}));
    panel.removeSelected();
    QCOMPARE(undo.count(), 10); // the undone hold and stroke edits are gone from the stack
    // "Remove 2 Gestures" once thespis_en.ts has the plural forms of the new strings.
    QVERIFY2(undo.text(9).startsWith(QStringLiteral("Remove 2 Gesture")), qPrintable(undo.text(8)));
    QCOMPARE(model.rowCount(), n);
    QCOMPARE(gestures().size(), std::size_t(n));
    QCOMPARE(gestures()[0].name, std::string("greet"));
    QCOMPARE(gestures()[1].name, std::string("agree"));
    QCOMPARE(panel.selectedRows(), QList<int>{n - 1}); // the row before the removed ones

    // Undo brings the removed rows back, then undo everything: the document as it was.
    undo.undo();
    QCOMPARE(model.rowCount(), n + 2);
    QCOMPARE(cell(model, n, GesticonModel::NameColumn), QStringLiteral("beckon"));
    while (undo.canUndo())
        undo.undo();
    QVERIFY(document->scenario() == original);
    QCOMPARE(model.rowCount(), n);
    QCOMPARE(cell(model, 0, GesticonModel::FadeInColumn), QStringLiteral("0.40"));
    QVERIFY(!document->isModified());
    while (undo.canRedo())
        undo.redo();
    QCOMPARE(gestures().size(), std::size_t(n));
    QCOMPARE(gestures()[0].fadeIn, core::secondsToTicks(0.75));
}

void GesticonPanelTest::editorsInTheTableEditTheDocument()
{
    auto document = openDemo();
    QUndoStack& undo = *document->undoStack();
    GesticonPanel panel;
    panel.resize(640, 300);
    panel.setDocument(document.get());
    panel.show();
    QVERIFY(QTest::qWaitForWindowExposed(&panel));
    QTableView* table = panel.table();
    GesticonModel& model = *panel.model();
    const auto gesture = [&](int row) { return document->scenario().characters[0].gestures[std::size_t(row)]; };

    // The body part is a combo of "Whole body" and the scenario's masks; picking one commits.
    const QModelIndex maskCell = model.index(1, GesticonModel::MaskColumn);
    table->setCurrentIndex(maskCell);
    table->edit(maskCell);
    auto* combo = table->viewport()->findChild<QComboBox*>();
    QVERIFY(combo);
    QCOMPARE(combo->count(), 4);
    QCOMPARE(combo->itemText(0), QStringLiteral("Whole body"));
    QCOMPARE(combo->currentText(), QStringLiteral("head"));
    combo->setCurrentIndex(0);
    emit combo->activated(0);
    QCOMPARE(gesture(1).mask, std::string());
    QCOMPARE(undo.count(), 1);
    QCOMPARE(undo.text(0), QStringLiteral("Change Gesture Body Part"));
    QTRY_VERIFY(!table->viewport()->findChild<QComboBox*>());

    // Fades: a spin box in seconds.
    const QModelIndex fadeCell = model.index(1, GesticonModel::FadeOutColumn);
    table->setCurrentIndex(fadeCell);
    table->edit(fadeCell);
    auto* spin = table->viewport()->findChild<QDoubleSpinBox*>();
    QVERIFY(spin);
    QCOMPARE(spin->value(), 0.25);
    spin->selectAll();
    QTest::keyClicks(spin, QStringLiteral("0.6"));
    QTest::keyClick(spin, Qt::Key_Return); // the delegate commits from the event loop
    QTRY_COMPARE(gesture(1).fadeOut, core::secondsToTicks(0.6));
    QCOMPARE(undo.count(), 2);

    // The filter check box toggles with a click in its cell.
    const QRect filterRect = table->visualRect(model.index(1, GesticonModel::FilterColumn));
    QTest::mouseClick(table->viewport(), Qt::LeftButton, {}, filterRect.center());
    QVERIFY(gesture(1).dependentJointFilter);
    QCOMPARE(undo.count(), 3);

    // Rename starts editing the name in place.
    panel.selectRow(0);
    panel.renameSelected();
    auto* line = table->viewport()->findChild<QLineEdit*>();
    QVERIFY(line);
    QCOMPARE(line->text(), QStringLiteral("greet"));
    line->selectAll();
    QTest::keyClicks(line, QStringLiteral("hail"));
    QTest::keyClick(line, Qt::Key_Return);
    QTRY_COMPARE(gesture(0).name, std::string("hail"));
    QCOMPARE(undo.count(), 4);
    QCOMPARE(panel.selectedRows(), QList<int>{0});
}

void GesticonPanelTest::previewIsDisabledWithoutASession()
{
    auto document = openDemo();
    GesticonPanel panel;
    panel.setDocument(document.get());
    QCOMPARE(panel.selectedRows(), QList<int>{0});
    QVERIFY(!panel.previewButton()->isEnabled());
    QVERIFY2(panel.previewButton()->toolTip().contains(QStringLiteral("Open a scenario")),
             qPrintable(panel.previewButton()->toolTip()));
    panel.preview();
    QVERIFY(!panel.isPreviewing());
}

void GesticonPanelTest::previewPlaysTheGestureOnTheCharacter()
{
    QVERIFY2(widgets::OsgViewport::isSupported(), "No OpenGL on this display (Xvfb and Mesa are dependencies)");
    QWidget window;
    window.resize(1200, 520);
    auto* layout = new QHBoxLayout(&window);
    auto* viewport = new widgets::OsgViewport(&window);
    viewport->setMinimumWidth(560);
    auto* panel = new GesticonPanel(&window);
    layout->addWidget(viewport, 1);
    layout->addWidget(panel, 1);
    // As the studio's window wires them: the 3D view and the panel are views of one session.
    editor::PlaybackClock clock;
    editor::Session session(&clock);
    editor::ScenePreview scene(viewport);
    scene.setSession(&session);
    session.addPanel(panel);
    panel->setSession(&session);
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    QVERIFY2(viewport->glErrorText().isEmpty(), qPrintable(viewport->glErrorText()));
    session.setDocument(openDemo());
    editor::Document* document = session.document();
    const core::scenario::Scenario original = document->scenario();
    clock.setLooping(true);
    QVERIFY(panel->previewButton()->isEnabled());
    QCOMPARE(panel->previewButton()->text(), QStringLiteral("Preview"));
    core::runtime::Stage& stage = *session.stage();

    // Creon (character 0) "greet": the clip "wave" on the right arm. Before his own wave (1.5 s).
    QCOMPARE(panel->currentCharacter(), 0);
    panel->selectRow(0);
    const core::anim::TimeDomain wave = stage.runtime().characters[0].clips.at("wave")->domain();
    const double length = wave.end - wave.start;
    QVERIFY(length > 1.5 && length < 6);
    const core::Tick start = core::secondsToTicks(0.2), during = start + core::TicksPerSecond;
    // The document's pose during the gesture: the session's at that time, before any preview.
    clock.seek(during);
    const std::vector<float> documentFrame = session.poses().characters[0].body;
    const auto shownPositions = [&] {
        const auto positions = scene.scene()->scene().character(0).posedPositions();
        return std::vector<core::anim::Vec3>(positions.begin(), positions.end());
    };
    const std::vector<core::anim::Vec3> documentPose = shownPositions();
    clock.seek(start);

    const std::string live = "greet (gesture preview)";
    const auto previewShown = [&] { return *stage.isPlaying("Creon", core::runtime::Track::Body, live, clock.time()); };
    panel->preview();
    QVERIFY(panel->isPreviewing());
    QVERIFY(previewShown()); // a live action on the session's stage
    QVERIFY(clock.isPlaying());
    QCOMPARE(panel->previewButton()->text(), QStringLiteral("Stop"));
    QVERIFY(!clock.isLooping());
    QVERIFY(clock.duration() >= start + core::secondsToTicks(length) - 1);
    QVERIFY(document->scenario() == original); // a preview edits nothing
    QCOMPARE(document->undoStack()->count(), 0);
    // Every view shows the document plus the gesture: the session's poses, and the 3D view.
    QTRY_VERIFY_WITH_TIMEOUT(clock.time() >= during || !panel->isPreviewing(), 15000);
    QVERIFY(panel->isPreviewing());
    {
        const std::vector<float>& frame = session.poses().characters[0].body;
        const core::Tick t = clock.time();
        // The document's pose at the same moment, from a stage of its own.
        core::runtime::Stage reference(stage.runtimeCopy());
        core::runtime::PoseSet expected = reference.makePoseSet();
        reference.evaluate(t, expected);
        const std::vector<float>& authored = expected.characters[0].body;
        // The stage's runtime is replaced whenever the document changes: take Creon from the copy.
        const core::scenario::CharacterRuntime& creonNow = reference.runtime().characters[0];
        const double rightShoulder =
            angleBetween(rotationOf(creonNow, frame, "r_shoulder"), rotationOf(creonNow, authored, "r_shoulder"));
        const double hip = angleBetween(rotationOf(creonNow, frame, "l_hip"), rotationOf(creonNow, authored, "l_hip"));
        QVERIFY2(rightShoulder > 10, qPrintable(QString::number(rightShoulder)));
        // "greet" has the dependent-joint filter on (paper §4.4): the gesture plays over the upper
        // body, while the legs go on with the idle as the document has them.
        QVERIFY2(hip < 0.01, qPrintable(QString::number(hip)));
        // The 3D view draws those poses.
        QCOMPARE(scene.scene()->poses().time, session.poses().time);
        QVERIFY(scene.scene()->poses().characters[0].body == frame);
        saveScreenshot(&window, QStringLiteral("gesticon_preview.png"));
    }

    // The gesture ends on its own: the live action is gone, the clock as it was.
    QTRY_VERIFY_WITH_TIMEOUT(!panel->isPreviewing(), 15000);
    QVERIFY(!clock.isPlaying());
    QCOMPARE(clock.time(), start);
    QCOMPARE(clock.duration(), document->previewDuration());
    QVERIFY(clock.isLooping());
    QCOMPARE(panel->previewButton()->text(), QStringLiteral("Preview"));
    QVERIFY(!previewShown());
    clock.seek(during);
    QVERIFY(session.poses().characters[0].body == documentFrame);
    QCOMPARE(largestDistance(shownPositions(), documentPose), 0.0f);
    clock.seek(start);

    // Pausing the clock stops the preview.
    panel->preview();
    QVERIFY(panel->isPreviewing() && previewShown());
    clock.pause();
    QTRY_VERIFY(!panel->isPreviewing());
    QVERIFY(!previewShown());

    // So does Stop.
    panel->preview();
    QVERIFY(panel->isPreviewing() && previewShown());
    QTest::mouseClick(panel->previewButton(), Qt::LeftButton);
    QVERIFY(!panel->isPreviewing());
    QVERIFY(!previewShown());
    QCOMPARE(clock.time(), start);

    // Previewing again while a preview plays restarts it (the first one's stop does not end it).
    panel->preview();
    panel->preview();
    QTest::qWait(100);
    QVERIFY(panel->isPreviewing() && previewShown());

    // Any edit ends it.
    QVERIFY(panel->model()->setData(panel->model()->index(1, GesticonModel::FadeInColumn), 0.5));
    QTRY_VERIFY(!panel->isPreviewing());
    QVERIFY(!previewShown());
    document->undoStack()->undo();
    QVERIFY(document->scenario() == original);

    // Before / After: the gesture without the dependent-joint filter, then with it, each from the
    // same time. Without it the left shoulder (outside the gesture's mask) keeps the document's
    // motion; with it, it follows the waving arm.
    const auto leftShoulderMoves = [&] {
        core::runtime::Stage reference(stage.runtimeCopy());
        core::runtime::PoseSet expected = reference.makePoseSet();
        reference.evaluate(session.poses().time, expected);
        const core::scenario::CharacterRuntime& creonNow = reference.runtime().characters[0];
        return angleBetween(rotationOf(creonNow, session.poses().characters[0].body, "l_shoulder"),
                            rotationOf(creonNow, expected.characters[0].body, "l_shoulder"));
    };
    clock.seek(start);
    panel->selectRow(0);
    QVERIFY(panel->compareButton()->isEnabled());
    QTest::mouseClick(panel->compareButton(), Qt::LeftButton);
    QVERIFY(panel->isPreviewing());
    QVERIFY2(panel->playing().startsWith(QStringLiteral("Before:")), qPrintable(panel->playing()));
    QTRY_VERIFY_WITH_TIMEOUT(clock.time() >= during, 15000);
    const double without = leftShoulderMoves();
    QVERIFY2(without < 0.01, qPrintable(QString::number(without)));
    QTRY_VERIFY_WITH_TIMEOUT(panel->playing().startsWith(QStringLiteral("After:")), 15000);
    QVERIFY(panel->isPreviewing());
    QTRY_VERIFY_WITH_TIMEOUT(clock.time() >= during || !panel->isPreviewing(), 15000); // the arm up
    QVERIFY(panel->isPreviewing());
    const double with = leftShoulderMoves();
    QVERIFY2(with > 1.0, qPrintable(QString::number(with)));
    saveScreenshot(&window, QStringLiteral("gesticon_before_after.png"));
    QTRY_VERIFY_WITH_TIMEOUT(!panel->isPreviewing(), 15000);
    QVERIFY(panel->playing().isEmpty());
    QCOMPARE(clock.time(), start);
    QVERIFY(document->scenario() == original);
}

// A gesture whose clip moves only the face (Creon's "stern" expression) plays on the face track:
// the preview shows it on his face, and Stop takes it off there.
void GesticonPanelTest::aFaceGesturePreviewsOnTheFace()
{
    editor::PlaybackClock clock;
    editor::Session session(&clock);
    GesticonPanel panel;
    session.addPanel(&panel);
    panel.setSession(&session);
    session.setDocument(openDemo());
    panel.show();
    QVERIFY(QTest::qWaitForWindowExposed(&panel));
    GesticonModel& model = *panel.model();
    panel.addGesture();
    const int row = model.rowCount() - 1;
    QVERIFY(model.setData(model.index(row, GesticonModel::NameColumn), QStringLiteral("frown")));
    QVERIFY(model.setData(model.index(row, GesticonModel::ClipColumn), QStringLiteral("stern")));
    panel.selectRow(row);
    QVERIFY(panel.previewButton()->isEnabled());

    core::runtime::Stage& stage = *session.stage();
    const std::string live = "frown (gesture preview)";
    const int stern = core::scene::expressionChannel(3);
    const float before = session.poses().characters[0].face[std::size_t(stern)];
    panel.preview();
    QVERIFY2(panel.isPreviewing(), qPrintable(panel.message()));
    QVERIFY(*stage.isPlaying("Creon", core::runtime::Track::Face, live, clock.time()));
    QVERIFY(!*stage.isPlaying("Creon", core::runtime::Track::Body, live, clock.time()));
    QTRY_VERIFY_WITH_TIMEOUT(session.poses().characters[0].face[std::size_t(stern)] > before + 0.3f
                                 || !panel.isPreviewing(),
                             15000);
    QVERIFY2(panel.isPreviewing(), "the stern look shows while the preview plays");
    QTest::mouseClick(panel.previewButton(), Qt::LeftButton);
    QVERIFY(!panel.isPreviewing());
    QVERIFY(!*stage.isPlaying("Creon", core::runtime::Track::Face, live, clock.time()));
}

QTEST_MAIN(GesticonPanelTest)
#include "gesticon_panel_test.moc"
