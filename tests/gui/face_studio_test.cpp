// Faces in the studio (issue 31), on the real window and the built-in demo: the face pose editor
// poses Antigone's face live in the 3D view's close-up (the picture changes on the face), saves the
// pose as a face clip and gesture in one undo step; the mask editor shows a face mask on the
// face's regions and paints them; the blink clip's settings edit in Properties, one undo step
// each, never past a whole blink of 0.4 s.

#include <QDockWidget>
#include <QDoubleSpinBox>
#include <QImage>
#include <QPushButton>
#include <QSlider>
#include <QSpinBox>
#include <QTest>
#include <QToolBox>
#include <QUndoStack>

#include <cmath>

#include "edit/document_edits.h"
#include "editor/blink_properties.h"
#include "editor/document.h"
#include "editor/face_pose_panel.h"
#include "editor/joint_mask_panel.h"
#include "editor/playback_clock.h"
#include "editor/properties_panel.h"
#include "editor/session.h"
#include "gui_support.h"
#include "studio_support.h"
#include "main_window.h"
#include "render/scenario_scene.h"
#include "scene/face_mask.h"
#include "scene/fap.h"
#include "widgets/joint_mask_view.h"
#include "widgets/osg_viewport.h"

using namespace thespis;
using test::raiseDock;
using test::characterIndex;
using test::changedPixels;
using test::saveScreenshot;

namespace {

QString demoPath() { return QStringLiteral(THESPIS_RESOURCES "/demo.thespis"); }

} // namespace

class FaceStudioTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void init();
    void facePoseEditorPosesTheFaceLiveAndSavesOneStep();
    void maskEditorShowsAndPaintsAFaceMask();
    void blinkSettingsEditInProperties();

private:
    std::unique_ptr<studio::MainWindow> m_window;
};

void FaceStudioTest::initTestCase()
{
    m_window = std::make_unique<studio::MainWindow>();
    m_window->resize(1440, 900);
    m_window->show();
    QVERIFY(QTest::qWaitForWindowExposed(m_window.get()));
}

void FaceStudioTest::init()
{
    QVERIFY(m_window->openScenario(demoPath()));
    QVERIFY(m_window->document());
    m_window->clock()->pause();
    m_window->clock()->seek(core::secondsToTicks(1.0));
}

void FaceStudioTest::facePoseEditorPosesTheFaceLiveAndSavesOneStep()
{
    editor::Document& document = *m_window->document();
    const auto original = document.scenario();
    editor::FacePosePanel* panel = m_window->facePose();
    QVERIFY(panel);
    raiseDock(panel);
    // Antigone at 9 s holds her head up (the idle motion bows it at other times).
    m_window->clock()->seek(core::secondsToTicks(9.0));
    const int antigone = characterIndex(document, "Antigone");
    QVERIFY(antigone >= 0);
    panel->setCurrentCharacter(antigone);

    // Pose: the 3D view turns to her face.
    widgets::OsgViewport* viewport = m_window->viewport();
    auto* poseButton = panel->findChild<QPushButton*>(QStringLiteral("facePosePlay"));
    QVERIFY(poseButton && poseButton->isEnabled());
    poseButton->click();
    QVERIFY(panel->isPosing());
    const auto head = m_window->scenePreview()->scene()->head("Antigone");
    QVERIFY(head.ok());
    const auto centre = head->bounds.centre();
    QVERIFY2((viewport->centre() - QVector3D(float(centre.x), float(centre.y), float(centre.z))).length() < 0.01f,
             "the camera looks at Antigone's face");
    QTest::qWait(100);
    const QImage neutral = viewport->grabFramebuffer();

    // The jaw slider opens his mouth at once, in the poses the views draw and in the picture.
    QSlider* jaw = panel->slider(core::scene::fapChannel(3));
    QVERIFY(jaw);
    jaw->setValue(500);
    QCOMPARE(panel->pose()[std::size_t(core::scene::fapChannel(3))], 500.0f);
    const auto& face = m_window->session()->poses().characters[std::size_t(antigone)].face;
    QCOMPARE(face[std::size_t(core::scene::fapChannel(3))], 500.0f);
    panel->setChannel(core::scene::expressionChannel(*core::scene::findExpression("surprise")), 0.8f);
    QTest::qWait(100);
    const QImage posed = viewport->grabFramebuffer();
    QVERIFY(neutral.save(QStringLiteral(THESPIS_SCREENSHOT_DIR "/face_pose_before.png")));
    QVERIFY(posed.save(QStringLiteral(THESPIS_SCREENSHOT_DIR "/face_pose_after.png")));
    const int changed = changedPixels(neutral, posed);
    QVERIFY2(changed > 500, qPrintable(QStringLiteral("%1 pixels changed on the face").arg(changed)));
    QVERIFY2(changed < neutral.width() * neutral.height() / 3, "only the face changes, not the whole view");
    QVERIFY(document.scenario() == original); // posing changes nothing in the document
    panel->groups()->setCurrentIndex(1); // the mouth and jaw sliders, for people to see
    QApplication::processEvents();
    saveScreenshot(m_window.get(), QStringLiteral("studio_face_pose.png"));

    // Save: a face clip and a gesture, one undo step.
    const int steps = document.undoStack()->count();
    QVERIFY(panel->save(QStringLiteral("astonished"), true));
    QCOMPARE(document.undoStack()->count(), steps + 1);
    const auto& character = document.scenario().characters[std::size_t(antigone)];
    const core::scenario::ClipAsset* clip = character.findClip("astonished");
    QVERIFY(clip);
    QCOMPARE(clip->scalars, (std::vector<std::string>{"fap3", "expression6"})); // the jaw, surprise
    QCOMPARE(clip->frames.size(), 2 * clip->scalars.size());
    QCOMPARE(clip->frames[0], 500.0f);
    const core::scenario::Gesture* gesture = character.findGesture("astonished");
    QVERIFY(gesture && gesture->clip == "astonished");
    // The stage plays the saved clip as a face action (what scripts and speech will play).
    const auto* runtime = document.runtime().findCharacter("Antigone");
    QVERIFY(runtime && runtime->faceClips.count("astonished"));
    QVERIFY(panel->isPosing()); // posing goes on over the rebuilt stage
    QCOMPARE(m_window->session()->poses().characters[std::size_t(antigone)].face[std::size_t(core::scene::fapChannel(3))], 500.0f);
    document.undoStack()->undo();
    QVERIFY(document.scenario() == original);

    // Off: the face plays the document again.
    poseButton->click();
    QVERIFY(!panel->isPosing());
    QCOMPARE(m_window->session()->poses().characters[std::size_t(antigone)].face[std::size_t(core::scene::fapChannel(3))], 0.0f);
    QVERIFY(!panel->save(QString(), false));
}

