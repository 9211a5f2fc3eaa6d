// JointMaskView: painting joints in the body picture, editing weights in the tree, and that
// setters (and only user gestures) stay silent; leaves a screenshot of an "upper body" mask.

#include <QApplication>
#include <QDir>
#include <QDoubleSpinBox>
#include <QLineEdit>
#include <QMenu>
#include <QSignalSpy>
#include <QSlider>
#include <QSpinBox>
#include <QTest>
#include <QTimer>
#include <QTreeWidget>

#include <cmath>

#include "widgets/joint_mask_view.h"

using thespis::widgets::JointMaskView;
using thespis::widgets::MaskJoint;

namespace {

// Indices into the skeleton below.
enum Joint {
    HumanoidRoot, Sacroiliac, LHip, LKnee, LAnkle, RHip, RKnee, RAnkle, Vl5, Vt6, Vc4, Skullbase,
    LSternoclavicular, LShoulder, LElbow, LWrist, RSternoclavicular, RShoulder, RElbow, RWrist, JointCount
};

// An H-Anim LOA 1-like skeleton standing in its default pose (arms down), front view in metres:
// x is the character's left (the viewer's right), y up.
QVector<MaskJoint> skeleton()
{
    auto joint = [](const char* name, int parent, double x, double y) {
        MaskJoint j;
        j.name = QString::fromLatin1(name);
        j.parent = parent;
        j.position = QPointF(x, y);
        return j;
    };
    QVector<MaskJoint> joints = {
        joint("humanoid_root", -1, 0.0, 0.824),
        joint("sacroiliac", HumanoidRoot, 0.0, 0.915),
        joint("l_hip", Sacroiliac, 0.096, 0.912),
        joint("l_knee", LHip, 0.104, 0.487),
        joint("l_ankle", LKnee, 0.110, 0.066),
        joint("r_hip", Sacroiliac, -0.096, 0.912),
        joint("r_knee", RHip, -0.104, 0.487),
        joint("r_ankle", RKnee, -0.110, 0.066),
        joint("vl5", Sacroiliac, 0.0, 1.097),
        joint("vt6", Vl5, 0.0, 1.300),
        joint("vc4", Vt6, 0.0, 1.520),
        joint("skullbase", Vc4, 0.0, 1.621),
        joint("l_sternoclavicular", Vt6, 0.082, 1.420),
        joint("l_shoulder", LSternoclavicular, 0.203, 1.430),
        joint("l_elbow", LShoulder, 0.250, 1.140),
        joint("l_wrist", LElbow, 0.282, 0.850),
        joint("r_sternoclavicular", Vt6, -0.082, 1.420),
        joint("r_shoulder", RSternoclavicular, -0.203, 1.430),
        joint("r_elbow", RShoulder, -0.250, 1.140),
        joint("r_wrist", RElbow, -0.282, 0.850),
    };
    Q_ASSERT(joints.size() == JointCount);
    return joints;
}

// "Upper body": spine, arms and head 1 (named at vl5, inherited above), legs 0 (named at the
// hips), the pelvis and the wrists at 0.5.
QVector<MaskJoint> upperBody()
{
    QVector<MaskJoint> joints = skeleton();
    auto set = [&](int joint, float weight, bool named) {
        joints[joint].weight = weight;
        joints[joint].named = named;
    };
    set(Sacroiliac, 0.5f, true);
    for (int j : {LHip, RHip})
        set(j, 0.0f, true);
    for (int j : {Vl5, LWrist, RWrist})
        set(j, j == Vl5 ? 1.0f : 0.5f, true);
    for (int j : {Vt6, Vc4, Skullbase, LSternoclavicular, LShoulder, LElbow, RSternoclavicular, RShoulder, RElbow})
        set(j, 1.0f, false);
    return joints;
}

QVector<int> jointsOf(const QList<QVariant>& emission)
{
    return emission.at(0).value<QVector<int>>();
}

} // namespace

