#pragma once
// What `speak` and `lipsync` share: a spoken or lip-synced line put into a scenario as the
// studio's Insert does (edit::insertSpeech) and saved as another scenario file, its audio named
// relative to where that file is.

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "scenario/open_scenario.h"
#include "speech/speech_plan.h"

namespace thespis::cli {

struct SpeechTarget {
    std::filesystem::path scenario;  ///< the scenario read
    std::filesystem::path out;       ///< the scenario to write
    std::string character;
    double at = 0;                   ///< seconds
};

/// Inserts `line` (its audio given as a path from the working folder, or empty) with its cues
/// into `opened` and writes the result to target.out. Prints what was inserted unless `quiet`;
/// returns the exit status (errors printed, naming the command).
int insertSpeechAndSave(const std::string& command, const core::scenario::OpenedScenario& opened,
                        const SpeechTarget& target, core::scenario::SpeechLine line,
                        const std::vector<core::speech::VisemeCue>& visemes,
                        const std::vector<core::speech::GestureCue>& gestures, bool quiet);

} // namespace thespis::cli
