// PoseSampler: the world positions it computes into its own buffers are the skeleton's forward
// kinematics of the schedule's frame, and its figure description matches the skeleton.

#include <QTest>

#include "editor/document.h"
#include "editor/pose_sampler.h"
#include "fixture_scenario.h"

using thespis::editor::Document;
using thespis::editor::PoseSampler;
using thespis::widgets::BodySide;

class PoseSamplerTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void matchesSkeletonForwardKinematics();
    void followsTheSchedule();
    void describesTheFigure();
    void sweptBoundsHoldEveryPose();

private:
    std::unique_ptr<Document> m_document;
    const thespis::core::scenario::CharacterRuntime& ada() const { return m_document->runtime().characters.at(0); }
};

void PoseSamplerTest::initTestCase()
{
    auto document = Document::fromScenario(thespis::test::makeFixtureScenario(), QString());
    QVERIFY2(document.ok(), document.ok() ? "" : thespis::core::describe(document.error()).c_str());
    m_document = std::move(*document);
    QCOMPARE(m_document->runtime().characters.size(), std::size_t(2));
}

void PoseSamplerTest::matchesSkeletonForwardKinematics()
{
    PoseSampler sampler(ada());
    for (double t : {0.0, 0.6, 1.0, 2.4, 3.99}) {
        sampler.sample(t);
        const std::vector<thespis::core::anim::Vec3d> expected = ada().skeleton.worldPositions(sampler.frame());
        QCOMPARE(sampler.positions().size(), expected.size());
        for (std::size_t j = 0; j < expected.size(); ++j) {
            const QVector3D p = sampler.positions()[j];
            QVERIFY2(std::abs(p.x() - expected[j].x) < 1e-5 && std::abs(p.y() - expected[j].y) < 1e-5 &&
                         std::abs(p.z() - expected[j].z) < 1e-5,
                     qPrintable(QStringLiteral("joint %1 at t=%2").arg(j).arg(t)));
        }
    }
}

void PoseSamplerTest::followsTheSchedule()
{
    PoseSampler sampler(ada());
    const int wrist = ada().skeleton.find("r_radiocarpal");
    QVERIFY(wrist >= 0);
    sampler.sample(0.0); // nothing plays: rest pose, arm down
    const QVector3D rest = sampler.positions()[std::size_t(wrist)];
    sampler.sample(1.0); // "raise" at its peak: the right arm swings out (−X is the right)
    const QVector3D raised = sampler.positions()[std::size_t(wrist)];
    QVERIFY2(raised.y() > rest.y() + 0.2, qPrintable(QStringLiteral("%1 → %2").arg(rest.y()).arg(raised.y())));
    QVERIFY(raised.x() < rest.x() - 0.2);
    // Evaluating the same time gives the same pose.
    sampler.sample(1.0);
    QCOMPARE(sampler.positions()[std::size_t(wrist)], raised);
}

void PoseSamplerTest::describesTheFigure()
{
    PoseSampler sampler(ada());
    const thespis::widgets::PoseFigure figure = sampler.figure(Qt::red);
    QCOMPARE(figure.name, QStringLiteral("Ada"));
    QCOMPARE(figure.color, QColor(Qt::red));
    QCOMPARE(figure.parents, ada().skeleton.parents());
    QCOMPARE(figure.headJoint, ada().skeleton.find("skullbase"));
    QCOMPARE(figure.sides[std::size_t(ada().skeleton.find("l_elbow"))], BodySide::Left);
    QCOMPARE(figure.sides[std::size_t(ada().skeleton.find("r_knee"))], BodySide::Right);
    QCOMPARE(figure.sides[std::size_t(ada().skeleton.find("vl5"))], BodySide::Centre);
    // An adult H-Anim figure is about 1.7 m: the head radius is about a sixteenth of that.
    QVERIFY(figure.headRadius > 0.07f && figure.headRadius < 0.13f);
}

void PoseSamplerTest::sweptBoundsHoldEveryPose()
{
    PoseSampler sampler(ada());
    const auto [low, high] = sampler.sweepBounds(4.0, 0.1);
    for (double t = 0; t <= 4.0; t += 0.25) {
        sampler.sample(t);
        for (const QVector3D& p : sampler.positions()) {
            QVERIFY(p.x() >= low.x() - 0.02f && p.x() <= high.x() + 0.02f);
            QVERIFY(p.y() >= low.y() - 0.02f && p.y() <= high.y() + 0.02f);
        }
    }
    QVERIFY(high.y() - low.y() > 1.3f); // a standing figure
}

QTEST_MAIN(PoseSamplerTest)
#include "pose_sampler_test.moc"