class JointMaskViewTest : public QObject {
    Q_OBJECT
private slots:
    void init();
    void cleanup();
    void layoutMatchesTheSkeleton();
    void jointAtAndJointPositionAgree();
    void clickPaintsOneJoint();
    void dragPaintsTheJointsAlongThePath();
    void fastMoveStillPaintsJointsInBetween();
    void rightButtonPaintsZero();
    void strokeOverNothingEmitsNothing();
    void hidingMidStrokeFinishesIt();
    void clickSelectsTheJoint();
    void treeSelectionIsReported();
    void typingAWeightRequestsIt();
    void contextMenuRequestsAWeight();
    void settersEmitNothing();
    void brushBarEditsTheBrush();
    void sameStructureUpdatesInPlace();
    void newStructureRebuildsAndKeepsSelectionByName();
    void inheritedWeightsAreGreyItalic();
    void screenshot();

private:
    void showView();
    QVector<int> paintedBy(const QSignalSpy& spy) const;

    JointMaskView* m_view = nullptr;
};

void JointMaskViewTest::init()
{
    m_view = new JointMaskView;
    m_view->resize(760, 520);
}

void JointMaskViewTest::cleanup()
{
    delete m_view;
    m_view = nullptr;
}

void JointMaskViewTest::showView()
{
    m_view->setJoints(upperBody());
    m_view->show();
    QVERIFY(QTest::qWaitForWindowExposed(m_view));
}

void JointMaskViewTest::layoutMatchesTheSkeleton()
{
    showView();
    QWidget* picture = m_view->picture();
    QVERIFY(picture);
    QVERIFY(picture->width() > 300);
    // Front view: the character's left is on the viewer's right, the head is above the feet.
    QVERIFY(m_view->jointPosition(LShoulder).x() > m_view->jointPosition(RShoulder).x());
    QVERIFY(m_view->jointPosition(LWrist).x() > m_view->jointPosition(Sacroiliac).x());
    QVERIFY(m_view->jointPosition(Skullbase).y() < m_view->jointPosition(LAnkle).y());
    // Everything inside the picture.
    for (int j = 0; j < JointCount; ++j)
        QVERIFY(picture->rect().contains(m_view->jointPosition(j)));
    // The aspect ratio is kept: shoulder width over shoulder-to-ankle height as in metres.
    const QPoint ls = m_view->jointPosition(LShoulder), rs = m_view->jointPosition(RShoulder);
    const QPoint la = m_view->jointPosition(LAnkle);
    const double pixels = double(ls.x() - rs.x()) / double(la.y() - ls.y());
    const double metres = (0.203 * 2) / (1.430 - 0.066);
    QVERIFY2(std::abs(pixels - metres) < 0.02, qPrintable(QStringLiteral("%1 vs %2").arg(pixels).arg(metres)));
    // Scaled to fit: the figure uses most of the picture's height.
    QVERIFY(la.y() - m_view->jointPosition(Skullbase).y() > picture->height() / 2);
    QCOMPARE(m_view->jointPosition(-1), QPoint(-1, -1));
    QCOMPARE(m_view->jointPosition(JointCount), QPoint(-1, -1));
}

void JointMaskViewTest::jointAtAndJointPositionAgree()
{
    showView();
    for (int j = 0; j < JointCount; ++j) {
        QCOMPARE(m_view->jointAt(m_view->jointPosition(j)), j);
        // A few pixels off still finds it (within the brush radius).
        QCOMPARE(m_view->jointAt(m_view->jointPosition(j) + QPoint(3, -2)), j);
    }
    // Far from every joint: none.
    QCOMPARE(m_view->jointAt(QPoint(2, 2)), -1);
    // The radius bounds the search.
    const QPoint nearElbow = m_view->jointPosition(LElbow) + QPoint(12, 0);
    QCOMPARE(m_view->jointAt(nearElbow), int(LElbow));
    m_view->setBrushRadius(6);
    QCOMPARE(m_view->jointAt(nearElbow), -1);
}

QVector<int> JointMaskViewTest::paintedBy(const QSignalSpy& spy) const
{
    return spy.isEmpty() ? QVector<int>() : jointsOf(spy.last());
}

