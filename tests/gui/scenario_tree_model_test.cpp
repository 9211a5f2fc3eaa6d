// ScenarioTreeModel: the outline lists the document's characters, layers and actions, with
// their clip, start, mode and weight curve, and marks the actions that play at a time.

#include <QAbstractItemModelTester>
#include <QSignalSpy>
#include <QTest>

#include "editor/document.h"
#include "editor/scenario_tree_model.h"
#include "editor/translations.h"
#include "fixture_scenario.h"

using namespace thespis;
using thespis::editor::Document;
using thespis::editor::ScenarioTreeModel;

class ScenarioTreeModelTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void init();
    void cleanup();
    void listsCharactersLayersAndActions();
    void isAConsistentItemModel();
    void marksActionsPlayingAtATime();
    void describesCurves();
    void emptiesWithoutADocument();

private:
    std::unique_ptr<Document> m_document;
    QString text(const QModelIndex& parent, int row, int column) const
    {
        return m_model->index(row, column, parent).data().toString();
    }
    std::unique_ptr<ScenarioTreeModel> m_model;
};

void ScenarioTreeModelTest::initTestCase()
{
    // English, whatever the machine's language: it supplies the plural forms ("1 clip").
    QCOMPARE(thespis::editor::installTranslators(*QCoreApplication::instance(), QLocale(QLocale::English)),
             QStringLiteral("en_US"));
}

void ScenarioTreeModelTest::init()
{
    auto document = Document::fromScenario(thespis::test::makeFixtureScenario(), QString());
    QVERIFY2(document.ok(), document.ok() ? "" : thespis::core::describe(document.error()).c_str());
    m_document = std::move(*document);
    m_model = std::make_unique<ScenarioTreeModel>();
    m_model->setDocument(m_document.get());
}

void ScenarioTreeModelTest::cleanup()
{
    m_model.reset();
    m_document.reset();
}

void ScenarioTreeModelTest::listsCharactersLayersAndActions()
{
    QCOMPARE(m_model->rowCount(), 2);
    QCOMPARE(m_model->columnCount(), int(ScenarioTreeModel::ColumnCount));
    QCOMPARE(m_model->headerData(ScenarioTreeModel::StartColumn, Qt::Horizontal).toString(), QStringLiteral("Start (s)"));
    QCOMPARE(text({}, 0, ScenarioTreeModel::NameColumn), QStringLiteral("Ada"));
    QCOMPARE(text({}, 1, ScenarioTreeModel::NameColumn), QStringLiteral("Ben"));
    QCOMPARE(text({}, 0, ScenarioTreeModel::ClipColumn), QStringLiteral("1 clip"));

    const QModelIndex ada = m_model->index(0, 0);
    QCOMPARE(m_model->rowCount(ada), 1);
    QCOMPARE(text(ada, 0, ScenarioTreeModel::NameColumn), QStringLiteral("base"));
    QCOMPARE(text(ada, 0, ScenarioTreeModel::ClipColumn), QStringLiteral("body layer"));
    const QModelIndex adaBase = m_model->index(0, 0, ada);
    QCOMPARE(m_model->rowCount(adaBase), 2);
    QCOMPARE(text(adaBase, 0, ScenarioTreeModel::NameColumn), QStringLiteral("raise"));
    QCOMPARE(text(adaBase, 0, ScenarioTreeModel::ClipColumn), QStringLiteral("raise_arm"));
    QCOMPARE(text(adaBase, 0, ScenarioTreeModel::StartColumn), QStringLiteral("0.500"));
    QCOMPARE(text(adaBase, 0, ScenarioTreeModel::ModeColumn), QStringLiteral("normalized"));
    QCOMPARE(text(adaBase, 0, ScenarioTreeModel::WeightColumn), QStringLiteral("cubic fade 0.2 / 0.2 s"));
    QCOMPARE(text(adaBase, 0, ScenarioTreeModel::MaskColumn), QStringLiteral("whole body"));
    QCOMPARE(text(adaBase, 1, ScenarioTreeModel::NameColumn), QStringLiteral("raise_again"));
    QCOMPARE(text(adaBase, 1, ScenarioTreeModel::StartColumn), QStringLiteral("2.000"));

    const QModelIndex benBase = m_model->index(0, 0, m_model->index(1, 0));
    QCOMPARE(text(benBase, 0, ScenarioTreeModel::NameColumn), QStringLiteral("bow"));
    QCOMPARE(text(benBase, 0, ScenarioTreeModel::WeightColumn), QStringLiteral("linear ADSR 0.3 / 0.2 / 0.8 / 0.4"));
    QCOMPARE(m_model->rowCount(m_model->index(0, 0, benBase)), 0);

    // Parents lead back up.
    const QModelIndex bow = m_model->index(0, 0, benBase);
    QCOMPARE(bow.parent(), benBase);
    QCOMPARE(bow.parent().parent(), m_model->index(1, 0));
    QVERIFY(!m_model->index(1, 0).parent().isValid());
    QCOMPARE(bow.data(ScenarioTreeModel::NodeKindRole).toInt(), int(ScenarioTreeModel::NodeKind::Action));
    QVERIFY(bow.data(Qt::ToolTipRole).toString().contains(QStringLiteral("bend")));
}

