#pragma once
// Stands an imported rig up in H-Anim's axes: +Y up, facing +Z, +X its left. Files from other
// tools lie down or face away (MakeHuman's and Blender's BVH exports are Z-up, some rigs face
// −Z): their rest pose says so, by where the head is from the root and where the left hip or
// shoulder is from the right one. The turn is a whole number of quarter turns, so a file already
// in H-Anim's axes is left exactly as it is.

#include <span>
#include <string>
#include <vector>

#include "anim/skeleton.h"

namespace thespis::core::anim {

/// A rotation by quarter turns: a signed permutation matrix (rows of the rotated axes).
struct AxisTurn {
    int matrix[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    bool isIdentity() const;
    /// "Z up, facing −Y" style words for what the rig was, for import reports.
    std::string description;
    Vec3d apply(const Vec3d& v) const;
};

/// The turn that stands `skeleton` (H-Anim joint names: humanoid_root, skullbase or a spine
/// joint, the hips or shoulders) up in H-Anim's axes, or the identity when it already is or its
/// names do not tell.
AxisTurn uprightTurn(const Skeleton& skeleton);

/// Turns joints: their offsets and end sites.
void applyTurn(const AxisTurn& turn, std::vector<Joint>& joints);
/// Turns frames of `layout` (rotations R·q·R⁻¹, translations R·t); `frames` holds whole frames
/// one after another.
void applyTurn(const AxisTurn& turn, const FrameLayout& layout, std::span<float> frames);
/// The turn as a unit quaternion.
Quatd turnRotation(const AxisTurn& turn);

} // namespace thespis::core::anim