void JointMaskViewTest::clickPaintsOneJoint()
{
    showView();
    m_view->setBrushWeight(0.75f);
    QSignalSpy paints(m_view, &JointMaskView::weightsPaintRequested);
    QTest::mouseClick(m_view->picture(), Qt::LeftButton, {}, m_view->jointPosition(LElbow));
    QCOMPARE(paints.count(), 2);
    QCOMPARE(jointsOf(paints.at(0)), QVector<int>{LElbow});
    QCOMPARE(paints.at(0).at(1).toFloat(), 0.75f);
    QCOMPARE(paints.at(0).at(2).toBool(), false);
    QCOMPARE(jointsOf(paints.at(1)), QVector<int>{LElbow});
    QCOMPARE(paints.at(1).at(1).toFloat(), 0.75f);
    QCOMPARE(paints.at(1).at(2).toBool(), true);
    // The view paints nothing itself: the weights change only when the editor says so.
    QCOMPARE(m_view->joints()[LElbow].weight, 1.0f);

    // A wide brush paints every joint under it, the nearest first.
    paints.clear();
    m_view->setBrushRadius(100);
    QTest::mouseClick(m_view->picture(), Qt::LeftButton, {}, m_view->jointPosition(Vt6));
    QCOMPARE(paints.count(), 2);
    const QVector<int> wide = jointsOf(paints.at(1));
    QVERIFY(wide.size() > 3);
    QCOMPARE(wide.first(), int(Vt6));
    QVERIFY(wide.contains(LSternoclavicular) && wide.contains(RSternoclavicular));
    QVERIFY(!wide.contains(LAnkle));
}

void JointMaskViewTest::dragPaintsTheJointsAlongThePath()
{
    showView();
    QSignalSpy paints(m_view, &JointMaskView::weightsPaintRequested);
    QWidget* picture = m_view->picture();
    // Down the left arm, from above the shoulder past the wrist, in small steps.
    const QPoint start = m_view->jointPosition(LShoulder) + QPoint(0, -30);
    const QPoint end = m_view->jointPosition(LWrist) + QPoint(0, 30);
    QTest::mousePress(picture, Qt::LeftButton, {}, start);
    QCOMPARE(paints.count(), 0); // nothing under the brush yet
    for (int step = 1; step <= 20; ++step)
        QTest::mouseMove(picture, start + (end - start) * step / 20);
    QTest::mouseRelease(picture, Qt::LeftButton, {}, end);

    QVERIFY(paints.count() >= 4); // shoulder, elbow, wrist, release
    QCOMPARE(paints.last().at(2).toBool(), true);
    QCOMPARE(jointsOf(paints.last()), (QVector<int>{LShoulder, LElbow, LWrist}));
    // Every emission before the last is unfinished, cumulative (a prefix of the next) and adds.
    for (int i = 0; i + 1 < paints.count(); ++i) {
        QCOMPARE(paints.at(i).at(2).toBool(), false);
        QCOMPARE(paints.at(i).at(1).toFloat(), 1.0f);
        const QVector<int> now = jointsOf(paints.at(i)), next = jointsOf(paints.at(i + 1));
        QVERIFY(next.size() >= now.size());
        QCOMPARE(next.mid(0, now.size()), now);
        if (i + 2 < paints.count())
            QVERIFY(next.size() > now.size());
    }
}

void JointMaskViewTest::fastMoveStillPaintsJointsInBetween()
{
    showView();
    QSignalSpy paints(m_view, &JointMaskView::weightsPaintRequested);
    QWidget* picture = m_view->picture();
    // One jump from the right wrist up the arm and across the chest to the left shoulder, as a
    // fast mouse gives: the brush sweeps the segment, not only its ends.
    m_view->setBrushRadius(10);
    QTest::mousePress(picture, Qt::LeftButton, {}, m_view->jointPosition(RWrist));
    QTest::mouseMove(picture, m_view->jointPosition(RShoulder));
    QTest::mouseMove(picture, m_view->jointPosition(LShoulder));
    QTest::mouseRelease(picture, Qt::LeftButton, {}, m_view->jointPosition(LShoulder));
    const QVector<int> painted = paintedBy(paints);
    QCOMPARE(paints.last().at(2).toBool(), true);
    QCOMPARE(painted.first(), int(RWrist));
    QCOMPARE(painted.indexOf(RElbow), 1);
    QCOMPARE(painted.indexOf(RShoulder), 2);
    QVERIFY(painted.contains(RSternoclavicular) && painted.contains(LSternoclavicular));
    QCOMPARE(painted.last(), int(LShoulder));
    QVERIFY(!painted.contains(Skullbase));
    QCOMPARE(painted.size(), 6);
}

