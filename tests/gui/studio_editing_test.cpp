// The studio's editors driven as a user would, on the real window: drop a clip from the library
// onto the timeline, move and trim it with the mouse, undo back to the original document and
// redo forward; change a curve preset, and make a weight curve a dominance curve; paint a joint mask; save and reopen; recover autosaved
// work after the studio process is killed with SIGKILL. Each editor leaves a screenshot.

#include <QComboBox>
#include <QDir>
#include <QDockWidget>
#include <QDoubleSpinBox>
#include <QLineEdit>
#include <QSpinBox>
#include <QMimeData>
#include <QProcess>
#include <QSettings>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>
#include <QTranslator>
#include <QLabel>
#include <QTabWidget>
#include <QUndoStack>

#include <cmath>
#include <iostream>

#include "edit/document_edits.h"
#include "editor/autosave.h"
#include "editor/clip_library_panel.h"
#include "editor/curve_panel.h"
#include "editor/document.h"
#include "editor/joint_mask_panel.h"
#include "editor/playback_clock.h"
#include "editor/properties_panel.h"
#include "editor/scenario_tree_model.h"
#include "editor/translations.h"
#include "editor/timeline_panel.h"
#include "main_window.h"
#include "preferences_dialog.h"
#include "scenario/scenario_io.h"
#include "widgets/joint_mask_view.h"
#include "widgets/timeline_view.h"
#include "widgets/transport_bar.h"

using namespace thespis;
using core::edit::ActionPath;

namespace {

QString demoPath() { return QStringLiteral(THESPIS_RESOURCES "/demo.thespis"); }

void saveScreenshot(QWidget* widget, const QString& name)
{
    QDir().mkpath(QStringLiteral(THESPIS_SCREENSHOT_DIR));
    QVERIFY(widget->grab().save(QStringLiteral(THESPIS_SCREENSHOT_DIR "/") + name));
}

// Drags with the left button in small steps, as a hand would.
void drag(QWidget* target, QPoint from, QPoint to, Qt::KeyboardModifiers modifiers = {})
{
    QTest::mousePress(target, Qt::LeftButton, modifiers, from);
    for (int i = 1; i <= 8; ++i)
        QTest::mouseMove(target, from + (to - from) * i / 8);
    QTest::mouseRelease(target, Qt::LeftButton, modifiers, to);
}

// Types a value into a spin box and presses Enter, as a user would.
void typeInto(QDoubleSpinBox* box, double value)
{
    QTest::keyClick(box, Qt::Key_A, Qt::ControlModifier);
    QTest::keyClicks(box, box->locale().toString(value));
    QTest::keyClick(box, Qt::Key_Return);
}

const core::scenario::ActionSpec& actionAt(const editor::Document& document, ActionPath p)
{
    return document.scenario().characters[std::size_t(p.character)].layers[std::size_t(p.layer)].actions[std::size_t(p.action)];
}

// The child side of the crash test: a studio that opens a scenario, edits it, autosaves and
// then waits to be killed.
int runCrashChild(int argc, char** argv)
{
    QApplication app(argc, argv);
    studio::MainWindow window;
    if (!window.openScenario(QString::fromLocal8Bit(argv[2])))
        return 2;
    window.autosaver()->setInterval(100);
    QObject::connect(window.autosaver(), &editor::Autosaver::autosaved, [](const QString& file) {
        std::cout << "AUTOSAVED " << file.toStdString() << std::endl;
    });
    editor::Document& document = *window.document();
    auto edit = core::edit::moveActions(document.scenario(), std::vector<ActionPath>{{0, 0, 1}}, core::TicksPerSecond);
    if (!document.edit(edit, QStringLiteral("Move")))
        return 3;
    return app.exec();
}

} // namespace

class StudioEditingTest : public QObject {
    Q_OBJECT
private slots:
    void init();
    void cleanup();
    void dropMoveTrimThenUndoAndRedo();
    void dragToAnotherLayerIsOneUndoStep();
    void curvePresetChangesTheEvaluatedWeights();
    void dominanceCurveFromTheCurvePanel();
    void paintingAMaskSetsJointWeights();
    void saveAndReopenGiveTheSameDocument();
    void autosavedWorkSurvivesKill9();
    void propertiesEditTheSelectedAction();
    void framesStepWithTheArrowsAndEndGoesToTheEnd();
    void preferencesChooseTheLanguage();

private:
    std::unique_ptr<studio::MainWindow> m_window;
    QTemporaryDir m_dir;
};

