// The thespis binary and scripts/run-studio.sh as a user starts them: without a display they
// explain what to do (exit 3) instead of crashing; --help needs no display; --screenshot shows
// the demo and writes a picture; a bad scenario is an error, not a crash.

#include <QDir>
#include <QFileInfo>
#include <QImage>
#include <QProcess>
#include <QTemporaryDir>
#include <QTest>

#include "scenario/scenario_io.h"

namespace {

const QString kStudio = QStringLiteral(THESPIS_STUDIO_BINARY);
const QString kDemo = QStringLiteral(THESPIS_RESOURCES "/demo.thespis");

struct Run {
    int exitCode = -1;
    QProcess::ExitStatus status = QProcess::CrashExit;
    QString out, err;
};

// Runs a program with the display variables removed (and `extra` added).
Run run(const QString& program, const QStringList& arguments, const QStringList& extra = {})
{
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    for (const char* name : {"DISPLAY", "WAYLAND_DISPLAY", "QT_QPA_PLATFORM"})
        env.remove(QString::fromLatin1(name));
    for (const QString& assignment : extra)
        env.insert(assignment.section(QLatin1Char('='), 0, 0), assignment.section(QLatin1Char('='), 1));
    QProcess process;
    process.setProcessEnvironment(env);
    process.start(program, arguments);
    Run result;
    if (!process.waitForFinished(60000)) {
        process.kill();
        process.waitForFinished();
        return result;
    }
    result.exitCode = process.exitCode();
    result.status = process.exitStatus();
    result.out = QString::fromLocal8Bit(process.readAllStandardOutput());
    result.err = QString::fromLocal8Bit(process.readAllStandardError());
    return result;
}

QString firstCharacter()
{
    auto scenario = thespis::core::scenario::loadScenario(kDemo.toStdString());
    return scenario && !scenario->characters.empty() ? QString::fromStdString(scenario->characters.front().name)
                                                     : QStringLiteral("NAME");
}

} // namespace

class StudioStartupTest : public QObject {
    Q_OBJECT
private slots:
    void withoutDisplayExplainsWhatToDo();
    void unreachableDisplayIsExplainedToo();
    void helpNeedsNoDisplay();
    void screenshotShowsTheDemo();
    void badScenarioIsAnErrorNotACrash();
    void runScriptWithoutDisplayExplainsWhatToDo();
};

void StudioStartupTest::withoutDisplayExplainsWhatToDo()
{
    const Run r = run(kStudio, {kDemo});
    QCOMPARE(r.status, QProcess::NormalExit);
    QCOMPARE(r.exitCode, 3);
    QVERIFY2(r.err.contains(QStringLiteral("no display")), qPrintable(r.err));
    QVERIFY(r.err.contains(QStringLiteral("xvfb-run -a")));
    QVERIFY(r.err.contains(QStringLiteral("ssh -X")));
    QVERIFY(r.err.contains(QStringLiteral("QT_QPA_PLATFORM")));
    QVERIFY(r.err.contains(QStringLiteral(" validate ") + kDemo));
    // The bake example names a character the demo really has, so it runs as printed.
    QVERIFY2(r.err.contains(QStringLiteral("bake-motion ") + kDemo + QStringLiteral(" --character ") + firstCharacter()),
             qPrintable(r.err));
}

void StudioStartupTest::unreachableDisplayIsExplainedToo()
{
    // DISPLAY points to no X server: Qt gives up; the studio explains instead of aborting.
    const Run r = run(kStudio, {kDemo}, {QStringLiteral("DISPLAY=:4242")});
    QCOMPARE(r.status, QProcess::NormalExit);
    QCOMPARE(r.exitCode, 3);
    QVERIFY2(r.err.contains(QStringLiteral("xvfb-run -a")), qPrintable(r.err));
}

void StudioStartupTest::helpNeedsNoDisplay()
{
    const Run r = run(kStudio, {QStringLiteral("--help")});
    QCOMPARE(r.exitCode, 0);
    QVERIFY(r.out.contains(QStringLiteral("[SCENARIO]")));
    QVERIFY(r.out.contains(QStringLiteral("--screenshot")));
}

void StudioStartupTest::screenshotShowsTheDemo()
{
    QTemporaryDir dir;
    const QString png = dir.filePath(QStringLiteral("demo.png"));
    const Run r = run(kStudio, {QStringLiteral("--time"), QStringLiteral("2"), QStringLiteral("--screenshot"), png, kDemo},
                      {QStringLiteral("QT_QPA_PLATFORM=offscreen")});
    QVERIFY2(r.exitCode == 0, qPrintable(r.err));
    const QImage image(png);
    QVERIFY(!image.isNull());
    QVERIFY2(image.width() >= 600 && image.height() >= 400, qPrintable(QStringLiteral("%1x%2").arg(image.width()).arg(image.height())));
}

void StudioStartupTest::badScenarioIsAnErrorNotACrash()
{
    QTemporaryDir dir;
    const QString png = dir.filePath(QStringLiteral("bad.png"));
    const Run r = run(kStudio, {QStringLiteral("--screenshot"), png, QStringLiteral(THESPIS_TEST_DATA "/gui/malformed_start.thespis")},
                      {QStringLiteral("QT_QPA_PLATFORM=offscreen")});
    QCOMPARE(r.status, QProcess::NormalExit);
    QCOMPARE(r.exitCode, 1); // the window showed the error, then the picture was taken
    QVERIFY(QFileInfo::exists(png));
    // Option values are not taken for the scenario: the demo opens (exit 0).
    QCOMPARE(run(kStudio, {QStringLiteral("--time"), QStringLiteral("1"), QStringLiteral("--screenshot"), png},
                 {QStringLiteral("QT_QPA_PLATFORM=offscreen")}).exitCode, 0);
    QCOMPARE(run(kStudio, {QStringLiteral("--time"), QStringLiteral("soon"), kDemo},
                 {QStringLiteral("QT_QPA_PLATFORM=offscreen")}).exitCode, 2);
}

void StudioStartupTest::runScriptWithoutDisplayExplainsWhatToDo()
{
    const Run r = run(QStringLiteral("bash"), {QStringLiteral(THESPIS_SOURCE_DIR "/scripts/run-studio.sh")},
                      {QStringLiteral("THESPIS_BUILD_DIR=" THESPIS_BUILD_DIR)});
    QCOMPARE(r.exitCode, 3);
    QVERIFY2(r.err.contains(QStringLiteral("xvfb-run -a scripts/studio.sh")), qPrintable(r.err));
    QVERIFY(r.err.contains(QStringLiteral("thespis-cli validate")));
    QVERIFY(r.err.contains(QStringLiteral("--character \"") + firstCharacter() + QLatin1Char('"')));
}

QTEST_MAIN(StudioStartupTest)
#include "studio_startup_test.moc"