void JointMaskViewTest::rightButtonPaintsZero()
{
    showView();
    m_view->setBrushWeight(0.8f);
    QSignalSpy paints(m_view, &JointMaskView::weightsPaintRequested);
    QTest::mousePress(m_view->picture(), Qt::RightButton, {}, m_view->jointPosition(Skullbase));
    QTest::mouseMove(m_view->picture(), m_view->jointPosition(Vc4));
    QTest::mouseRelease(m_view->picture(), Qt::RightButton, {}, m_view->jointPosition(Vc4));
    QVERIFY(paints.count() >= 2);
    for (const QList<QVariant>& emission : paints)
        QCOMPARE(emission.at(1).toFloat(), 0.0f);
    QCOMPARE(paints.last().at(2).toBool(), true);
    QCOMPARE(jointsOf(paints.last()), (QVector<int>{Skullbase, Vc4}));
    QCOMPARE(m_view->brushWeight(), 0.8f); // the right button does not change the brush
}

void JointMaskViewTest::strokeOverNothingEmitsNothing()
{
    showView();
    QSignalSpy paints(m_view, &JointMaskView::weightsPaintRequested);
    QSignalSpy selections(m_view, &JointMaskView::jointSelected);
    QTest::mousePress(m_view->picture(), Qt::LeftButton, {}, QPoint(5, 5));
    QTest::mouseMove(m_view->picture(), QPoint(40, 8));
    QTest::mouseRelease(m_view->picture(), Qt::LeftButton, {}, QPoint(40, 8));
    QCOMPARE(paints.count(), 0);
    QCOMPARE(selections.count(), 0);
    // The middle button does not paint.
    QTest::mouseClick(m_view->picture(), Qt::MiddleButton, {}, m_view->jointPosition(Vt6));
    QCOMPARE(paints.count(), 0);
}

void JointMaskViewTest::hidingMidStrokeFinishesIt()
{
    showView();
    QSignalSpy paints(m_view, &JointMaskView::weightsPaintRequested);
    QTest::mousePress(m_view->picture(), Qt::LeftButton, {}, m_view->jointPosition(LKnee));
    QCOMPARE(paints.count(), 1);
    // The release will never come (the editor's dock closed): the editor still gets its end.
    m_view->hide();
    QCOMPARE(paints.count(), 2);
    QCOMPARE(paints.last().at(2).toBool(), true);
    // Destroyed mid-stroke: no signal from a half-destroyed view, no crash.
    m_view->show();
    QVERIFY(QTest::qWaitForWindowExposed(m_view));
    QTest::mousePress(m_view->picture(), Qt::LeftButton, {}, m_view->jointPosition(LKnee));
    QCOMPARE(paints.count(), 3);
    delete m_view;
    m_view = nullptr;
    QCOMPARE(paints.count(), 3);
}

void JointMaskViewTest::clickSelectsTheJoint()
{
    showView();
    QSignalSpy selections(m_view, &JointMaskView::jointSelected);
    QTest::mouseClick(m_view->picture(), Qt::LeftButton, {}, m_view->jointPosition(RKnee));
    QCOMPARE(selections.count(), 1);
    QCOMPARE(selections.at(0).at(0).toInt(), int(RKnee));
    QCOMPARE(m_view->currentJoint(), int(RKnee));
    QCOMPARE(m_view->tree()->currentItem()->text(0), QStringLiteral("r_knee"));
}

