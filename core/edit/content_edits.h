#pragma once
// The edits that fill a scenario with the user's own content: characters (the built-in humanoid
// or a glTF model, their placement), layers, imported clips and the light. As document_edits.h:
// each looks at the document as it is and returns the Edit that makes the change (apply it, or
// push it as one undoable command), or an error saying why it cannot be made.

#include <string>
#include <vector>

#include "edit/scenario_edit.h"
#include "scenario/scenario.h"

namespace thespis::core::edit {

// ---- Characters ------------------------------------------------------------------------------

/// A new character on the built-in humanoid (`model` empty, `skeleton` an H-Anim level) or on a
/// glTF model (path relative to the scenario; skeleton "model" plays on its own rig), with a
/// body and a face layer.
scenario::Character newCharacter(const std::string& name, const std::string& model, const std::string& skeleton);
/// Adds a character at the end (its name made unique: "Actor", "Actor 2", …).
Result<Edit> addCharacter(const scenario::Scenario& scenario, scenario::Character character);
Result<Edit> removeCharacter(const scenario::Scenario& scenario, int character);
/// A new, unique, non-empty name.
Result<Edit> renameCharacter(const scenario::Scenario& scenario, int character, const std::string& name);
/// A copy named "Name 2", a metre to the original's right (its +X), added after the last one.
Result<Edit> duplicateCharacter(const scenario::Scenario& scenario, int character);
/// Another body: a glTF model (empty: the built-in humanoid) and the skeleton its motion plays on
/// ("hanim-loa1", "hanim-loa2", "hanim-25", "model"). A new model drops the old one's segment tags
/// and bake, which name its segments; the built-in humanoid drops the face mapping table too.
Result<Edit> setCharacterBody(const scenario::Scenario& scenario, int character, const std::string& model,
                              const std::string& skeleton);
/// The face mapping table the character's glTF model follows: a `thespis-face-mapping` file, path
/// relative to the scenario's folder; empty: the table recognised from the model's names. Refused
/// for the built-in humanoid, which has its own face.
Result<Edit> setCharacterFaceMapping(const scenario::Scenario& scenario, int character, const std::string& path);
/// Where the character stands (metres) and which way it faces (degrees about +Y).
Result<Edit> setCharacterPlacement(const scenario::Scenario& scenario, int character, anim::Vec3 position,
                                   double heading);

// ---- Layers ----------------------------------------------------------------------------------

/// Adds a layer at the end of the character's (name made unique in the character).
Result<Edit> addLayer(const scenario::Scenario& scenario, int character, const std::string& name,
                      scenario::LayerKind kind);
Result<Edit> removeLayer(const scenario::Scenario& scenario, const LayerPath& layer);
Result<Edit> renameLayer(const scenario::Scenario& scenario, const LayerPath& layer, const std::string& name);
/// Moves a layer `delta` places down (up when negative) among the character's layers.
Result<Edit> moveLayer(const scenario::Scenario& scenario, const LayerPath& layer, int delta);

// ---- Clips -----------------------------------------------------------------------------------

/// Adds clips to a character (names made unique among its clips).
Result<Edit> addClips(const scenario::Scenario& scenario, int character, std::vector<scenario::ClipAsset> clips);
/// An open-ended action playing idle motion from `database` (an .idle file, as the scenario names
/// it) on a body layer from `start`: the character's idle clip on that database when it has one,
/// else a new clip "idle" (seeded by the character's place, so that characters differ) added in
/// the same edit.
Result<Edit> addIdleAction(const scenario::Scenario& scenario, const LayerPath& layer, const std::string& database,
                           Tick start);
/// Replaces a clip (its options, its joint mapping); a new name is followed by the actions,
/// gestures and skeleton ("clip:NAME") that use the clip.
Result<Edit> replaceClip(const scenario::Scenario& scenario, const CharacterItemPath& clip, scenario::ClipAsset value);
/// Removes a clip no action, gesture or skeleton uses (the error names those that do).
Result<Edit> removeClip(const scenario::Scenario& scenario, const CharacterItemPath& clip);

// ---- The light -------------------------------------------------------------------------------

/// Another light: probe file and layout (an empty probe: the default sky), rotation about the
/// vertical axis (degrees), intensity (≥ 0).
Result<Edit> setLighting(const scenario::Scenario& scenario, scenario::LightingSpec lighting);

/// Adds the script, or replaces the source of the one of that name. Errors: an empty name.
Result<Edit> setScript(const scenario::Scenario& scenario, const std::string& name, const std::string& source);
/// Removes the script of that name. Errors: there is none.
Result<Edit> removeScript(const scenario::Scenario& scenario, const std::string& name);

} // namespace thespis::core::edit
