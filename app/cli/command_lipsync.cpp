// thespis-cli lipsync WAV: a recorded line's word and phoneme timing (issue 32 §4), by forced
// alignment with what it says (--text or --text-file; with neither, pocketsphinx recognises the
// words first), written as a table with one row per phoneme: start end word phoneme viseme; with
// --scenario-out the line (the recording as its audio), its visemes and its face go into a scenario
// as the studio's Lip Sync does.

#include <cstdio>

#include "commands.h"
#include "exit_codes.h"
#include "job_progress.h"
#include "speech_output.h"
#include "edit/speech_edits.h"
#include "speech/lip_sync.h"
#include "speech/timing_tsv.h"
#include "util/file_io.h"

namespace thespis::cli {

CommandSpec lipsyncSpec()
{
    CommandSpec spec;
    spec.name = "lipsync";
    spec.summary = "Time the words and phonemes of a recorded line; write them as a table (TSV).";
    spec.positionals = {"WAV"};
    spec.options = {
        {"text", "TEXT", "what the recording says"},
        {"text-file", "FILE", "what the recording says, from a UTF-8 text file"},
        {"out", "FILE.tsv", "the timing to write; replaced atomically"},
        {"scenario", "FILE", "the scenario to put the line into (with --character and --scenario-out)"},
        {"character", "NAME", "who says it"},
        {"at", "SECONDS", "where on the timeline the line starts (default 0)"},
        {"scenario-out", "FILE.thespis", "the scenario with the line, its visemes and the recording as its audio"},
        {"quiet", "", "no progress and no summary"},
    };
    spec.description =
        "WAV is a sound file (WAV, FLAC, OGG) of any rate, mono or stereo, of English speech. Without\n"
        "--text or --text-file the words are recognised first (less reliable), then aligned.\n"
        "Rows: start, end (seconds), word (empty in a pause), phoneme (ARPAbet, SIL for a pause),\n"
        "viseme (MPEG-4, 0 in a pause), after a header row. Words missing from pocketsphinx's\n"
        "dictionary are pronounced as espeak-ng says them, with a warning each.\n"
        "With --scenario, --character and --scenario-out the line goes into the scenario as the\n"
        "studio's Lip Sync a Recording does. Give --out, --scenario-out or both.\n"
        "Example: thespis-cli lipsync line.wav --text \"Are you really sure about that?\" --out line.tsv\n"
        "         thespis-cli lipsync line.wav --text-file line.txt --scenario demo.thespis \\\n"
        "           --character Creon --at 2 --scenario-out demo_lipsync.thespis\n"
        "Exit status: 0 written, 2 bad command line, 3 a recording or transcript that cannot be used,\n"
        "4 the file could not be written, 130 cancelled.";
    return spec;
}

int runLipsync(const CommandSpec& spec, const ParsedArguments& arguments)
{
    core::speech::LipSyncJob job;
    job.audio = arguments.positionals[0];
    const auto text = arguments.value("text"), textFile = arguments.value("text-file");
    if (text && textFile)
        return usageError(spec, "give what the recording says with --text or with --text-file, not both");
    if (textFile) {
        auto read = core::readTextFile(*textFile);
        if (!read) {
            printError(spec.name, read.error());
            return ExitInvalidInput;
        }
        job.transcript = std::move(*read);
    } else if (text) {
        job.transcript = *text;
    }
    if ((text || textFile) && job.transcript.find_first_not_of(" \t\r\n") == std::string::npos)
        return usageError(spec, std::string(text ? "--text" : *textFile) + " has no words; leave it out to recognise them");
    const auto out = arguments.value("out");
    const auto scenarioOut = arguments.value("scenario-out");
    const auto scenario = arguments.value("scenario");
    const auto character = arguments.value("character");
    if (!out && !scenarioOut)
        return usageError(spec, "give --out, --scenario-out or both");
    if (scenarioOut && (!scenario || !character))
        return usageError(spec, "--scenario-out needs --scenario and --character");
    int exitCode = ExitOk;
    const double at = secondsOption(spec, arguments, "at", exitCode).value_or(0.0);
    if (exitCode != ExitOk)
        return exitCode;
    const bool quiet = arguments.has("quiet");
    if (auto valid = job.validate(); !valid)
        return usageError(spec, valid.error().message);
    std::optional<core::scenario::OpenedScenario> opened;
    if (scenarioOut) {
        opened = openScenarioReporting(spec.name, *scenario);
        if (!opened)
            return ExitInvalidInput;
        if (!opened->scenario.findCharacter(*character)) {
            printError(spec.name, "the scenario has no character '" + *character + "'");
            return ExitInvalidInput;
        }
    }

    const auto synced = runJobWithProgress(spec.name, job, {core::speech::LipSyncJob::PhonemesStage, "stretches"},
                                           quiet, "nothing was written");
    if (!synced)
        return reportJobFailure(spec.name, synced.error());
    for (const std::string& warning : job.result.warnings)
        std::fprintf(stderr, "thespis-cli %s: warning: %s\n", spec.name.c_str(), warning.c_str());
    if (out)
        if (auto written = core::speech::writeTimingTsv(*out, job.result.timing); !written) {
            printError(spec.name, written.error());
            return ExitFailure;
        }
    if (scenarioOut) {
        const auto& timing = job.result.timing;
        const int inserted = insertSpeechAndSave(
            spec.name, *opened, {*scenario, *scenarioOut, *character, at},
            core::edit::speechLine(job.result.transcript, {}, timing, std::filesystem::absolute(job.audio).string(), 0),
            core::speech::visemeCues(timing), {}, quiet);
        if (inserted != ExitOk)
            return inserted;
    }
    if (!quiet) {
        const auto& timing = job.result.timing;
        if (!text && !textFile)
            std::printf("Recognised: %s\n", job.result.transcript.c_str());
        std::printf("Aligned %zu words, %zu phonemes and pauses, over %.2f s.\n", timing.words.size(),
                    timing.phonemes.size(), timing.duration);
        if (out)
            std::printf("Wrote %s.\n", out->c_str());
    }
    return ExitOk;
}

} // namespace thespis::cli