void JointMaskViewTest::treeSelectionIsReported()
{
    showView();
    QSignalSpy selections(m_view, &JointMaskView::jointSelected);
    QTreeWidget* tree = m_view->tree();
    QCOMPARE(tree->objectName(), QStringLiteral("jointTree"));
    QCOMPARE(tree->headerItem()->text(0), QStringLiteral("Joint"));
    QCOMPARE(tree->headerItem()->text(1), QStringLiteral("Weight"));
    const QList<QTreeWidgetItem*> found = tree->findItems(QStringLiteral("l_elbow"), Qt::MatchExactly | Qt::MatchRecursive);
    QCOMPARE(found.size(), 1);
    // Expanded by default, so every joint is visible.
    QVERIFY(found.first()->parent()->isExpanded());
    const QRect rect = tree->visualItemRect(found.first());
    QVERIFY(rect.isValid());
    QTest::mouseClick(tree->viewport(), Qt::LeftButton, {}, rect.center());
    QCOMPARE(selections.count(), 1);
    QCOMPARE(selections.at(0).at(0).toInt(), int(LElbow));
}

void JointMaskViewTest::typingAWeightRequestsIt()
{
    showView();
    QSignalSpy requests(m_view, &JointMaskView::weightRequested);
    QSignalSpy paints(m_view, &JointMaskView::weightsPaintRequested);
    QTreeWidget* tree = m_view->tree();
    QTreeWidgetItem* item = tree->findItems(QStringLiteral("l_knee"), Qt::MatchExactly | Qt::MatchRecursive).first();
    QCOMPARE(item->text(1), QStringLiteral("0.00"));
    tree->editItem(item, 1);
    auto* editor = tree->viewport()->findChild<QDoubleSpinBox*>(QStringLiteral("weightEditor"));
    QVERIFY(editor);
    QCOMPARE(editor->minimum(), 0.0);
    QCOMPARE(editor->maximum(), 1.0);
    QCOMPARE(editor->singleStep(), 0.05);
    editor->selectAll();
    QTest::keyClicks(editor, QStringLiteral("0.35"));
    QTest::keyClick(editor, Qt::Key_Return);
    // The delegate commits on the next turn of the event loop.
    QTRY_COMPARE(requests.count(), 1);
    QTRY_VERIFY(!tree->viewport()->findChild<QDoubleSpinBox*>(QStringLiteral("weightEditor")));
    QCOMPARE(requests.at(0).at(0).toInt(), int(LKnee));
    QVERIFY(std::abs(requests.at(0).at(1).toFloat() - 0.35f) < 1e-6f);
    QCOMPARE(paints.count(), 0);
    // The view waits for the editor: the shown weight is unchanged until setJoints().
    QCOMPARE(item->text(1), QStringLiteral("0.00"));

    // The name column is not editable.
    tree->editItem(item, 0);
    QVERIFY(!tree->viewport()->findChild<QLineEdit*>());

    // Confirming the shown weight of a named joint asks nothing; of an inherited one it names it.
    QTreeWidgetItem* hip = tree->findItems(QStringLiteral("l_hip"), Qt::MatchExactly | Qt::MatchRecursive).first();
    tree->editItem(hip, 1);
    editor = tree->viewport()->findChild<QDoubleSpinBox*>(QStringLiteral("weightEditor"));
    QVERIFY(editor);
    QTest::keyClick(editor, Qt::Key_Return);
    QTRY_VERIFY(!tree->viewport()->findChild<QDoubleSpinBox*>(QStringLiteral("weightEditor")));
    QCOMPARE(requests.count(), 1);
    tree->editItem(item, 1); // l_knee: inherited 0
    editor = tree->viewport()->findChild<QDoubleSpinBox*>(QStringLiteral("weightEditor"));
    QVERIFY(editor);
    QTest::keyClick(editor, Qt::Key_Return);
    QTRY_COMPARE(requests.count(), 2);
    QCOMPARE(requests.at(1).at(1).toFloat(), 0.0f);
}

