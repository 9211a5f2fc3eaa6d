// Motion synthesis in the studio (paper §4.3–4.4), on the real window and the demo with its
// shipped CMU-derived files: "Idle" dragged from the clip library onto a body track plays the
// character's idle clip, open-ended, as one undoable step; its settings (seed, variations) edit
// in Properties, one undo step each; the Posture PCs chart shows the pose at the playhead as
// |PC| per component of the upper-body basis (the paper's Figs. 4–5), equal to the basis' own
// projection, and the hand-keyed wave shows more energy in the high components than the idle.

#include <QComboBox>
#include <QDir>
#include <QDockWidget>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QMimeData>
#include <QSettings>
#include <QSpinBox>
#include <QStandardPaths>
#include <QTest>
#include <QUndoStack>

#include <cmath>

#include "edit/content_edits.h"
#include "edit/document_edits.h"
#include "editor/clip_library_panel.h"
#include "editor/document.h"
#include "editor/idle_properties.h"
#include "editor/playback_clock.h"
#include "editor/posture_chart_panel.h"
#include "editor/properties_panel.h"
#include "editor/timeline_panel.h"
#include "gui_support.h"
#include "main_window.h"
#include "motion/posture.h"
#include "motion/posture_bases.h"
#include "widgets/component_chart.h"
#include "widgets/timeline_view.h"

using namespace thespis;
using test::raiseDock;
using test::saveScreenshot;

namespace {

QString demoPath() { return QStringLiteral(THESPIS_RESOURCES "/demo.thespis"); }

// The share of the squared components from index `from` (0-based) on.
double energyFrom(const std::vector<float>& pcs, std::size_t from)
{
    double above = 0, all = 0;
    for (std::size_t i = 0; i < pcs.size(); ++i) {
        all += double(pcs[i]) * pcs[i];
        if (i >= from)
            above += double(pcs[i]) * pcs[i];
    }
    return all > 0 ? above / all : 0;
}

} // namespace

class MotionStudioTest : public QObject {
    Q_OBJECT
private slots:
    void init();
    void cleanup();
    void idleFromTheLibraryAndItsProperties();
    void postureChartShowsTheComponentsOfThePose();

private:
    std::unique_ptr<studio::MainWindow> m_window;
};

void MotionStudioTest::init()
{
    QStandardPaths::setTestModeEnabled(true);
    QSettings().clear();
    m_window = std::make_unique<studio::MainWindow>();
    m_window->resize(1500, 950);
    m_window->show();
    QVERIFY(QTest::qWaitForWindowExposed(m_window.get()));
    QVERIFY(m_window->openScenario(demoPath()));
}

void MotionStudioTest::cleanup()
{
    m_window.reset();
}

void MotionStudioTest::idleFromTheLibraryAndItsProperties()
{
    editor::Document& document = *m_window->document();
    const core::scenario::Scenario original = document.scenario();
    editor::TimelinePanel* timeline = m_window->timeline();
    widgets::TimelineView* view = timeline->view();
    raiseDock(timeline);
    view->setPixelsPerSecond(60);
    QApplication::processEvents();

    // The library offers "Idle" with the shipped database; its drag is a synthesizer's.
    editor::ClipLibraryPanel* library = m_window->clipLibrary();
    QTreeWidgetItem* idle = library->idleItem();
    QVERIFY(idle);
    QVERIFY(idle->flags() & Qt::ItemIsDragEnabled);
    QVERIFY2(idle->text(1).contains(QStringLiteral("cmu_standing.idle")), qPrintable(idle->text(1)));
    std::unique_ptr<QMimeData> mime(library->model()->mimeData({library->indexFromItem(idle)}));
    QVERIFY(mime && mime->hasFormat(QString::fromLatin1(widgets::TimelineView::SynthesizerMimeType)));

    // Dropped on Antigone's body track at 9 s: an action playing her own idle clip (the demo's
    // already plays the shipped database), open-ended, in one undo step.
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
    const auto& antigone = document.scenario().characters[1];
    QCOMPARE(antigone.clips.size(), original.characters[1].clips.size());
    QCOMPARE(antigone.layers[0].actions.size(), original.characters[1].layers[0].actions.size() + 1);
    const core::edit::ActionPath added{1, 0, int(antigone.layers[0].actions.size()) - 1};
    QCOMPARE(QString::fromStdString(antigone.layers[0].actions.back().clip), QStringLiteral("antigone_idle"));
    QCOMPARE(antigone.layers[0].actions.back().start, 9 * core::TicksPerSecond);
    QCOMPARE(document.undoStack()->count(), 1);
    const auto span = core::edit::actionSpan(document.scenario(), document.runtime(), added);
    QVERIFY(span && span->openEnded);
    const int id = timeline->clipId(added);
    QVERIFY(id >= 0);
    QVERIFY(view->clip(id));
    QCOMPARE(view->clip(id)->end, widgets::TimelineView::OpenEnd); // drawn fading out to the right

    // The drop selected it: Properties shows its idle settings.
    QCOMPARE(timeline->currentAction(), std::optional<core::edit::ActionPath>(added));
    editor::PropertiesPanel* properties = m_window->properties();
    raiseDock(properties);
    editor::IdleProperties* settings = properties->idleProperties();
    QVERIFY(settings->isVisible());
    const core::scenario::IdleSynthesizer before = *antigone.clips[0].idle;
    QCOMPARE(settings->seedEdit()->value(), int(before.seed));
    QCOMPARE(settings->amplitudeEdit()->value(), before.amplitude);
    QCOMPARE(settings->databaseLabel()->text(), QStringLiteral("cmu_standing.idle"));

    // Another seed, fewer variations: one undo step each; the runtime plays them.
    settings->seedEdit()->setValue(7);
    QCOMPARE(document.scenario().characters[1].clips[0].idle->seed, std::uint64_t(7));
    settings->amplitudeEdit()->setValue(0.5);
    QCOMPARE(document.scenario().characters[1].clips[0].idle->amplitude, 0.5);
    QCOMPARE(document.undoStack()->count(), 3);
    saveScreenshot(properties, QStringLiteral("idle_properties.png"));
    saveScreenshot(m_window.get(), QStringLiteral("studio_idle.png"));
    document.undoStack()->undo();
    document.undoStack()->undo();
    QVERIFY(*document.scenario().characters[1].clips[0].idle == before);
    QCOMPARE(settings->seedEdit()->value(), int(before.seed));
    document.undoStack()->undo();
    QVERIFY(document.scenario() == original);
    QVERIFY(!document.isModified());
}

