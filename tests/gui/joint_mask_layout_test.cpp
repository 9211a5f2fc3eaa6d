// The joint-mask picture's pure layout, without a widget: body widths by joint name, the figure
// fitted into a rectangle with its aspect kept, picking a joint within the brush radius, and the
// joints a brush stroke meets, in the order it meets them.

#include <QTest>

#include <cmath>

#include "widgets/joint_mask_layout.h"

using namespace thespis::widgets;

namespace {

MaskJoint joint(const QString& name, int parent, QPointF position)
{
    MaskJoint j;
    j.name = name;
    j.parent = parent;
    j.position = position;
    return j;
}

// A stick figure without hands or feet (H-Anim LOA 1 style), 1.55 m from ankles to skull base.
QVector<MaskJoint> figure()
{
    return {joint("HumanoidRoot", -1, {0, 0.95}), joint("skullbase", 0, {0, 1.55}),
            joint("l_wrist", 0, {0.6, 1.0}),      joint("r_wrist", 0, {-0.6, 1.0}),
            joint("l_ankle", 0, {0.1, 0}),        joint("r_ankle", 0, {-0.1, 0})};
}

QVector<qreal> widths(const QVector<MaskJoint>& joints)
{
    QVector<qreal> w;
    for (const MaskJoint& j : joints)
        w.append(jointBodyWidth(j.name.toLower()));
    return w;
}

} // namespace

class JointMaskLayoutTest : public QObject {
    Q_OBJECT
private slots:
    void bodyWidthsFollowNames();
    void fitsTheFigureKeepingItsAspect();
    void picksTheNearestJointWithinTheRadius();
    void brushMeetsJointsInStrokeOrder();
};

void JointMaskLayoutTest::bodyWidthsFollowNames()
{
    QCOMPARE(jointBodyWidth("vt6"), 0.30);
    QCOMPARE(jointBodyWidth("l_hip"), 0.17);
    QCOMPARE(jointBodyWidth("r_wrist"), 0.075);
    QCOMPARE(jointBodyWidth("leftforearm"), 0.075); // BVH / FBX names too
    QCOMPARE(jointBodyWidth("l_eyeball_joint"), 0.0); // inside the head
    QCOMPARE(jointBodyWidth("tail"), 0.05);
    QVERIFY(isHeadJoint("skullbase"));
    QVERIFY(!isHeadJoint("vc1"));
}

void JointMaskLayoutTest::fitsTheFigureKeepingItsAspect()
{
    const QVector<MaskJoint> joints = figure();
    JointMaskLayout layout;
    const QRectF fit(20, 10, 400, 600);
    layout.fitInto(joints, widths(joints), fit);
    QCOMPARE(layout.screen.size(), joints.size());
    // Inside the rectangle, centred, touching it on one axis, the same scale on both.
    QVERIFY(fit.adjusted(-1e-6, -1e-6, 1e-6, 1e-6).contains(layout.figure));
    QVERIFY(std::abs(layout.figure.center().x() - fit.center().x()) < 1e-6);
    QVERIFY(std::abs(layout.figure.width() - fit.width()) < 1e-6 || std::abs(layout.figure.height() - fit.height()) < 1e-6);
    const QPointF wrists = layout.screen[2] - layout.screen[3];
    const QPointF skullToRoot = layout.screen[0] - layout.screen[1];
    QVERIFY(std::abs(wrists.x() / 1.2 - skullToRoot.y() / 0.6) < 1e-6);
    QVERIFY(layout.screen[2].x() > layout.screen[3].x()); // the character's left on the viewer's right
    QVERIFY(layout.screen[1].y() < layout.screen[0].y()); // y up becomes y down
    // Leaf wrists and ankles get a hand and a foot; the head sits above the skull base.
    QVERIFY(layout.tipWidth[2] > 0 && layout.tipWidth[4] > 0);
    QCOMPARE(layout.tipWidth[0], 0.0);
    QVERIFY(layout.tip[4].y() > layout.screen[4].y()); // the foot hangs below the ankle
    QVERIFY(!layout.head.isEmpty());
    QVERIFY(layout.head.center().y() < layout.screen[1].y());
    QVERIFY(layout.dotRadius >= 3.5 && layout.dotRadius <= 6.5);

    // Twice the room, twice the size.
    JointMaskLayout big;
    big.fitInto(joints, widths(joints), QRectF(0, 0, 800, 1200));
    const QPointF bigWrists = big.screen[2] - big.screen[3];
    QVERIFY(std::abs(bigWrists.x() - 2 * wrists.x()) < 1e-6);
}

void JointMaskLayoutTest::picksTheNearestJointWithinTheRadius()
{
    JointMaskLayout layout;
    layout.screen = {{100, 100}, {110, 100}, {110, 100}};
    QCOMPARE(layout.jointAt({101, 100}, 18), 0);
    QCOMPARE(layout.jointAt({110, 117.9}, 18), 2); // a tie: the later joint, drawn on top
    QCOMPARE(layout.jointAt({110, 118.1}, 18), -1);
    QCOMPARE(layout.jointAt({100, 100}, 0), 0);
}

void JointMaskLayoutTest::brushMeetsJointsInStrokeOrder()
{
    JointMaskLayout layout;
    layout.screen = {{300, 100}, {100, 105}, {200, 95}, {200, 140}};
    QVector<std::pair<qreal, int>> found;
    // Left to right along y = 100 with a radius of 10: joints 1, 2, 0 in that order; 3 is too far.
    layout.brushHits({50, 100}, {350, 100}, 10, {}, found);
    QCOMPARE(int(found.size()), 3);
    QCOMPARE(found[0].second, 1);
    QCOMPARE(found[1].second, 2);
    QCOMPARE(found[2].second, 0);
    // The same stroke backwards, and with joint 2 already touched.
    layout.brushHits({350, 100}, {50, 100}, 10, {0, 0, 1, 0}, found);
    QCOMPARE(int(found.size()), 2);
    QCOMPARE(found[0].second, 0);
    QCOMPARE(found[1].second, 1);
    // A press without a move: only what is under the brush.
    layout.brushHits({200, 100}, {200, 100}, 10, {}, found);
    QCOMPARE(int(found.size()), 1);
    QCOMPARE(found[0].second, 2);
}

QTEST_MAIN(JointMaskLayoutTest)
#include "joint_mask_layout_test.moc"