void ScenarioTreeModelTest::isAConsistentItemModel()
{
    QAbstractItemModelTester tester(m_model.get(), QAbstractItemModelTester::FailureReportingMode::QtTest);
    m_model->setTime(core::secondsToTicks(1.0));
    m_model->setDocument(nullptr);
    m_model->setDocument(m_document.get());
}

void ScenarioTreeModelTest::marksActionsPlayingAtATime()
{
    const QModelIndex adaBase = m_model->index(0, 0, m_model->index(0, 0));
    const QModelIndex raise = m_model->index(0, 0, adaBase);
    const QModelIndex raiseAgain = m_model->index(1, 0, adaBase);
    const QModelIndex bow = m_model->index(0, 0, m_model->index(0, 0, m_model->index(1, 0)));
    QSignalSpy changed(m_model.get(), &QAbstractItemModel::dataChanged);

    m_model->setTime(core::secondsToTicks(0.0));
    QVERIFY(!raise.data(ScenarioTreeModel::ActiveRole).toBool());
    QCOMPARE(changed.count(), 0); // nothing plays at 0, nothing changed

    m_model->setTime(core::secondsToTicks(0.75)); // raise plays over [0.5, 1.5]
    QVERIFY(raise.data(ScenarioTreeModel::ActiveRole).toBool());
    QVERIFY(!raiseAgain.data(ScenarioTreeModel::ActiveRole).toBool());
    QVERIFY(!bow.data(ScenarioTreeModel::ActiveRole).toBool());
    QCOMPARE(changed.count(), 1);
    QCOMPARE(changed.at(0).at(0).value<QModelIndex>(), raise);
    QVERIFY(raise.data(Qt::FontRole).value<QFont>().bold());

    changed.clear();
    m_model->setTime(core::secondsToTicks(1.2)); // raise and bow ([1.0, 2.5])
    QVERIFY(raise.data(ScenarioTreeModel::ActiveRole).toBool());
    QVERIFY(bow.data(ScenarioTreeModel::ActiveRole).toBool());
    QCOMPARE(changed.count(), 1);

    m_model->setTime(core::secondsToTicks(3.9)); // everything has ended
    QVERIFY(!raise.data(ScenarioTreeModel::ActiveRole).toBool());
    QVERIFY(!raiseAgain.data(ScenarioTreeModel::ActiveRole).toBool());
    QVERIFY(!bow.data(ScenarioTreeModel::ActiveRole).toBool());
}

void ScenarioTreeModelTest::describesCurves()
{
    using thespis::core::anim::Curve;
    using thespis::editor::describeCurve;
    QCOMPARE(describeCurve(Curve()), QStringLiteral("constant 1"));
    QCOMPARE(describeCurve(Curve::linearFade(0.5, 1, 0.8)), QStringLiteral("linear fade 0.5 / 1 s, peak 0.8"));
    QCOMPARE(describeCurve(Curve::cubicAdsr(0.1, 0.2, 0.5, 0.3)), QStringLiteral("cubic ADSR 0.1 / 0.2 / 0.5 / 0.3"));
    auto keyed = Curve::keyframed({{0.0, 0.0}, {1.0, 1.0}, {2.0, 0.0}});
    QVERIFY(keyed.ok());
    QCOMPARE(describeCurve(*keyed), QStringLiteral("keyframed, 3 keys"));
}

void ScenarioTreeModelTest::emptiesWithoutADocument()
{
    QSignalSpy reset(m_model.get(), &QAbstractItemModel::modelReset);
    m_model->setDocument(nullptr);
    QCOMPARE(reset.count(), 1);
    QCOMPARE(m_model->rowCount(), 0);
    m_model->setTime(core::secondsToTicks(1.0)); // no document: nothing to do, no crash
}

QTEST_MAIN(ScenarioTreeModelTest)
#include "scenario_tree_model_test.moc"
