// StickFigure: the world positions it computes into its own buffers are the skeleton's forward
// kinematics of the pose the Session published (placed where the character stands), and its
// figure description matches the skeleton. SkeletonView frames every pose of the timeline.

#include <QTest>

#include "editor/document.h"
#include "editor/playback_clock.h"
#include "editor/session.h"
#include "editor/skeleton_view.h"
#include "editor/stick_figure.h"
#include "fixture_scenario.h"
#include "widgets/pose_view.h"

using thespis::editor::Document;
using thespis::editor::StickFigure;
using thespis::widgets::BodySide;

class StickFigureTest : public QObject {
    Q_OBJECT
private slots:
    void init();
    void matchesSkeletonForwardKinematics();
    void followsTheSchedule();
    void describesTheFigure();
    void theViewIsFramedOnEveryPoseOfTheTimeline();

private:
    thespis::editor::PlaybackClock m_clock;
    std::unique_ptr<thespis::editor::Session> m_session;
    const thespis::core::scenario::CharacterRuntime& ada() const { return m_session->stage()->runtime().characters.at(0); }
    StickFigure adaFigure() const { return StickFigure(ada().name, ada().skeleton); }
};

void StickFigureTest::init()
{
    auto document = Document::fromScenario(thespis::test::makeFixtureScenario(), QString());
    QVERIFY2(document.ok(), document.ok() ? "" : thespis::core::describe(document.error()).c_str());
    m_session = std::make_unique<thespis::editor::Session>(&m_clock);
    m_session->setDocument(std::move(*document));
    QCOMPARE(m_session->stage()->runtime().characters.size(), std::size_t(2));
}

void StickFigureTest::matchesSkeletonForwardKinematics()
{
    StickFigure figure = adaFigure();
    for (double t : {0.0, 0.6, 1.0, 2.4, 3.99}) {
        m_clock.seek(thespis::core::secondsToTicks(t));
        figure.setPose(m_session->poses().characters[0]);
        const std::vector<thespis::core::anim::Vec3d> expected = ada().skeleton.worldPositions(figure.frame());
        QCOMPARE(figure.positions().size(), expected.size());
        for (std::size_t j = 0; j < expected.size(); ++j) {
            const QVector3D p = figure.positions()[j];
            QVERIFY2(std::abs(p.x() - expected[j].x) < 1e-5 && std::abs(p.y() - expected[j].y) < 1e-5 &&
                         std::abs(p.z() - expected[j].z) < 1e-5,
                     qPrintable(QStringLiteral("joint %1 at t=%2").arg(j).arg(t)));
        }
    }
}

void StickFigureTest::followsTheSchedule()
{
    StickFigure figure = adaFigure();
    const int wrist = ada().skeleton.find("r_radiocarpal");
    QVERIFY(wrist >= 0);
    m_clock.seek(0); // nothing plays: rest pose, arm down
    figure.setPose(m_session->poses().characters[0]);
    const QVector3D rest = figure.positions()[std::size_t(wrist)];
    m_clock.seek(thespis::core::secondsToTicks(1.0)); // "raise" at its peak: the right arm swings out (−X is the right)
    figure.setPose(m_session->poses().characters[0]);
    const QVector3D raised = figure.positions()[std::size_t(wrist)];
    QVERIFY2(raised.y() > rest.y() + 0.2, qPrintable(QStringLiteral("%1 → %2").arg(rest.y()).arg(raised.y())));
    QVERIFY(raised.x() < rest.x() - 0.2);
    // Posing the same pose again gives the same positions.
    figure.setPose(m_session->poses().characters[0]);
    QCOMPARE(figure.positions()[std::size_t(wrist)], raised);
}

void StickFigureTest::describesTheFigure()
{
    const thespis::widgets::PoseFigure figure = adaFigure().figure(Qt::red);
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

void StickFigureTest::theViewIsFramedOnEveryPoseOfTheTimeline()
{
    thespis::widgets::PoseView view;
    thespis::editor::SkeletonView skeletons(&view, m_session.get());
    QCOMPARE(view.figureCount(), 2);
    // Every joint at every time lies in the samples' box (which the view frames), and the
    // figures shown follow the Session's ticks.
    QVector3D low(1e9f, 1e9f, 1e9f), high(-1e9f, -1e9f, -1e9f);
    for (const auto& sample : m_session->timelineSamples()) {
        StickFigure figure = adaFigure();
        figure.setPose(sample.characters[0]);
        for (const QVector3D& p : figure.positions()) {
            low = QVector3D(std::min(low.x(), p.x()), std::min(low.y(), p.y()), std::min(low.z(), p.z()));
            high = QVector3D(std::max(high.x(), p.x()), std::max(high.y(), p.y()), std::max(high.z(), p.z()));
        }
    }
    QVERIFY(high.y() - low.y() > 1.3f); // a standing figure
    for (double t = 0; t <= 4.0; t += 0.25) {
        m_clock.seek(thespis::core::secondsToTicks(t));
        QCOMPARE(skeletons.figures()[0].positions().size(), view.figurePositions(0).size());
        for (const QVector3D& p : view.figurePositions(0)) {
            QVERIFY(p.x() >= low.x() - 0.02f && p.x() <= high.x() + 0.02f);
            QVERIFY(p.y() >= low.y() - 0.02f && p.y() <= high.y() + 0.02f);
        }
    }
}

QTEST_MAIN(StickFigureTest)
#include "stick_figure_test.moc"