void JointMaskViewTest::contextMenuRequestsAWeight()
{
    showView();
    QSignalSpy requests(m_view, &JointMaskView::weightRequested);
    QTreeWidget* tree = m_view->tree();
    QTreeWidgetItem* item = tree->findItems(QStringLiteral("r_shoulder"), Qt::MatchExactly | Qt::MatchRecursive).first();
    QStringList offered;
    QTimer::singleShot(0, this, [&offered] {
        auto* menu = qobject_cast<QMenu*>(QApplication::activePopupWidget());
        QVERIFY(menu);
        for (QAction* action : menu->actions()) {
            offered << action->text();
            if (action->text() == QStringLiteral("Set to 0.5"))
                action->trigger();
        }
        menu->close();
    });
    emit tree->customContextMenuRequested(tree->visualItemRect(item).center());
    QCOMPARE(offered, (QStringList{QStringLiteral("Set to 1"), QStringLiteral("Set to 0.5"), QStringLiteral("Set to 0")}));
    QCOMPARE(requests.count(), 1);
    QCOMPARE(requests.at(0).at(0).toInt(), int(RShoulder));
    QCOMPARE(requests.at(0).at(1).toFloat(), 0.5f);
}

void JointMaskViewTest::settersEmitNothing()
{
    QSignalSpy paints(m_view, &JointMaskView::weightsPaintRequested);
    QSignalSpy requests(m_view, &JointMaskView::weightRequested);
    QSignalSpy selections(m_view, &JointMaskView::jointSelected);
    QCOMPARE(m_view->brushWeight(), 1.0f);
    QCOMPARE(m_view->brushRadius(), 18);
    m_view->setJoints(skeleton());
    m_view->setCurrentJoint(LHip);
    m_view->setJoints(upperBody());
    m_view->setBrushWeight(0.25f);
    m_view->setBrushRadius(30);
    m_view->setCurrentJoint(Vt6);
    m_view->show();
    QVERIFY(QTest::qWaitForWindowExposed(m_view));
    m_view->setJoints(skeleton());
    QCOMPARE(paints.count(), 0);
    QCOMPARE(requests.count(), 0);
    QCOMPARE(selections.count(), 0);
    QCOMPARE(m_view->brushWeight(), 0.25f);
    QCOMPARE(m_view->brushRadius(), 30);
    QCOMPARE(m_view->currentJoint(), int(Vt6));
    QCOMPARE(m_view->findChild<QDoubleSpinBox*>(QStringLiteral("brushWeightSpin"))->value(), 0.25);
    QCOMPARE(m_view->findChild<QSlider*>(QStringLiteral("brushWeightSlider"))->value(), 25);
    QCOMPARE(m_view->findChild<QSpinBox*>(QStringLiteral("brushRadiusSpin"))->value(), 30);
    // Out of range values are clamped.
    m_view->setBrushWeight(3.0f);
    QCOMPARE(m_view->brushWeight(), 1.0f);
    m_view->setBrushRadius(0);
    QVERIFY(m_view->brushRadius() >= 1);
}

void JointMaskViewTest::brushBarEditsTheBrush()
{
    showView();
    auto* spin = m_view->findChild<QDoubleSpinBox*>(QStringLiteral("brushWeightSpin"));
    auto* slider = m_view->findChild<QSlider*>(QStringLiteral("brushWeightSlider"));
    auto* radius = m_view->findChild<QSpinBox*>(QStringLiteral("brushRadiusSpin"));
    QVERIFY(spin && slider && radius);
    QVERIFY(spin->isVisible() && slider->isVisible() && radius->isVisible());
    // The bar sits above the picture.
    QVERIFY(spin->mapTo(m_view, QPoint(0, spin->height())).y() <= m_view->picture()->mapTo(m_view, QPoint(0, 0)).y());
    slider->setValue(40);
    QCOMPARE(m_view->brushWeight(), 0.4f);
    QCOMPARE(spin->value(), 0.4);
    spin->setValue(0.65);
    QCOMPARE(m_view->brushWeight(), 0.65f);
    QCOMPARE(slider->value(), 65);
    radius->setValue(25);
    QCOMPARE(m_view->brushRadius(), 25);
    // The next stroke paints the new weight.
    QSignalSpy paints(m_view, &JointMaskView::weightsPaintRequested);
    QTest::mouseClick(m_view->picture(), Qt::LeftButton, {}, m_view->jointPosition(LWrist));
    QCOMPARE(paints.count(), 2);
    QCOMPARE(paints.at(1).at(1).toFloat(), 0.65f);
}