void StudioEditingTest::init()
{
    QStandardPaths::setTestModeEnabled(true);
    QSettings().clear();
    m_window = std::make_unique<studio::MainWindow>();
    m_window->resize(1500, 950);
    m_window->show();
    QVERIFY(QTest::qWaitForWindowExposed(m_window.get()));
    QVERIFY(m_window->openScenario(demoPath()));
}

void StudioEditingTest::cleanup()
{
    m_window.reset();
}

void StudioEditingTest::dropMoveTrimThenUndoAndRedo()
{
    editor::Document& document = *m_window->document();
    const core::scenario::Scenario original = document.scenario();
    editor::TimelinePanel* timeline = m_window->timeline();
    widgets::TimelineView* view = timeline->view();
    view->findChild<QWidget*>(); // make sure it is laid out
    timeline->parentWidget()->findChild<QWidget*>();
    qobject_cast<QDockWidget*>(timeline->parentWidget())->raise();
    view->setPixelsPerSecond(80);
    QApplication::processEvents();

    // 1. Drop "nod" from the clip library onto Antigone's body track at about 9 s. The drag's
    //    data is what the library itself hands to Qt's drag and drop.
    editor::ClipLibraryPanel* library = m_window->clipLibrary();
    QTreeWidgetItem* nod = library->clipItem(QStringLiteral("Antigone"), QStringLiteral("nod"));
    QVERIFY(nod);
    std::unique_ptr<QMimeData> mime(library->model()->mimeData({library->indexFromItem(nod)}));
    QVERIFY(mime && mime->hasFormat(QString::fromLatin1(widgets::TimelineView::ClipMimeType)));
    int antigoneBody = -1;
    for (int t = 0; t < view->tracks().size(); ++t)
        if (view->tracks()[t].group == QStringLiteral("Antigone") && view->tracks()[t].name == QStringLiteral("body"))
            antigoneBody = t;
    QVERIFY(antigoneBody >= 0);
    const QPoint dropAt(view->xForTime(9 * core::TicksPerSecond), view->trackRect(antigoneBody).center().y());
    QDragEnterEvent enter(dropAt, Qt::CopyAction, mime.get(), Qt::LeftButton, {});
    QApplication::sendEvent(view->viewport(), &enter);
    QDragMoveEvent move(dropAt, Qt::CopyAction, mime.get(), Qt::LeftButton, {});
    QApplication::sendEvent(view->viewport(), &move);
    QDropEvent drop(dropAt, Qt::CopyAction, mime.get(), Qt::LeftButton, {});
    QApplication::sendEvent(view->viewport(), &drop);
    const ActionPath added{1, 0, int(original.characters[1].layers[0].actions.size())};
    QCOMPARE(document.scenario().characters[1].layers[0].actions.size(), original.characters[1].layers[0].actions.size() + 1);
    QCOMPARE(QString::fromStdString(actionAt(document, added).clip), QStringLiteral("nod"));
    QCOMPARE(actionAt(document, added).start, 9 * core::TicksPerSecond); // snapped to a frame: 9 s exactly
    QCOMPARE(document.undoStack()->count(), 1);
    const core::scenario::Scenario afterDrop = document.scenario();

    // 2. Move it 1 s earlier with the mouse: one undo step however many mouse moves.
    int id = timeline->clipId(added);
    QVERIFY(id >= 0);
    QRect clip = view->clipRect(id);
    const QPoint grab = clip.center() + QPoint(0, 6);
    drag(view->viewport(), grab, grab - QPoint(80, 0));
    QCOMPARE(actionAt(document, added).start, 8 * core::TicksPerSecond);
    QCOMPARE(document.undoStack()->count(), 2);
    const core::scenario::Scenario afterMove = document.scenario();

    // 3. Trim its end 0.5 s shorter by dragging the right edge.
    const auto before = core::edit::actionSpan(document.scenario(), document.runtime(), added);
    QVERIFY(before);
    clip = view->clipRect(id);
    const QPoint edge(clip.right() - 1, clip.center().y() + 6);
    drag(view->viewport(), edge, edge - QPoint(40, 0));
    const auto after = core::edit::actionSpan(document.scenario(), document.runtime(), added);
    QVERIFY(after);
    QCOMPARE(after->start, before->start);
    QCOMPARE(after->end, before->end - core::TicksPerSecond / 2);
    QCOMPARE(document.undoStack()->count(), 3);
    QVERIFY(m_window->isWindowModified());
    const core::scenario::Scenario afterTrim = document.scenario();
    saveScreenshot(m_window.get(), QStringLiteral("studio_timeline_editing.png"));
    saveScreenshot(view, QStringLiteral("timeline_panel.png"));

    // 4. Undo everything: the original document, unmodified; redo: each state again.
    m_window->undoAction()->trigger();
    QVERIFY(document.scenario() == afterMove);
    m_window->undoAction()->trigger();
    QVERIFY(document.scenario() == afterDrop);
    m_window->undoAction()->trigger();
    QVERIFY(document.scenario() == original);
    QVERIFY(!document.isModified());
    QVERIFY(!m_window->isWindowModified());
    m_window->redoAction()->trigger();
    m_window->redoAction()->trigger();
    m_window->redoAction()->trigger();
    QVERIFY(document.scenario() == afterTrim);
    // The schedules follow: the runtime plays the nod at 8.2 s.
    const auto span = core::edit::actionSpan(document.scenario(), document.runtime(), added);
    QVERIFY(span);
    QCOMPARE(span->start, 8 * core::TicksPerSecond);
}

