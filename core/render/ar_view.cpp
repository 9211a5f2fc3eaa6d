#include "render/ar_view.h"

#include <cmath>
#include <numbers>

namespace thespis::core::render {

namespace {

using Matrix = std::array<double, 9>; // row by row

anim::Vec3d times(const Matrix& m, const anim::Vec3d& v)
{
    return {m[0] * v.x + m[1] * v.y + m[2] * v.z, m[3] * v.x + m[4] * v.y + m[5] * v.z,
            m[6] * v.x + m[7] * v.y + m[8] * v.z};
}

anim::Vec3d transposedTimes(const Matrix& m, const anim::Vec3d& v)
{
    return {m[0] * v.x + m[3] * v.y + m[6] * v.z, m[1] * v.x + m[4] * v.y + m[7] * v.z,
            m[2] * v.x + m[5] * v.y + m[8] * v.z};
}

Matrix product(const Matrix& a, const Matrix& b)
{
    Matrix c{};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            for (int k = 0; k < 3; ++k)
                c[std::size_t(3 * i + j)] += a[std::size_t(3 * i + k)] * b[std::size_t(3 * k + j)];
    return c;
}

// The world's axes in the target's frame, as the columns of a rotation: x along the target's
// plane (turned by the heading), y the printed side's normal, z = x × y.
Matrix worldAxes(const ar::TargetGeometry& target, const scenario::ArSpec& placement)
{
    const double h = placement.heading * std::numbers::pi / 180, f = target.faceNormal;
    const anim::Vec3d x{std::cos(h), std::sin(h), 0}, y{0, 0, f};
    const anim::Vec3d z{x.y * y.z - x.z * y.y, x.z * y.x - x.x * y.z, x.x * y.y - x.y * y.x};
    return {x.x, y.x, z.x, x.y, y.y, z.y, x.z, y.z, z.z};
}

anim::Vec3d worldOrigin(const ar::TargetGeometry& target, const scenario::ArSpec& placement)
{
    return {target.centre[0] + placement.offset[0], target.centre[1] + placement.offset[1], target.centre[2]};
}

} // namespace

std::array<double, 3> worldToTarget(const anim::Vec3d& world, const ar::TargetGeometry& target,
                                    const scenario::ArSpec& placement)
{
    const anim::Vec3d p = times(worldAxes(target, placement), world) * placement.scale + worldOrigin(target, placement);
    return {p.x, p.y, p.z};
}

std::array<double, 9> worldToCameraRotation(const ar::TargetPose& pose, const ar::TargetGeometry& target,
                                            const scenario::ArSpec& placement)
{
    return product(ar::rotationMatrix(pose), worldAxes(target, placement));
}

CameraView arCameraView(const ar::CameraIntrinsics& camera, const ar::TargetPose& pose,
                        const ar::TargetGeometry& target, const scenario::ArSpec& placement)
{
    // camera = s · B · world + d, with B = R · A and d = R · origin + t.
    const Matrix b = worldToCameraRotation(pose, target, placement);
    const std::array<double, 3> d = ar::toCamera(pose, worldToTarget({0, 0, 0}, target, placement));
    const double s = placement.scale;
    CameraView view;
    view.eye = transposedTimes(b, {d[0], d[1], d[2]}) * (-1.0 / s);
    view.centre = view.eye + transposedTimes(b, {0, 0, 1});
    view.up = transposedTimes(b, {0, -1, 0});
    // 2 cm to 100 m of the real world, in the world's metres.
    view.zNear = 0.02 / s;
    view.zFar = 100 / s;
    view.pinhole = Pinhole{camera.fx(), camera.fy(), camera.cx(), camera.cy(), camera.width, camera.height};
    return view;
}

} // namespace thespis::core::render