void FaceStudioTest::maskEditorShowsAndPaintsAFaceMask()
{
    editor::Document& document = *m_window->document();
    editor::JointMaskPanel* panel = m_window->maskEditor();
    raiseDock(panel);
    QVERIFY(document.edit(core::edit::addMask(document.scenario(), "speech",
                                              core::scene::faceMaskPreset(core::scene::FaceMaskPreset::Speech)),
                          QStringLiteral("Add Mask")));
    panel->showMask(QStringLiteral("speech"));
    QCOMPARE(panel->currentMask(), QStringLiteral("speech"));
    widgets::JointMaskView* view = panel->view();
    QVERIFY(!view->faceOutline().isEmpty());
    const auto& shown = view->joints();
    QCOMPARE(shown.size(), qsizetype(core::scene::kFaceRegions.size() + core::scene::kFaceChannelCount));
    int brows = -1, jaw = -1;
    for (int i = 0; i < shown.size(); ++i) {
        if (shown[i].name == QStringLiteral("brows"))
            brows = i;
        if (shown[i].name == QStringLiteral("open_jaw"))
            jaw = i;
    }
    QVERIFY(brows >= 0 && jaw >= 0);
    QCOMPARE(shown[jaw].weight, 1.0f);
    QCOMPARE(shown[brows].weight, 0.0f);

    // A click on the brows' dot paints them with the brush (1): the speech mask now moves them.
    const int steps = document.undoStack()->count();
    QTest::mouseClick(view->picture(), Qt::LeftButton, {}, view->jointPosition(brows));
    QCOMPARE(document.undoStack()->count(), steps + 1);
    const core::scenario::NamedMask* mask = document.scenario().findMask("speech");
    QVERIFY(mask);
    QCOMPARE(mask->mask.weight("brows"), 1.0f);
    QCOMPARE(view->joints()[brows].weight, 1.0f);
    saveScreenshot(panel, QStringLiteral("face_mask.png"));
    document.undoStack()->undo();
    QCOMPARE(document.scenario().findMask("speech")->mask.weight("brows"), -1.0f);

    // A body mask shows the body again.
    panel->showMask(QString::fromStdString(document.scenario().masks.front().name));
    QVERIFY(view->faceOutline().isEmpty());
}

void FaceStudioTest::blinkSettingsEditInProperties()
{
    editor::Document& document = *m_window->document();
    const int antigone = characterIndex(document, "Antigone");
    QVERIFY(antigone >= 0);
    const auto& layers = document.scenario().characters[std::size_t(antigone)].layers;
    std::optional<core::edit::ActionPath> blinking;
    for (std::size_t l = 0; l < layers.size(); ++l)
        for (std::size_t a = 0; a < layers[l].actions.size(); ++a)
            if (layers[l].actions[a].clip == "antigone_blinks")
                blinking = core::edit::ActionPath{antigone, int(l), int(a)};
    QVERIFY(blinking);
    editor::PropertiesPanel* properties = m_window->properties();
    raiseDock(properties);
    properties->setAction(blinking);
    editor::BlinkProperties* blinks = properties->blinkProperties();
    QVERIFY(blinks->isVisible());
    QCOMPARE(blinks->rateEdit()->value(), 17.0);
    const auto clipOf = [&] { return *document.scenario().characters[std::size_t(antigone)].findClip("antigone_blinks")->blinks; };
    const core::scenario::BlinkClip before = clipOf();

    blinks->findChild<QPushButton*>(QStringLiteral("blinkRateTalking"))->click();
    QCOMPARE(clipOf().rate, 26.0);
    blinks->seedEdit()->setValue(9);
    QCOMPARE(clipOf().seed, std::uint64_t(9));
    // A whole blink stays under 0.4 s: opening may only grow as far as closing and shut leave.
    QCOMPARE(blinks->openEdit()->maximum(), 399 - blinks->closeEdit()->value() - blinks->shutEdit()->value());
    blinks->openEdit()->setValue(1000);
    QVERIFY(clipOf().closeSeconds + clipOf().shutSeconds + clipOf().openSeconds < 0.4);
    saveScreenshot(properties, QStringLiteral("blink_properties.png"));
    document.undoStack()->undo();
    document.undoStack()->undo();
    document.undoStack()->undo();
    QVERIFY(clipOf() == before);
    QCOMPARE(blinks->rateEdit()->value(), 17.0);
}

QTEST_MAIN(FaceStudioTest)
#include "face_studio_test.moc"