void StudioEditingTest::dragToAnotherLayerIsOneUndoStep()
{
    editor::Document& document = *m_window->document();
    // Creon (character 0) gets a second body layer, "gestures", between his body and face layers.
    core::scenario::Layer gestures;
    gestures.name = "gestures";
    QVERIFY(document.edit(core::edit::Edit(core::edit::LayerChange{{0, 1}, std::nullopt, gestures}),
                          QStringLiteral("Add Layer")));
    const core::scenario::Scenario original = document.scenario();
    const int steps = document.undoStack()->count();
    editor::TimelinePanel* timeline = m_window->timeline();
    widgets::TimelineView* view = timeline->view();
    qobject_cast<QDockWidget*>(timeline->parentWidget())->raise();
    view->setPixelsPerSecond(80);
    QApplication::processEvents();
    auto trackOf = [&](const QString& group, const QString& name) {
        for (int t = 0; t < view->tracks().size(); ++t)
            if (view->tracks()[t].group == group && view->tracks()[t].name == name)
                return t;
        return -1;
    };
    const int body = trackOf(QStringLiteral("Creon"), QStringLiteral("body"));
    const int layer = trackOf(QStringLiteral("Creon"), QStringLiteral("gestures"));
    const int face = trackOf(QStringLiteral("Creon"), QStringLiteral("face"));
    const int antigone = trackOf(QStringLiteral("Antigone"), QStringLiteral("body"));
    QVERIFY(body >= 0 && layer == body + 1 && face == body + 2 && antigone >= 0);
    QCOMPARE(view->tracks()[layer].kind, view->tracks()[body].kind);
    QVERIFY(view->tracks()[face].kind != view->tracks()[body].kind);

    // Drag creon_wave down to "gestures", on over the face layer and Antigone's (it stays on
    // "gestures"), back up to "body", down again and 1 s later: one drag, many steps.
    const ActionPath wave{0, 0, 1};
    const core::scenario::ActionSpec spec = actionAt(document, wave);
    const QRect clip = view->clipRect(timeline->clipId(wave));
    QVERIFY(!clip.isNull());
    const QPoint grab = clip.center();
    auto y = [&](int track) { return view->trackRect(track).center().y(); };
    QWidget* vp = view->viewport();

    // Escape during a drag to the other layer: the original document, no undo step, still selected.
    QTest::mousePress(vp, Qt::LeftButton, {}, grab);
    QTest::mouseMove(vp, grab + QPoint(0, 8));
    QTest::mouseMove(vp, QPoint(grab.x() + 40, y(layer)));
    QCOMPARE(document.scenario().characters[0].layers[1].actions.size(), std::size_t(1));
    QTest::keyClick(view, Qt::Key_Escape);
    QVERIFY(document.scenario() == original);
    QCOMPARE(document.undoStack()->count(), steps);
    QCOMPARE(timeline->selectedActions(), std::vector<ActionPath>{wave});
    QTest::mouseRelease(vp, Qt::LeftButton, {}, QPoint(grab.x() + 40, y(layer)));
    QVERIFY(document.scenario() == original);

    QTest::mousePress(vp, Qt::LeftButton, {}, grab);
    const QList<QPoint> path = {grab + QPoint(0, 8),         QPoint(grab.x(), y(layer)),      QPoint(grab.x() + 20, y(face)),
                                QPoint(grab.x() + 40, y(antigone)), QPoint(grab.x() + 40, y(body)), QPoint(grab.x() + 60, y(layer)),
                                QPoint(grab.x() + 80, y(layer))};
    QList<int> seenLayers;
    for (const QPoint& p : path) {
        QTest::mouseMove(vp, p);
        // Where the action is now, during the drag: the layer that holds an action named creon_wave.
        for (int l = 0; l < 3; ++l)
            for (const auto& a : document.scenario().characters[0].layers[std::size_t(l)].actions)
                if (a.name == spec.name)
                    seenLayers.push_back(l);
    }
    QCOMPARE(seenLayers, (QList<int>{0, 1, 1, 1, 0, 1, 1}));
    // The moved clip is selected where it is now, drawn on the gestures lane.
    QCOMPARE(timeline->selectedActions(), (std::vector<ActionPath>{{0, 1, 0}}));
    QVERIFY(view->trackRect(layer).contains(view->clipRect(timeline->clipId({0, 1, 0}))));
    QApplication::processEvents();
    saveScreenshot(m_window.get(), QStringLiteral("studio_timeline_drag_to_layer.png"));
    saveScreenshot(view, QStringLiteral("timeline_drag_to_layer.png"));
    QTest::mouseRelease(vp, Qt::LeftButton, {}, path.last());

    // The action is in "gestures", 1 s later, and the document is exactly that move of the original.
    core::scenario::Scenario expected = original;
    QVERIFY(core::edit::moveActions(expected, std::vector<ActionPath>{wave}, core::TicksPerSecond, 1)->apply(expected).ok());
    QCOMPARE(document.scenario().characters[0].layers[1].actions.size(), std::size_t(1));
    const core::scenario::ActionSpec& moved = document.scenario().characters[0].layers[1].actions[0];
    QCOMPARE(moved.name, spec.name);
    QCOMPARE(moved.start, spec.start + core::TicksPerSecond);
    QCOMPARE(document.scenario().characters[0].layers[0].actions.size(), original.characters[0].layers[0].actions.size() - 1);
    QVERIFY(document.scenario() == expected);
    QCOMPARE(timeline->selectedActions(), (std::vector<ActionPath>{{0, 1, 0}}));
    // The runtime plays it from the gestures layer.
    const auto span = core::edit::actionSpan(document.scenario(), document.runtime(), {0, 1, 0});
    QVERIFY(span);
    QCOMPARE(span->start, spec.start + core::TicksPerSecond);

    // One undo step; undo gives the original, redo the moved document.
    QCOMPARE(document.undoStack()->count(), steps + 1);
    m_window->undoAction()->trigger();
    QVERIFY(document.scenario() == original);
    m_window->redoAction()->trigger();
    QVERIFY(document.scenario() == expected);
    m_window->undoAction()->trigger();
    m_window->undoAction()->trigger();
    QVERIFY(!document.isModified());
}

