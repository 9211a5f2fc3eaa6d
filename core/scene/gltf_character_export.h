#pragma once
// A character Thespis holds in its own form — the built-in humanoid, which has no glTF file to
// carry its motion — written as a glTF 2.0 character (`thespis-cli bake-motion … --out C.glb`,
// the studio's File ▸ Export ▸ Motion): one node per skeleton joint, named as the joint, at its
// rest offset with no rest rotation (the world-aligned rest pose, character.h); one skinned mesh,
// a primitive per material, sharing POSITION, NORMAL, TEXCOORD_0, JOINTS_0 / WEIGHTS_0 (and _1
// beyond 4 influences; a rigid segment weighs 1 on its joint); a skin whose inverse bind matrices
// undo each joint's rest position; the materials' base colours (metallic 0, roughness 1, as the
// renderer shades them); and the motion as rotation channels on every joint and translation
// channels on the translating ones. With `animationOnly`, the joint nodes and the animation only,
// which play onto a character exported before by node name. Importing the file again
// (gltf_character.h) gives the same skeleton and the baked frames back.

#include <filesystem>
#include <string>
#include <vector>

#include "scene/character.h"
#include "scene/gltf_motion_export.h"
#include "util/error.h"

namespace thespis::core::scene {

struct GltfCharacterResult {
    std::size_t nodes = 0;     ///< joint nodes written
    std::size_t primitives = 0;
    std::vector<std::string> warnings; ///< what was left out (textures), one sentence each
};

/// Writes `character` with `motion` (its body frames on character.skeleton's layout; face frames
/// are not written yet) as `output` (.glb), atomically. Errors: the output is not a .glb, the
/// character or the frames do not validate.
Result<GltfCharacterResult> writeGltfCharacter(const std::filesystem::path& output, const Character& character,
                                               const GltfMotion& motion, bool animationOnly = false);

} // namespace thespis::core::scene
