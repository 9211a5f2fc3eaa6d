#pragma once
// Reading and writing scenario files (.thespis): JSON with
//   {"format": "thespis-scenario", "version": N, "schema": "Scenario.6", …}
// Readers accept every older version (upgrade steps run in order before parsing) and refuse
// newer ones with ErrorCode::NewerVersion, never loading part of a file. Any malformed input
// gets CorruptData naming the field path ("characters[0].layers[1].actions[2].start: expected an
// integer number of ticks") — never a crash. Writers always write the current version, and
// keep unknown fields.

#include <filesystem>
#include <string>
#include <string_view>

#include "scenario/scenario.h"
#include "util/error.h"

namespace thespis::core::scenario {

inline constexpr std::string_view FormatName = "thespis-scenario";
inline constexpr std::string_view FileExtension = ".thespis";

namespace format {
enum Version : int {
    Initial = 1,
    TimelineAndGesticon = 2, ///< layer mute / solo / lock, markers, the characters' gesticons
    ImportAndPlacement = 3,  ///< clip files' retarget options and glTF animations, action
                             ///< placement, loop root motion, character placement, probe rotation
    Scripts = 4,             ///< Python scripts kept in the scenario
    IdleMotion = 5,          ///< clips that are idle motion synthesizers
    NoPostureTags = 6,       ///< segment tags lost "posture" (PI / PD), which changed nothing
    Blinks = 7,              ///< clips that are blink generators (face layers)
    FaceMappingTable = 8,    ///< a character's own face mapping table file ("faceMapping")
    Speech = 9,              ///< characters' speech lines; dominance weight curves
    Gaze = 10,               ///< gaze layers, whose actions look at a target
    Pointing = 11,           ///< body actions that point their gesture's arm at a target
    BmlLexicon = 12,         ///< a character's own BML lexicon (gesture lexemes → gestures)
    Current = BmlLexicon,
};
} // namespace format

Result<Scenario> parseScenario(std::string_view json);
Result<Scenario> loadScenario(const std::filesystem::path& path);
std::string serializeScenario(const Scenario& scenario);
/// Atomic: a crash or full disk never leaves a half-written file.
Result<void> saveScenario(const std::filesystem::path& path, const Scenario& scenario);

} // namespace thespis::core::scenario
