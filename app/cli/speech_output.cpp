#include "speech_output.h"

#include <cstdio>

#include "commands.h"
#include "edit/speech_edits.h"
#include "exit_codes.h"
#include "scenario/scenario_io.h"

namespace thespis::cli {

int insertSpeechAndSave(const std::string& command, const core::scenario::OpenedScenario& opened,
                        const SpeechTarget& target, core::scenario::SpeechLine line,
                        const std::vector<core::speech::VisemeCue>& visemes,
                        const std::vector<core::speech::GestureCue>& gestures, bool quiet)
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
    auto inserted = core::edit::insertSpeech(opened.scenario, int(speaker - opened.scenario.characters.data()),
                                             std::move(line), visemes, gestures);
    if (!inserted) {
        printError(command, inserted.error());
        return ExitInvalidInput;
    }
    core::scenario::Scenario result = opened.scenario;
    if (auto applied = inserted->edit.apply(result); !applied) {
        printError(command, applied.error());
        return ExitFailure;
    }
    core::scenario::rebasePaths(result, std::filesystem::absolute(target.scenario).parent_path(), folder);
    if (auto saved = core::scenario::saveScenario(target.out, result); !saved) {
        printError(command, saved.error());
        return ExitFailure;
    }
    if (!quiet)
        std::printf("Inserted into %s: %d viseme actions, %d face and %d body gestures for %s from %g s.\n",
                    target.out.string().c_str(), inserted->visemeActions, inserted->faceGestures,
                    inserted->bodyGestures, target.character.c_str(), target.at);
    return ExitOk;
}

} // namespace thespis::cli
