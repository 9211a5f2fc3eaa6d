#pragma once
// Where a body frame stands on the floor: its root's position and heading, and moves on the
// floor (a turn about +Y, then a shift) that put one root onto another. Used to start an action
// where the character is or where the previous action left it, and to let a loop go on from where
// its last repetition ended (root motion) instead of jumping back.

#include <complex>
#include <span>

#include "anim/frame.h"

namespace thespis::core::anim {

/// The root of a body's motion in a layout: humanoid_root when it translates, else the joint of
/// the first translation element (its rotation element has the same name).
struct RootElements {
    int rotation = -1;          ///< rotation element, or -1
    std::size_t translation = 0; ///< float offset of the root translation
    bool valid = false;         ///< the layout has a root translation
};
RootElements rootElements(const FrameLayout& layout);

/// Heading of a root rotation: the angle about +Y (radians) of where its +Z points, seen from
/// above (0 = facing +Z, π/2 = facing +X).
double heading(const Quat& rootRotation);

/// A move on the floor: p ↦ turn(p) + shift, the turn about +Y by `yaw` radians (x and z only;
/// heights stay). Floor points are held as complex numbers z + i·x, so a turn is a product.
struct FloorMove {
    double yaw = 0;
    std::complex<double> shift; ///< z + i·x

    /// The move that takes a root standing at `from` facing `fromHeading` onto `to` facing
    /// `toHeading`.
    static FloorMove onto(const Vec3& from, double fromHeading, const Vec3& to, double toHeading);
    /// This move done `times` times over (closed form, exact for any count).
    FloorMove repeated(long long times) const;
    Quat rotation() const;
    Vec3 apply(const Vec3& point) const;
    /// Moves a frame's root (rotation and translation).
    void apply(const RootElements& root, std::span<float> frame) const;
};

/// Where a character stands and faces: a body frame's root is turned, then shifted.
struct Placement {
    Quat rotation;
    Vec3 translation;
    /// Moves the root of a frame of `layout` (the skeleton's, or a rig it is retargeted onto).
    void apply(const FrameLayout& layout, std::span<float> frame) const;
    bool operator==(const Placement&) const = default;
};

} // namespace thespis::core::anim