void MotionStudioTest::postureChartShowsTheComponentsOfThePose()
{
    editor::Document& document = *m_window->document();
    editor::PostureChartPanel* panel = m_window->postureChart();
    raiseDock(panel);
    panel->characterCombo()->setCurrentIndex(0); // Creon
    const core::scenario::CharacterRuntime& creon = document.runtime().characters[0];
    const auto bases = core::motion::readPostureBasesFile(THESPIS_RESOURCES "/motion/cmu_postures.pca");
    QVERIFY(bases.ok());
    const auto map = core::motion::PostureMap::create(creon.skeleton, core::motion::PostureSet::UpperBody);
    QVERIFY(map.ok());
    const auto componentsAt = [&](double t) {
        std::vector<float> frame = creon.skeleton.restFrame(), posture(45), pcs(45);
        creon.evaluateBody(t, frame);
        map->toPosture(frame, posture);
        bases->upper.project(posture, pcs);
        return pcs;
    };

    // At the height of Creon's hand-keyed wave, and while he only idles.
    const double waving = 3.0, idling = 0.5;
    m_window->clock()->seek(core::secondsToTicks(waving));
    QApplication::processEvents();
    const std::vector<float> wave = componentsAt(waving);
    QCOMPARE(panel->components().size(), std::size_t(45));
    for (std::size_t i = 0; i < 45; ++i)
        QCOMPARE(panel->components()[i], std::abs(wave[i]));
    widgets::ComponentChart* chart = panel->chart();
    QCOMPARE(chart->bars().values.size(), 45);
    QCOMPARE(chart->lines().size(), 1);
    QCOMPARE(chart->lines()[0].values[0], std::sqrt(bases->upper.eigenvalues()[0]));
    QVERIFY2(chart->caption().contains(QStringLiteral("energy above PC 20")), qPrintable(chart->caption()));
    saveScreenshot(panel, QStringLiteral("posture_chart.png"));

    // Figs. 4–5: the hand-keyed pose has a larger share of its energy above PC 20 than the idle
    // from motion capture.
    const double keyed = energyFrom(wave, 20), captured = energyFrom(componentsAt(idling), 20);
    qInfo("energy above PC 20: waving %.2f %%, idling %.2f %%", 100 * keyed, 100 * captured);
    QVERIFY2(keyed > 2 * captured, qPrintable(QStringLiteral("%1 %2").arg(keyed).arg(captured)));
    m_window->clock()->seek(core::secondsToTicks(idling));
    QApplication::processEvents();
    QCOMPARE(panel->components()[0], std::abs(componentsAt(idling)[0]));

    // A character the chart cannot map says why instead of charting.
    QVERIFY(document.edit(core::edit::setCharacterBody(document.scenario(), 0, "", "hanim-loa1"), QStringLiteral("LOA 1")));
    QVERIFY(panel->components().empty());
    QVERIFY2(chart->message().contains(QStringLiteral("vl5")) || chart->message().contains(QStringLiteral("lacks")),
             qPrintable(chart->message()));
    saveScreenshot(panel, QStringLiteral("posture_chart_unmapped.png"));
}

QTEST_MAIN(MotionStudioTest)
#include "motion_studio_test.moc"