void StudioEditingTest::curvePresetChangesTheEvaluatedWeights()
{
    editor::Document& document = *m_window->document();
    const ActionPath wave{0, 0, 1}; // creon_wave: a cubic ADSR
    m_window->timeline()->selectActions({wave});
    editor::CurvePanel* curves = m_window->curveEditor();
    QVERIFY(curves->action() == wave);
    qobject_cast<QDockWidget*>(curves->parentWidget())->raise();
    curves->setEditedCurve(editor::CurvePanel::WeightCurve);
    QComboBox* preset = curves->presetCombo();
    preset->setCurrentIndex(preset->findText(QStringLiteral("Linear fade")));
    const core::anim::Curve& weight = actionAt(document, wave).weight;
    QCOMPARE(weight.kind(), core::anim::CurveKind::LinearFade);
    // The fade keeps the envelope's attack (0.4 s) and release (0.5 s), now straight.
    const double duration = core::ticksToSeconds(core::edit::actionSpan(document.scenario(), document.runtime(), wave)->end
                                                 - actionAt(document, wave).start);
    QCOMPARE(weight.evaluate(0.2, duration), 0.5);
    QCOMPARE(weight.evaluate(duration / 2, duration), 1.0);
    QVERIFY(std::abs(weight.evaluate(duration - 0.25, duration) - 0.5) < 1e-9);
    auto* attack = curves->findChild<QDoubleSpinBox*>(QStringLiteral("curveAttack"));
    QVERIFY(attack);
    attack->setValue(0.8);
    QCOMPARE(actionAt(document, wave).weight.evaluate(0.2, duration), 0.25);
    saveScreenshot(curves, QStringLiteral("curve_panel.png"));
    QCOMPARE(document.undoStack()->count(), 2);
    document.undoStack()->undo();
    document.undoStack()->undo();
    QCOMPARE(actionAt(document, wave).weight.kind(), core::anim::CurveKind::CubicAdsr);
}

