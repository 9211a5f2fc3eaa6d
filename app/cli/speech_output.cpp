#include "speech_output.h"

#include <cstdio>

#include "commands.h"
#include "edit/bml_edits.h"
#include "edit/speech_edits.h"
#include "exit_codes.h"
#include "scenario/scenario_io.h"

namespace thespis::cli {

namespace {

// Writes the scenario read at target.scenario with `edit` applied to target.out, its files named
// from there. The exit status.
int applyAndSave(const std::string& command, const core::scenario::Scenario& read, const core::edit::Edit& edit,
                 const SpeechTarget& target)
{
    core::scenario::Scenario result = read;
    if (auto applied = edit.apply(result); !applied) {
        printError(command, applied.error());
        return ExitFailure;
    }
    const auto folder = std::filesystem::absolute(target.out).parent_path();
    core::scenario::rebasePaths(result, std::filesystem::absolute(target.scenario).parent_path(), folder);
    if (auto saved = core::scenario::saveScenario(target.out, result); !saved) {
        printError(command, saved.error());
        return ExitFailure;
    }
    return ExitOk;
}

} // namespace

int insertSpeechAndSave(const std::string& command, const core::scenario::OpenedScenario& opened,
                        const SpeechTarget& target, core::scenario::SpeechLine line,
                        const std::vector<core::speech::VisemeCue>& visemes,
                        const core::speech::TaggedBml& gestures, bool quiet)
{
    const core::scenario::Character* speaker = opened.scenario.findCharacter(target.character);
    if (!speaker) {
        printError(command, "the scenario has no character '" + target.character + "'");
        return ExitInvalidInput;
    }
    const auto folder = std::filesystem::absolute(target.out).parent_path();
    // The line names its audio relative to the scenario it is saved in, as every file is: from the
    // real folders, since ".." after a symbolic link leads elsewhere than the path reads.
    if (!line.audio.empty())
        line.audio = std::filesystem::weakly_canonical(std::filesystem::absolute(line.audio))
                         .lexically_relative(std::filesystem::weakly_canonical(folder))
                         .generic_string();
    line.start = core::secondsToTicks(target.at);
    std::optional<core::scenario::ScenarioRuntime> runtime;
    if (!gestures.empty()) { // the gestures' lengths
        auto built = core::scenario::buildRuntime(opened.scenario, opened.assets);
        if (!built) {
            printError(command, built.error());
            return ExitInvalidInput;
        }
        runtime = std::move(built).value();
    }
    auto inserted = core::edit::insertSpeech(opened.scenario, int(speaker - opened.scenario.characters.data()),
                                             std::move(line), visemes, gestures, runtime ? &*runtime : nullptr);
    if (!inserted) {
        printError(command, inserted.error());
        return ExitInvalidInput;
    }
    if (const int saved = applyAndSave(command, opened.scenario, inserted->edit, target); saved != ExitOk)
        return saved;
    if (!quiet)
        std::printf("Inserted into %s: %d viseme actions, %d face and %d body gestures for %s from %g s.\n",
                    target.out.string().c_str(), inserted->visemeActions, inserted->faceGestures,
                    inserted->bodyGestures, target.character.c_str(), target.at);
    return ExitOk;
}

} // namespace thespis::cli

namespace thespis::cli {

int insertBmlAndSave(const std::string& command, const core::scenario::OpenedScenario& opened,
                     const SpeechTarget& target, const core::speech::BmlBlock& block,
                     const std::map<std::string, core::speech::Utterance>& spoken,
                     const core::speech::VoiceSettings& voice, bool quiet)
{
    const core::scenario::Character* who = opened.scenario.findCharacter(target.character);
    if (!who) {
        printError(command, "the scenario has no character '" + target.character + "'");
        return ExitInvalidInput;
    }
    // The gestures' lengths and the skeleton the head gestures are made for.
    auto runtime = core::scenario::buildRuntime(opened.scenario, opened.assets);
    if (!runtime) {
        printError(command, runtime.error());
        return ExitInvalidInput;
    }
    core::edit::BmlInsertOptions options;
    options.voice = voice;
    auto inserted = core::edit::insertBml(opened.scenario, *runtime, int(who - opened.scenario.characters.data()),
                                          block, spoken, options, core::secondsToTicks(target.at));
    if (!inserted) {
        printError(command, inserted.error());
        return ExitInvalidInput;
    }
    if (const int saved = applyAndSave(command, opened.scenario, inserted->edit, target); saved != ExitOk)
        return saved;
    if (!quiet)
        std::printf("Inserted BML block \"%s\" into %s for %s from %g s to %g s: %d speech(es) with %d viseme "
                    "actions, %d gesture(s), %d head gesture(s), %d face lexeme(s), %d gaze(s).\n",
                    block.id.c_str(), target.out.string().c_str(), target.character.c_str(), target.at,
                    target.at + inserted->seconds, inserted->speeches, inserted->visemeActions, inserted->gestures,
                    inserted->headGestures, inserted->faceLexemes, inserted->gazes);
    return ExitOk;
}

} // namespace thespis::cli
