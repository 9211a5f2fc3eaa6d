#pragma once
// Private to the glTF character import: the H-Anim names of a rig's joints. The naming
// conventions of glTF rigs (Unity, Blender, Rigify, Quaternius) join the motion capture ones of
// anim/bvh_naming.h, whose tables, namespace stripping, H-Anim name recognition and detection
// threshold both importers share; names are compared here without case and separators, as
// glTF exporters spell them freely. A rig no convention knows is named by its rest shape.

#include <string>
#include <vector>

#include "scene/gltf_character.h"

namespace thespis::core::scene::rig_naming {

/// H-Anim names for a humanoid rig whose joint names say nothing, from its rest shape (see
/// gltf_character.h). `parents` come first; +Y is up. Joints it cannot place keep "" ; all ""
/// when there is no pelvis with two legs and a spine.
std::vector<std::string> namesByShape(const std::vector<int>& parents, const std::vector<Vec3d>& positions);

/// Final joint names: the user's table, else the automatic names; unique; the rest keep their
/// source names. Warns about what did not map.
std::vector<std::string> jointNames(const std::vector<std::string>& sources, const std::vector<int>& parents,
                                    const std::vector<Vec3d>& positions, const GltfCharacterOptions& options,
                                    std::vector<std::string>& warnings);

/// "a, b, c": names listed in a warning.
std::string joinedList(const std::vector<std::string>& items);

} // namespace thespis::core::scene::rig_naming