void StudioEditingTest::dominanceCurveFromTheCurvePanel()
{
    editor::Document& document = *m_window->document();
    const core::scenario::Scenario original = document.scenario();
    const ActionPath wave{0, 0, 1}; // creon_wave: a cubic ADSR
    m_window->timeline()->selectActions({wave});
    editor::CurvePanel* curves = m_window->curveEditor();
    QVERIFY(curves->action() == wave);
    qobject_cast<QDockWidget*>(curves->parentWidget())->raise();
    curves->setEditedCurve(editor::CurvePanel::WeightCurve);
    auto* alpha = curves->findChild<QDoubleSpinBox*>(QStringLiteral("curveAlpha"));
    auto* peak = curves->findChild<QDoubleSpinBox*>(QStringLiteral("curvePeak"));
    auto* attack = curves->findChild<QDoubleSpinBox*>(QStringLiteral("curveAttack"));
    QVERIFY(alpha && peak && attack);
    QVERIFY(!alpha->isEnabled()); // only a dominance curve has an α

    QComboBox* preset = curves->presetCombo();
    preset->setCurrentIndex(preset->findText(QStringLiteral("Dominance (coarticulation)")));
    auto weight = [&] { return actionAt(document, wave).weight; };
    QCOMPARE(weight().kind(), core::anim::CurveKind::Dominance);
    QCOMPARE(weight().envelope().alpha, 5.0);
    QVERIFY(alpha->isEnabled());
    QVERIFY(!attack->isEnabled());

    typeInto(alpha, 12);
    typeInto(peak, 0.8);
    QCOMPARE(weight(), core::anim::Curve::dominance(12, 0.8));
    QCOMPARE(document.undoStack()->count(), 3); // the shape, α and the peak: one step each
    const double duration = core::ticksToSeconds(core::edit::actionSpan(document.scenario(), document.runtime(), wave)->end
                                                 - actionAt(document, wave).start);
    QCOMPARE(weight().evaluate(duration / 2, duration), 0.8);
    QCOMPARE(weight().evaluate(duration / 4, duration), 0.8 * core::anim::dominance(12, 0.25));
    QCOMPARE(editor::describeCurve(weight()), QStringLiteral("dominance α 12, peak 0.8"));
    // The timeline's thumbnail reaches the peak in the action's middle.
    widgets::TimelineView* timeline = m_window->timeline()->view();
    const QVector<float>& thumbnail = timeline->clip(timeline->selectedClips().front())->weight;
    QCOMPARE(thumbnail[thumbnail.size() / 2], 0.8f);
    saveScreenshot(curves, QStringLiteral("curve_panel_dominance.png"));
    qobject_cast<QDockWidget*>(m_window->timeline()->parentWidget())->raise();
    timeline->setPixelsPerSecond(200);
    saveScreenshot(timeline, QStringLiteral("timeline_dominance.png"));

    // Made keyframed, it keeps the rise, the peak and the fall.
    qobject_cast<QDockWidget*>(curves->parentWidget())->raise();
    preset->setCurrentIndex(preset->findText(QStringLiteral("Keyframed")));
    QCOMPARE(weight().keys().size(), std::size_t(5));
    QCOMPARE(weight().keys()[2].value, 0.8);
    QCOMPARE(weight().keys()[1].value, 0.8 * core::anim::dominance(12, 0.25));

    document.undoStack()->undo();
    QCOMPARE(weight(), core::anim::Curve::dominance(12, 0.8));
    document.undoStack()->undo();
    QCOMPARE(weight(), core::anim::Curve::dominance(12, 1.0));
    QCOMPARE(alpha->value(), 12.0);
    document.undoStack()->undo();
    QCOMPARE(weight().envelope().alpha, 5.0);
    document.undoStack()->undo();
    QVERIFY(document.scenario() == original);
    QVERIFY(!alpha->isEnabled());
}