void JointMaskViewTest::sameStructureUpdatesInPlace()
{
    showView();
    QTreeWidget* tree = m_view->tree();
    QVector<QTreeWidgetItem*> before;
    QTreeWidgetItemIterator it(tree);
    for (; *it; ++it)
        before.append(*it);
    QCOMPARE(before.size(), int(JointCount));
    QTreeWidgetItem* elbow = tree->findItems(QStringLiteral("l_elbow"), Qt::MatchExactly | Qt::MatchRecursive).first();
    tree->setCurrentItem(elbow);
    QTreeWidgetItem* knee = tree->findItems(QStringLiteral("r_knee"), Qt::MatchExactly | Qt::MatchRecursive).first();
    knee->setExpanded(false);

    // A paint stroke in progress, fed back by the editor, goes on.
    QSignalSpy paints(m_view, &JointMaskView::weightsPaintRequested);
    QSignalSpy selections(m_view, &JointMaskView::jointSelected);
    QTest::mousePress(m_view->picture(), Qt::LeftButton, {}, m_view->jointPosition(LElbow));
    QVector<MaskJoint> joints = upperBody();
    joints[LElbow].weight = 0.25f;
    joints[LElbow].named = true;
    m_view->setJoints(joints);
    QTest::mouseMove(m_view->picture(), m_view->jointPosition(LWrist));
    QTest::mouseRelease(m_view->picture(), Qt::LeftButton, {}, m_view->jointPosition(LWrist));
    QCOMPARE(jointsOf(paints.last()), (QVector<int>{LElbow, LWrist}));
    QCOMPARE(paints.last().at(2).toBool(), true);

    QVector<QTreeWidgetItem*> after;
    QTreeWidgetItemIterator again(tree);
    for (; *again; ++again)
        after.append(*again);
    QCOMPARE(after, before);
    QCOMPARE(tree->currentItem(), elbow);
    QVERIFY(!knee->isExpanded());
    QCOMPARE(elbow->text(1), QStringLiteral("0.25"));
    QVERIFY(!elbow->font(0).italic());
    QCOMPARE(selections.count(), 1); // the press on the elbow, nothing from setJoints()
}

void JointMaskViewTest::newStructureRebuildsAndKeepsSelectionByName()
{
    showView();
    QTreeWidget* tree = m_view->tree();
    m_view->setCurrentJoint(RElbow);
    QVector<MaskJoint> joints = upperBody();
    joints.removeAt(RWrist); // a different skeleton: r_elbow keeps its index
    QSignalSpy selections(m_view, &JointMaskView::jointSelected);
    m_view->setJoints(joints);
    QCOMPARE(selections.count(), 0);
    QCOMPARE(tree->topLevelItemCount(), 1);
    int count = 0;
    for (QTreeWidgetItemIterator it(tree); *it; ++it)
        ++count;
    QCOMPARE(count, int(JointCount) - 1);
    QCOMPARE(m_view->currentJoint(), int(RElbow));
    QVERIFY(tree->findItems(QStringLiteral("r_wrist"), Qt::MatchExactly | Qt::MatchRecursive).isEmpty());
    QCOMPARE(m_view->jointPosition(RWrist), QPoint(-1, -1));
    // Empty: nothing to pick.
    m_view->setJoints({});
    QCOMPARE(tree->topLevelItemCount(), 0);
    QCOMPARE(m_view->jointAt(QPoint(100, 100)), -1);
    QCOMPARE(m_view->currentJoint(), -1);
}

