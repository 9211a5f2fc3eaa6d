#include "anim/root_motion.h"

#include <cmath>

namespace thespis::core::anim {

namespace {

std::complex<double> onFloor(const Vec3& p)
{
    return {p.z, p.x};
}

} // namespace

RootElements rootElements(const FrameLayout& layout)
{
    RootElements root;
    if (layout.translationCount() == 0)
        return root;
    // The body's root: humanoid_root when the layout has it translating (a rig whose armature
    // root stays on the floor moves its hips), else the first translation.
    int element = layout.find("humanoid_root", ElementKind::Translation);
    if (element < 0)
        element = layout.rotationCount();
    root.valid = true;
    root.translation = layout.floatOffset(element);
    root.rotation = layout.find(layout.name(element), ElementKind::Rotation);
    return root;
}

double heading(const Quat& rootRotation)
{
    const Vec3 forward = rotate(rootRotation, Vec3{0, 0, 1});
    if (std::abs(forward.x) < 1e-9f && std::abs(forward.z) < 1e-9f)
        return 0; // facing straight up or down: no heading
    return std::atan2(double(forward.x), double(forward.z));
}

FloorMove FloorMove::onto(const Vec3& from, double fromHeading, const Vec3& to, double toHeading)
{
    FloorMove move;
    move.yaw = toHeading - fromHeading;
    move.shift = onFloor(to) - std::polar(1.0, move.yaw) * onFloor(from);
    return move;
}

FloorMove FloorMove::repeated(long long times) const
{
    // p ↦ w·p + s done k times: w^k·p + s·(1 + w + … + w^(k−1)).
    FloorMove result;
    result.yaw = yaw * double(times);
    const std::complex<double> w = std::polar(1.0, yaw);
    if (std::abs(1.0 - w) < 1e-12)
        result.shift = shift * double(times);
    else
        result.shift = shift * (1.0 - std::polar(1.0, result.yaw)) / (1.0 - w);
    return result;
}

Quat FloorMove::rotation() const
{
    return Quat::fromAxisAngle(Vec3{0, 1, 0}, float(yaw));
}

Vec3 FloorMove::apply(const Vec3& point) const
{
    const std::complex<double> moved = std::polar(1.0, yaw) * onFloor(point) + shift;
    return {float(moved.imag()), point.y, float(moved.real())};
}

void Placement::apply(const FrameLayout& layout, std::span<float> frame) const
{
    const RootElements root = rootElements(layout);
    if (!root.valid)
        return;
    if (root.rotation >= 0) {
        Quat& q = rotationAt(frame, root.rotation);
        q = normalize(rotation * q);
    }
    float* p = &frame[root.translation];
    const Vec3 placed = anim::rotate(rotation, Vec3{p[0], p[1], p[2]}) + translation;
    p[0] = placed.x;
    p[1] = placed.y;
    p[2] = placed.z;
}

void FloorMove::apply(const RootElements& root, std::span<float> frame) const
{
    if (!root.valid)
        return;
    if (root.rotation >= 0) {
        Quat& q = rotationAt(frame, root.rotation);
        q = normalize(rotation() * q);
    }
    float* p = &frame[root.translation];
    const Vec3 moved = apply(Vec3{p[0], p[1], p[2]});
    p[0] = moved.x;
    p[2] = moved.z;
}

} // namespace thespis::core::anim