void StudioEditingTest::propertiesEditTheSelectedAction()
{
    editor::Document& document = *m_window->document();
    editor::PropertiesPanel* properties = m_window->properties();
    qobject_cast<QDockWidget*>(properties->parentWidget())->raise();
    const ActionPath wave{0, 0, 1};
    const core::scenario::ActionSpec original = actionAt(document, wave);
    m_window->timeline()->selectActions({wave});
    QVERIFY(properties->action() == wave);
    QCOMPARE(properties->nameEdit()->text(), QString::fromStdString(original.name));
    QCOMPARE(properties->startEdit()->value(), core::ticksToSeconds(original.start));

    // Type a new start: the action moves there, as one undo step.
    properties->startEdit()->setFocus();
    properties->startEdit()->selectAll();
    QTest::keyClicks(properties->startEdit(), QStringLiteral("2.5"));
    QTest::keyClick(properties->startEdit(), Qt::Key_Return);
    QCOMPARE(actionAt(document, wave).start, core::secondsToTicks(2.5));
    QCOMPARE(document.undoStack()->count(), 1);

    // Rename and change the body part; each one step, undo restores the action exactly.
    properties->nameEdit()->setFocus();
    properties->nameEdit()->selectAll();
    QTest::keyClicks(properties->nameEdit(), QStringLiteral("big wave"));
    QTest::keyClick(properties->nameEdit(), Qt::Key_Return);
    QCOMPARE(actionAt(document, wave).name, std::string("big wave"));
    QComboBox* mask = properties->maskChoice();
    const int wholeBody = mask->findData(QString());
    QVERIFY(wholeBody >= 0);
    mask->setCurrentIndex(wholeBody);
    emit mask->activated(wholeBody);
    QCOMPARE(actionAt(document, wave).mask, std::string());
    QCOMPARE(document.undoStack()->count(), 3);
    saveScreenshot(properties, QStringLiteral("properties_panel.png"));
    while (document.undoStack()->canUndo())
        document.undoStack()->undo();
    QCOMPARE(actionAt(document, wave), original);
    QCOMPARE(properties->nameEdit()->text(), QString::fromStdString(original.name));

    m_window->timeline()->selectActions({});
    QVERIFY(!properties->action());
}

