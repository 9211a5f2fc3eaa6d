#pragma once
// What `speak` and `lipsync` share: a spoken or lip-synced line, or a BML block, put into a
// scenario as the studio's Insert does (edit::insertSpeech, edit::insertBml) and saved as another
// scenario file, its audio named relative to where that file is.

#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "scenario/open_scenario.h"
#include "speech/bml.h"
#include "speech/espeak_voice.h"
#include "speech/speech_plan.h"
#include "speech/tagged_bml.h"

namespace thespis::cli {

struct SpeechTarget {
    std::filesystem::path scenario;  ///< the scenario read
    std::filesystem::path out;       ///< the scenario to write
    std::string character;
    double at = 0;                   ///< seconds
};

/// Inserts `line` (its audio given as a path from the working folder, or empty) with its viseme
/// cues and tagged gestures (timed on the scenario's built gesticon) into `opened` and writes the
/// result to target.out. Prints what was inserted unless `quiet`; returns the exit status (errors
/// printed, naming the command).
int insertSpeechAndSave(const std::string& command, const core::scenario::OpenedScenario& opened,
                        const SpeechTarget& target, core::scenario::SpeechLine line,
                        const std::vector<core::speech::VisemeCue>& visemes,
                        const core::speech::TaggedBml& gestures, bool quiet);

/// Inserts `block` (its speeches said in `spoken` with `voice`) into `opened` as the studio's
/// Insert does (edit::insertBml) and writes the result to target.out; as insertSpeechAndSave().
int insertBmlAndSave(const std::string& command, const core::scenario::OpenedScenario& opened,
                     const SpeechTarget& target, const core::speech::BmlBlock& block,
                     const std::map<std::string, core::speech::Utterance>& spoken,
                     const core::speech::VoiceSettings& voice, bool quiet);

} // namespace thespis::cli
