#pragma once
// The character a transfer bake bakes, described as `thespis-cli bake` and thespis.farm name it,
// and its loading: a glTF file (segments by mesh node, a skinned mesh split by dominant joint
// unless told not to), or a scenario's character — from a .thespis file or a .thespkg package —
// whose body is its glTF model or the built-in humanoid with the scenario's segment tags
// (loadCharacterBody, the mesh the renderer draws); then the tags of a tags file, or of another
// scenario's character, on top. The description is plain data so that a farm's workers, in
// other processes or machines, load the very mesh the local bake would.

#include <filesystem>
#include <string>

#include "scene/character_mesh.h"
#include "util/error.h"

namespace thespis::core::scenario {

struct BakeCharacter {
    std::filesystem::path file;         ///< .gltf/.glb, .thespis or .thespkg
    std::string character;              ///< the scenario's character; empty: its only one
    std::filesystem::path tagsFile;     ///< segment tags JSON (scene::readSegmentTagsFile); empty: none
    std::filesystem::path tagsScenario; ///< take the tags from this scenario's character; glTF files only
    bool splitSkinnedByJoint = true;    ///< glTF files only
};

/// True for the files whose character is a scenario's (.thespis, .thespkg).
bool isScenarioFile(const std::filesystem::path& file);

/// The mesh to bake. Errors name the file, the field or the character: a missing or broken file,
/// no character of that name (listing the scenario's), several characters and none named, an
/// unknown segment in the tags, tagsScenario or splitSkinnedByJoint = false with a scenario file.
Result<scene::CharacterMesh> loadBakeCharacter(const BakeCharacter& source);

} // namespace thespis::core::scenario
