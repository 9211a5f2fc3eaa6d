// thespis: the studio window. Opens the built-in demo scenario, or the file given on the
// command line. Without a display it explains how to get one instead of letting Qt abort.

#include <QApplication>
#include <QCommandLineParser>
#include <QDir>
#include <QTimer>

#include <cstdio>

#include "editor/translations.h"
#include "main_window.h"
#include "startup.h"

namespace {

const QCommandLineOption kTimeOption(QStringList{QStringLiteral("t"), QStringLiteral("time")},
                                     QApplication::translate("main", "Start at SECONDS into the scenario."),
                                     QStringLiteral("SECONDS"));
const QCommandLineOption kScreenshotOption(
    QStringLiteral("screenshot"),
    QApplication::translate("main", "Save a picture of the window to FILE (PNG) once the scenario is shown, then quit."),
    QStringLiteral("FILE"));

void setUpParser(QCommandLineParser& parser)
{
    parser.setApplicationDescription(QApplication::translate(
        "main", "Thespis Studio: author and preview virtual humans. Opens SCENARIO, or the built-in demo."));
    parser.addHelpOption();
    parser.addVersionOption();
    parser.addPositionalArgument(QStringLiteral("scenario"),
                                 QApplication::translate("main", "The scenario file (.thespis) to open."),
                                 QStringLiteral("[SCENARIO]"));
    parser.addOption(kTimeOption);
    parser.addOption(kScreenshotOption);
}

bool asksForHelpOrVersion(int argc, char** argv)
{
    for (int i = 1; i < argc; ++i) {
        const QByteArray arg(argv[i]);
        if (arg == "-h" || arg == "--help" || arg == "--help-all" || arg == "-v" || arg == "--version" || arg == "-?")
            return true;
    }
    return false;
}

} // namespace

int main(int argc, char** argv)
{
    QCoreApplication::setOrganizationName(QStringLiteral("Thespis"));
    QCoreApplication::setApplicationName(QStringLiteral("Thespis Studio"));
    QCoreApplication::setApplicationVersion(QStringLiteral(THESPIS_VERSION));

    // --help and --version need no display: answer them with a console-only application.
    if (asksForHelpOrVersion(argc, argv)) {
        QCoreApplication app(argc, argv);
        QCommandLineParser parser;
        setUpParser(parser);
        parser.process(app); // prints and exits
        return 0;
    }

    QStringList arguments;
    for (int i = 0; i < argc; ++i)
        arguments << QString::fromLocal8Bit(argv[i]);
    // The scenario, known before Qt starts, so that a missing display can be explained with it:
    // the first argument that is neither an option nor an option's value.
    static const QStringList kOptionsWithValues = {
        QStringLiteral("-t"), QStringLiteral("--time"), QStringLiteral("--screenshot"),
        // Qt's own (QGuiApplication / QApplication)
        QStringLiteral("-platform"), QStringLiteral("-platformpluginpath"), QStringLiteral("-platformtheme"),
        QStringLiteral("-plugin"), QStringLiteral("-display"), QStringLiteral("-style"), QStringLiteral("-stylesheet"),
        QStringLiteral("-qwindowgeometry"), QStringLiteral("-qwindowtitle"), QStringLiteral("-qwindowicon"),
        QStringLiteral("-geometry"), QStringLiteral("-title"), QStringLiteral("-name"), QStringLiteral("-session")};
    QString scenario;
    for (int i = 1; i < arguments.size() && scenario.isEmpty(); ++i) {
        if (kOptionsWithValues.contains(arguments[i]))
            ++i;
        else if (!arguments[i].startsWith(QLatin1Char('-')))
            scenario = arguments[i];
    }
    const QString binaryDir = thespis::studio::executableDir(argv[0]);
    if (scenario.isEmpty())
        scenario = thespis::studio::defaultScenarioPath(binaryDir);
    const QString studioPath = QDir(binaryDir).filePath(QStringLiteral("thespis"));
    const QString cliPath = thespis::studio::commandLinePath(binaryDir);
    if (const QString reason = thespis::studio::missingDisplayReason(arguments); !reason.isEmpty()) {
        std::fputs(qPrintable(thespis::studio::noDisplayHelp(reason, scenario, studioPath, cliPath)), stderr);
        return thespis::studio::NoDisplayExitCode;
    }

    thespis::studio::installDisplayFailureHandler(scenario, studioPath, cliPath);
    QApplication app(argc, argv);
    thespis::studio::finishDisplayFailureHandler();
    thespis::editor::installTranslators(app, thespis::editor::preferredLocale());

    QCommandLineParser parser;
    setUpParser(parser);
    parser.process(app);
    const QStringList positional = parser.positionalArguments();
    if (positional.size() > 1) {
        std::fprintf(stderr, "thespis: expected at most one scenario, got %d.\n%s", int(positional.size()),
                     qPrintable(parser.helpText()));
        return 2;
    }
    // Qt has taken its own options (-platform …) out by now: the parser has the final word.
    scenario = positional.isEmpty() ? thespis::studio::defaultScenarioPath(binaryDir) : positional.front();

    bool timeOk = true;
    const double startTime = parser.isSet(kTimeOption) ? parser.value(kTimeOption).toDouble(&timeOk) : 0.0;
    if (!timeOk) {
        std::fprintf(stderr, "thespis: --time expects seconds (e.g. 2.5), got \"%s\".\n",
                     qPrintable(parser.value(kTimeOption)));
        return 2;
    }
    const QString screenshot = parser.value(kScreenshotOption);

    thespis::studio::MainWindow window;
    window.show();
    // Open once the event loop runs, so that an error dialog appears over a visible window.
    QTimer::singleShot(0, &window, [&window, scenario, startTime, screenshot] {
        // Work a crashed session autosaved comes first (the question is skipped for screenshots).
        if (screenshot.isEmpty() && window.offerRecovery())
            return;
        const bool opened = window.openScenario(scenario);
        if (opened)
            window.clock()->seek(thespis::core::secondsToTicks(startTime));
        if (screenshot.isEmpty())
            return;
        // Give the window a moment to lay out and paint, then save it and quit.
        QTimer::singleShot(200, &window, [&window, screenshot, opened] {
            const bool saved = window.grab().save(screenshot);
            if (!saved)
                std::fprintf(stderr, "thespis: could not write the screenshot to %s\n", qPrintable(screenshot));
            QCoreApplication::exit(opened && saved ? 0 : 1);
        });
    });
    return app.exec();
}