void JointMaskViewTest::inheritedWeightsAreGreyItalic()
{
    showView();
    QTreeWidget* tree = m_view->tree();
    QTreeWidgetItem* hip = tree->findItems(QStringLiteral("l_hip"), Qt::MatchExactly | Qt::MatchRecursive).first();
    QTreeWidgetItem* knee = tree->findItems(QStringLiteral("l_knee"), Qt::MatchExactly | Qt::MatchRecursive).first();
    QVERIFY(!hip->font(0).italic());
    QVERIFY(knee->font(0).italic());
    QVERIFY(knee->font(1).italic());
    const QColor text = tree->palette().color(QPalette::Text);
    const QColor grey = knee->foreground(0).color();
    QVERIFY(knee->foreground(0).style() != Qt::NoBrush);
    QVERIFY(std::abs(grey.lightness() - text.lightness()) > 40);
    QCOMPARE(knee->text(1), QStringLiteral("0.00"));
    QCOMPARE(tree->findItems(QStringLiteral("vt6"), Qt::MatchExactly | Qt::MatchRecursive).first()->text(1), QStringLiteral("1.00"));
    QCOMPARE(tree->findItems(QStringLiteral("l_wrist"), Qt::MatchExactly | Qt::MatchRecursive).first()->text(1), QStringLiteral("0.50"));
    // The weight colour ramp goes from a grey to a saturated colour.
    const QColor base = tree->palette().color(QPalette::Base);
    QVERIFY(JointMaskView::weightColor(0.0f, base).hslSaturation() < 40);
    QVERIFY(JointMaskView::weightColor(1.0f, base).hslSaturation() > 200);
    QVERIFY(JointMaskView::weightColor(0.5f, base) != JointMaskView::weightColor(1.0f, base));
}

void JointMaskViewTest::screenshot()
{
    const QString dir = QStringLiteral(THESPIS_SCREENSHOT_DIR);
    QVERIFY(QDir().mkpath(dir));
    auto shoot = [&](JointMaskView& view, const QString& name, QPoint hover) {
        view.resize(760, 520);
        view.setJoints(upperBody());
        view.setCurrentJoint(LShoulder);
        view.setBrushRadius(22);
        view.show();
        QVERIFY(QTest::qWaitForWindowExposed(&view));
        // Hover the brush over the right elbow, so that the circle and the name label show.
        QTest::mouseMove(view.picture(), view.jointPosition(RElbow) + hover);
        QTest::qWait(20);
        const QString path = QDir(dir).filePath(name);
        const QImage image = view.grab().toImage();
        QCOMPARE(image.size(), QSize(760, 520));
        QVERIFY(image.save(path));
        qInfo("screenshot: %s", qPrintable(path));
    };
    shoot(*m_view, QStringLiteral("joint_mask_view.png"), QPoint(3, 2));

    m_view->hide(); // one window under the (simulated) mouse at a time

    // The same in a dark theme: every colour comes from the palette.
    JointMaskView dark;
    QPalette palette;
    palette.setColor(QPalette::Window, QColor(0x2b, 0x2d, 0x31));
    palette.setColor(QPalette::WindowText, QColor(0xdc, 0xde, 0xe2));
    palette.setColor(QPalette::Base, QColor(0x1f, 0x21, 0x24));
    palette.setColor(QPalette::AlternateBase, QColor(0x26, 0x28, 0x2c));
    palette.setColor(QPalette::Text, QColor(0xdc, 0xde, 0xe2));
    palette.setColor(QPalette::Button, QColor(0x33, 0x36, 0x3a));
    palette.setColor(QPalette::ButtonText, QColor(0xdc, 0xde, 0xe2));
    palette.setColor(QPalette::Highlight, QColor(0x3d, 0x8e, 0xe0));
    palette.setColor(QPalette::HighlightedText, Qt::white);
    palette.setColor(QPalette::ToolTipBase, QColor(0x10, 0x11, 0x13));
    palette.setColor(QPalette::ToolTipText, QColor(0xe8, 0xea, 0xee));
    palette.setColor(QPalette::Mid, QColor(0x44, 0x47, 0x4c));
    palette.setColor(QPalette::Dark, QColor(0x18, 0x19, 0x1b));
    palette.setColor(QPalette::Light, QColor(0x50, 0x53, 0x58));
    dark.setPalette(palette);
    shoot(dark, QStringLiteral("joint_mask_view_dark.png"), QPoint(-2, 3));
}

QTEST_MAIN(JointMaskViewTest)
#include "joint_mask_view_test.moc"