void StudioEditingTest::framesStepWithTheArrowsAndEndGoesToTheEnd()
{
    editor::PlaybackClock* clock = m_window->clock();
    QWidget* scene = m_window->views()->currentWidget();
    m_window->activateWindow();
    QVERIFY(QTest::qWaitForWindowActive(m_window.get()));
    QTest::mouseClick(scene, Qt::LeftButton, {}, QPoint(5, 5)); // a click gives the view the keys
    QCOMPARE(QApplication::focusWidget(), scene);
    QTest::keyClick(scene, Qt::Key_Right);
    QTest::keyClick(scene, Qt::Key_Right);
    QCOMPARE(clock->time(), core::secondsToTicks(2.0 / clock->frameRate()));
    QTest::keyClick(scene, Qt::Key_Left);
    QCOMPARE(clock->time(), core::secondsToTicks(1.0 / clock->frameRate()));
    QTest::keyClick(scene, Qt::Key_End);
    QCOMPARE(clock->time(), clock->duration());
    QTest::keyClick(scene, Qt::Key_Home);
    QCOMPARE(clock->time(), core::Tick(0));

    // A frame rate picked in the transport steps in its frames and is remembered.
    auto* rate = m_window->transportBar()->findChild<QComboBox*>(QStringLiteral("frameRateChoice"));
    QVERIFY(rate);
    const int index = rate->findData(25.0);
    rate->setCurrentIndex(index);
    emit rate->activated(index);
    QCOMPARE(clock->frameRate(), 25.0);
    QTest::keyClick(scene, Qt::Key_Right);
    QCOMPARE(clock->time(), core::secondsToTicks(0.04));
    QCOMPARE(QSettings().value(QStringLiteral("playback/frameRate")).toInt(), 25);
}

void StudioEditingTest::preferencesChooseTheLanguage()
{
    studio::PreferencesDialog dialog(m_window.get());
    QComboBox* language = dialog.languageChoice();
    QCOMPARE(language->currentData().toString(), QString()); // the system's by default
    QVERIFY(language->findData(QStringLiteral("de")) > 0);
    QVERIFY(language->findData(QStringLiteral("fr")) > 0);
    QCOMPARE(language->itemText(language->findData(QStringLiteral("fr"))), QStringLiteral("Français"));
    language->setCurrentIndex(language->findData(QStringLiteral("de")));
    QVERIFY(dialog.findChild<QLabel*>(QStringLiteral("restartNote"))->isVisibleTo(&dialog));
    dialog.autosaveMinutes()->setValue(5);
    saveScreenshot(&dialog, QStringLiteral("preferences.png"));
    dialog.apply();
    QCOMPARE(editor::preferredLanguage(), QStringLiteral("de"));
    QCOMPARE(editor::preferredLocale().language(), QLocale::German);
    QCOMPARE(studio::PreferencesDialog::storedAutosaveMinutes(), 5);

    // What the studio's main() then installs: German texts.
    QTranslator probe;
    QVERIFY(probe.load(editor::preferredLocale(), QStringLiteral("thespis"), QStringLiteral("_"), QStringLiteral(":/i18n")));
    QVERIFY(probe.language().startsWith(QStringLiteral("de")));
    editor::setPreferredLanguage({});
    QCOMPARE(editor::preferredLanguage(), QString());
}

void StudioEditingTest::paintingAMaskSetsJointWeights()
{
    editor::Document& document = *m_window->document();
    editor::JointMaskPanel* masks = m_window->maskEditor();
    qobject_cast<QDockWidget*>(masks->parentWidget())->raise();
    masks->showMask(QStringLiteral("leftArm"));
    QCOMPARE(masks->currentMask(), QStringLiteral("leftArm"));
    widgets::JointMaskView* view = masks->view();
    view->setBrushWeight(0.5f);
    int elbow = -1, wrist = -1;
    for (int j = 0; j < view->joints().size(); ++j) {
        if (view->joints()[j].name == QStringLiteral("l_elbow"))
            elbow = j;
        if (view->joints()[j].name == QStringLiteral("l_radiocarpal"))
            wrist = j;
    }
    QVERIFY(elbow >= 0 && wrist >= 0);
    drag(view->picture(), view->jointPosition(elbow), view->jointPosition(wrist));
    const core::anim::JointMask& mask = document.scenario().findMask("leftArm")->mask;
    QCOMPARE(mask.weight("l_elbow"), 0.5f);
    QCOMPARE(mask.weight("l_radiocarpal"), 0.5f);
    QCOMPARE(mask.weight("l_sternoclavicular"), 1.0f); // untouched
    QCOMPARE(document.undoStack()->count(), 1);         // one stroke, one step
    saveScreenshot(masks, QStringLiteral("joint_mask_panel.png"));
}

