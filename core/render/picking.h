#pragma once
// Picking: which mesh segment of which character a ray from the camera hits first — what the
// studio's segment tag editor selects when the user clicks a character in the viewport. The ray
// is tested against the posed mesh as the node last uploaded it (CharacterNode::posedPositions
// and the character's triangles), so it hits where the character is drawn, not its rest pose.
// Triangles count from both sides (a closed mesh's nearest hit is a face turned to the camera
// anyway). Brute force Möller–Trumbore in double precision over every triangle, with a bounding
// box test per segment first; no allocation per call.

#include <cstddef>
#include <optional>

#include "anim/quat.h"

namespace thespis::core::render {

class CharacterNode;
class RenderScene;

/// A ray in world space; `direction` need not be unit length (it must not be zero).
struct PickRay {
    anim::Vec3d origin;
    anim::Vec3d direction;
};

/// The first surface a ray meets.
struct PickHit {
    std::size_t character = 0; ///< index in the RenderScene (0 for a single node)
    std::size_t segment = 0;   ///< index in the character's mesh.segments
    std::size_t triangle = 0;  ///< global triangle index in the character's mesh
    double distance = 0;       ///< from the ray's origin to `point`, metres (> 0)
    anim::Vec3d point;         ///< world space, on the posed surface
};

/// The nearest hit of `ray` on the node's posed mesh in front of the origin, or nullopt when it
/// misses (or the direction is zero or not finite). `character` is copied into the hit.
std::optional<PickHit> pick(const CharacterNode& node, const PickRay& ray, std::size_t character = 0);
/// The nearest hit over every character of the scene.
std::optional<PickHit> pick(const RenderScene& scene, const PickRay& ray);

} // namespace thespis::core::render
