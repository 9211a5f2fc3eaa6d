#include "render/camera.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace thespis::core::render {

void Bounds::add(const anim::Vec3d& point)
{
    min = {std::min(min.x, point.x), std::min(min.y, point.y), std::min(min.z, point.z)};
    max = {std::max(max.x, point.x), std::max(max.y, point.y), std::max(max.z, point.z)};
}

void Bounds::add(const Bounds& other)
{
    if (other.empty())
        return;
    add(other.min);
    add(other.max);
}

CameraView frameBounds(const Bounds& bounds, double azimuthDegrees, double elevationDegrees, double aspect,
                       double fovYDegrees)
{
    constexpr double degree = std::numbers::pi / 180;
    CameraView view;
    view.fovYDegrees = fovYDegrees;
    if (bounds.empty())
        return view;
    const anim::Vec3d extent = bounds.max - bounds.min;
    const double radius =
        std::max(0.5 * std::sqrt(extent.x * extent.x + extent.y * extent.y + extent.z * extent.z), 1e-3);
    // The sphere fits when it fits the narrower of the two half-angles.
    const double halfY = 0.5 * fovYDegrees * degree;
    const double halfX = std::atan(std::tan(halfY) * aspect);
    const double distance = radius / std::sin(std::min(halfX, halfY));
    const double azimuth = azimuthDegrees * degree, elevation = elevationDegrees * degree;
    const anim::Vec3d direction{std::cos(elevation) * std::sin(azimuth), std::sin(elevation),
                                std::cos(elevation) * std::cos(azimuth)};
    view.centre = bounds.centre();
    view.eye = view.centre + direction * distance;
    // A generous depth range: the ground and the scene around the box stay inside it, and a
    // ratio of 2000 leaves a 24-bit depth buffer plenty of precision.
    view.zNear = 0.05 * distance;
    view.zFar = 100 * distance;
    return view;
}

osg::Matrixd viewMatrix(const CameraView& view)
{
    return osg::Matrixd::lookAt(osg::Vec3d(view.eye.x, view.eye.y, view.eye.z),
                                osg::Vec3d(view.centre.x, view.centre.y, view.centre.z),
                                osg::Vec3d(view.up.x, view.up.y, view.up.z));
}

osg::Matrixd projectionMatrix(const CameraView& view, double aspect)
{
    if (const std::optional<Pinhole>& p = view.pinhole) {
        // The image spans pixel edges −½ … width − ½; OpenCV's y runs down, GL's up.
        const double n = view.zNear;
        return osg::Matrixd::frustum((-0.5 - p->cx) / p->fx * n, (p->width - 0.5 - p->cx) / p->fx * n,
                                     -(p->height - 0.5 - p->cy) / p->fy * n, (p->cy + 0.5) / p->fy * n, n, view.zFar);
    }
    return osg::Matrixd::perspective(view.fovYDegrees, aspect, view.zNear, view.zFar);
}

PixelRect projectToPixels(std::span<const anim::Vec3> points, const CameraView& view, int width, int height)
{
    const osg::Matrixd viewProjection = viewMatrix(view) * projectionMatrix(view, double(width) / height);
    PixelRect rect{1e300, 1e300, -1e300, -1e300};
    for (const anim::Vec3& point : points) {
        const osg::Vec4d clip = osg::Vec4d(point.x, point.y, point.z, 1.0) * viewProjection;
        const double x = (clip.x() / clip.w() + 1) * 0.5 * width;
        const double y = (1 - clip.y() / clip.w()) * 0.5 * height;
        rect.left = std::min(rect.left, x);
        rect.right = std::max(rect.right, x);
        rect.top = std::min(rect.top, y);
        rect.bottom = std::max(rect.bottom, y);
    }
    return rect;
}

} // namespace thespis::core::render