void StudioEditingTest::saveAndReopenGiveTheSameDocument()
{
    editor::Document& document = *m_window->document();
    QVERIFY(document.edit(core::edit::moveActions(document.scenario(), std::vector<ActionPath>{{1, 0, 1}}, core::TicksPerSecond),
                          QStringLiteral("Move")));
    QVERIFY(m_window->isWindowModified());
    const QString path = m_dir.filePath(QStringLiteral("sub/saved.thespis"));
    QDir().mkpath(m_dir.filePath(QStringLiteral("sub")));
    QVERIFY(document.edit(core::edit::setCharacterBake(document.scenario(), 0, "bakes/made-here.prt"), QStringLiteral("Bake")));
    const QString bakeFile = QDir(document.baseDir()).absoluteFilePath(QStringLiteral("bakes/made-here.prt"));
    QVERIFY(m_window->saveAs(path));
    QVERIFY(!m_window->isWindowModified());
    const core::scenario::Scenario saved = document.scenario();
    // The same file, named from the new folder.
    QCOMPARE(QDir::cleanPath(QDir(document.baseDir()).absoluteFilePath(QString::fromStdString(saved.characters[0].bake))), bakeFile);

    // The history still fits the document saved elsewhere: undo and redo the bake, then the move.
    document.undoStack()->undo();
    QCOMPARE(document.scenario().characters[0].bake, std::string());
    document.undoStack()->redo();
    QVERIFY(document.scenario() == saved);
    document.undoStack()->undo();
    document.undoStack()->undo();
    QCOMPARE(document.undoStack()->index(), 0);
    document.undoStack()->redo();
    document.undoStack()->redo();
    QVERIFY(document.scenario() == saved);

    QVERIFY(m_window->openScenario(path));
    QVERIFY(m_window->document()->scenario() == saved);
}

void StudioEditingTest::autosavedWorkSurvivesKill9()
{
    // A studio process of its own, with its own data folder.
    const QString data = m_dir.filePath(QStringLiteral("xdg"));
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    env.insert(QStringLiteral("XDG_DATA_HOME"), data);
    QProcess child;
    child.setProcessEnvironment(env);
    child.setProcessChannelMode(QProcess::ForwardedErrorChannel);
    child.start(QCoreApplication::applicationFilePath(), {QStringLiteral("--crash-child"), demoPath()});
    QVERIFY(child.waitForStarted());
    QByteArray output;
    QElapsedTimer waited;
    waited.start();
    while (!output.contains("AUTOSAVED") && waited.elapsed() < 60000)
        if (child.waitForReadyRead(1000))
            output += child.readAllStandardOutput();
    QVERIFY2(output.contains("AUTOSAVED"), output.constData());
    child.kill(); // SIGKILL: no chance to clean up
    QVERIFY(child.waitForFinished());
    QCOMPARE(child.exitStatus(), QProcess::CrashExit);

    // The next start finds the copy and recovers the edit into a modified document.
    qputenv("XDG_DATA_HOME", data.toLocal8Bit());
    QStandardPaths::setTestModeEnabled(false);
    const auto pending = editor::Autosaver::pendingRecoveries();
    QCOMPARE(pending.size(), 1);
    QCOMPARE(QFileInfo(pending.front().originalPath), QFileInfo(demoPath()));
    auto recovered = editor::Document::recover(pending.front().recoveryFile, pending.front().originalPath, pending.front().baseDir);
    QVERIFY(recovered.ok());
    QVERIFY((*recovered)->isModified());
    QCOMPARE((*recovered)->filePath(), QFileInfo(demoPath()).absoluteFilePath());
    auto expected = core::scenario::loadScenario(demoPath().toStdString()).value();
    QVERIFY(core::edit::moveActions(expected, std::vector<ActionPath>{{0, 0, 1}}, core::TicksPerSecond)->apply(expected).ok());
    QVERIFY((*recovered)->scenario() == expected);
    editor::Autosaver::removeRecovery(pending.front());
    QVERIFY(editor::Autosaver::pendingRecoveries().isEmpty());
    QStandardPaths::setTestModeEnabled(true);
}

int main(int argc, char** argv)
{
    if (argc >= 3 && std::string_view(argv[1]) == "--crash-child")
        return runCrashChild(argc, argv);
    QApplication app(argc, argv);
    StudioEditingTest test;
    return QTest::qExec(&test, argc, argv);
}

#include "studio_editing_test.moc"
