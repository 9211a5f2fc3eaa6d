// thespis-cli speak: a character of a scenario says tagged text or plays a BML block (paper §5,
// issue 33): core's SpeakJob speaks it with espeak-ng; tagged text's visemes and gestures are
// planned and written as a WAV, and with --scenario-out its face actions and gestures — or the
// BML block's speeches, gestures, head and face lexemes and gaze — are inserted into the
// scenario as the studio's Insert does (core/edit/speech_edits.h, bml_edits.h).

#include <cstdio>

#include "commands.h"
#include "speech_output.h"
#include "edit/speech_edits.h"
#include "exit_codes.h"
#include "job_progress.h"
#include "scenario/scenario_io.h"
#include "speech/speak_job.h"
#include "util/file_io.h"

namespace thespis::cli {

CommandSpec speakSpec()
{
    CommandSpec spec;
    spec.name = "speak";
    spec.summary = "Make a character say tagged text or play BML: speech audio, visemes, gestures and gaze.";
    spec.positionals = {"SCENARIO"};
    spec.options = {
        {"character", "NAME", "who speaks", true},
        {"text", "TEXT", "what is said; gestures as <begin_gesture id=\"g1\" anim=\"NAME\"/> … <end_gesture id=\"g1\"/>"},
        {"text-file", "FILE", "read what is said from a UTF-8 file instead"},
        {"bml", "FILE.xml", "a BML 1.0 block to play instead (<speech>, <gesture>, <head>, <faceLexeme>, <gaze> …)"},
        {"voice", "VOICE", "an espeak-ng voice (default en-us; --voices lists them)"},
        {"rate", "WPM", "words a minute, 80 … 450 (default 175)"},
        {"pitch", "P", "0 … 100 (default 50)"},
        {"at", "SECONDS", "where the speech starts on the scenario's timeline (default 0)"},
        {"out", "FILE.wav", "the speech audio (16-bit, 22 050 Hz)"},
        {"scenario-out", "FILE.thespis", "the scenario with the line (its text, voice, timing and --out audio), its face actions and gestures"},
        {"quiet", "", "no progress and no summary"},
    };
    spec.description =
        "The text is spoken sentence by sentence. With --scenario-out the line is kept on the\n"
        "character (its audio plays from --at in `play --audio` and travels in packages), each\n"
        "phoneme becomes an MPEG-4 viseme action on the character's \"Speech\" face layer, weighted\n"
        "by the coarticulation dominance curve, and each tagged gesture plays its gesticon entry\n"
        "over the time of its words (face gestures on the\n"
        "Speech layer, body gestures on a \"Gestures\" layer). The summary lists the words with their\n"
        "times. Give --out, --scenario-out or both.\n"
        "With --bml the block's behaviours are timed against its speeches' words and inserted with\n"
        "--scenario-out: speeches as lines with their visemes, gestures on \"Gestures\", head nods,\n"
        "shakes and tilts on the additive \"Head\" layer, faceLexemes on \"Face lexemes\", gaze on the\n"
        "\"Gaze\" gaze layer. A BML error names its line and column.\n"
        "Example: thespis-cli speak demo.thespis --character Creon --text 'Are you <begin_gesture\n"
        "  id=\"g1\" anim=\"agree\"/>sure?<end_gesture id=\"g1\"/>' --out creon.wav --scenario-out demo2.thespis\n"
        "         thespis-cli speak demo.thespis --character Creon --bml greet.xml --at 2 --scenario-out demo2.thespis\n"
        "Exit status: 0 done, 2 bad command line or text, 3 the scenario cannot be read or has no such\n"
        "character or gesture, 4 a file could not be written, 130 cancelled.";
    return spec;
}

int runSpeak(const CommandSpec& spec, const ParsedArguments& arguments)
{
    const auto text = arguments.value("text");
    const auto bml = arguments.value("bml");
    const auto textFile = bml ? bml : arguments.value("text-file");
    if (int(text.has_value()) + int(arguments.has("text-file")) + int(bml.has_value()) != 1)
        return usageError(spec, "give one of --text, --text-file and --bml");
    const auto out = arguments.value("out");
    const auto scenarioOut = arguments.value("scenario-out");
    if (!out && !scenarioOut)
        return usageError(spec, "give --out, --scenario-out or both");

    core::speech::SpeakJob job;
    if (textFile) {
        auto read = core::readTextFile(*textFile);
        if (!read) {
            printError(spec.name, read.error());
            return ExitInvalidInput;
        }
        job.text = std::move(*read);
        if (bml && !core::speech::isBml(job.text))
            return usageError(spec, *bml + " is not BML: it does not start with <bml");
    } else {
        job.text = *text;
    }
    int exitCode = ExitOk;
    job.voice.voice = arguments.value("voice").value_or(job.voice.voice);
    job.voice.wordsPerMinute = int(integerOption(spec, arguments, "rate", core::speech::kMinWordsPerMinute,
                                                 core::speech::kMaxWordsPerMinute, exitCode)
                                       .value_or(job.voice.wordsPerMinute));
    job.voice.pitch = int(integerOption(spec, arguments, "pitch", 0, 100, exitCode).value_or(job.voice.pitch));
    if (exitCode != ExitOk)
        return exitCode;
    const double at = secondsOption(spec, arguments, "at", exitCode).value_or(0.0);
    if (exitCode != ExitOk)
        return exitCode;
    job.wavOutput = out.value_or("");
    if (auto valid = job.validate(); !valid)
        return usageError(spec, valid.error().message);

    const std::filesystem::path scenarioPath = arguments.positionals[0];
    auto opened = openScenarioReporting(spec.name, scenarioPath);
    if (!opened)
        return ExitInvalidInput;
    const std::string character = *arguments.value("character");
    const core::scenario::Character* speaker = opened->scenario.findCharacter(character);
    if (!speaker) {
        printError(spec.name, "the scenario has no character '" + character + "'");
        return ExitInvalidInput;
    }

    const bool quiet = arguments.has("quiet");
    const auto spoken = runJobWithProgress(spec.name, job, {core::speech::SpeakJob::SpeakingStage, "sentences"}, quiet,
                                           out ? *out + " was not written" : "nothing was written");
    if (!spoken)
        return reportJobFailure(spec.name, spoken.error());

    if (job.bml) {
        const SpeechTarget target{scenarioPath, *scenarioOut, character, at};
        return insertBmlAndSave(spec.name, *opened, target, *job.bml, job.bmlSpeech, job.voice, quiet);
    }
    if (scenarioOut) {
        const int inserted = insertSpeechAndSave(
            spec.name, *opened, {scenarioPath, *scenarioOut, character, at},
            core::edit::speechLine(job.text, job.voice, job.utterance.timing, out.value_or(""), 0), job.visemeCues,
            job.gestureBml, quiet);
        if (inserted != ExitOk) {
            job.discardOutput();
            return inserted;
        }
    }
    if (quiet)
        return ExitOk;
    const auto& timing = job.utterance.timing;
    std::printf("%s says %zu words in %.2f s%s%s.\n", character.c_str(), timing.words.size(), timing.duration,
                out ? ", written to " : "", out ? out->c_str() : "");
    for (const auto& word : timing.words)
        std::printf("  %7.3f %7.3f  %s\n", at + word.start, at + word.end, word.text.c_str());
    return ExitOk;
}

} // namespace thespis::cli
