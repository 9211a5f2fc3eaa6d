#pragma once
// A perspective camera as plain values (eye, centre, up, vertical field of view, depth range), the
// matrices OSG draws with, framing a bounding box, and projecting points to pixels — so that the
// CLI, the studio viewport and the picture tests agree on where things land.

#include <optional>
#include <span>

#include <osg/Matrixd>

#include "anim/quat.h"

namespace thespis::core::render {

/// Axis-aligned box in world space; empty until a point is added.
struct Bounds {
    anim::Vec3d min{1e300, 1e300, 1e300};
    anim::Vec3d max{-1e300, -1e300, -1e300};
    bool empty() const { return min.x > max.x; }
    void add(const anim::Vec3d& point);
    void add(const Bounds& other);
    anim::Vec3d centre() const { return (min + max) * 0.5; }
};

/// A real camera's projection (OpenCV's intrinsics, pixel centres at whole numbers): for drawing
/// over its video, where the view is off-centre and fx and fy may differ.
struct Pinhole {
    double fx = 0, fy = 0, cx = 0, cy = 0;
    int width = 0, height = 0;
    bool operator==(const Pinhole&) const = default;
};

struct CameraView {
    anim::Vec3d eye{0, 1, 4};
    anim::Vec3d centre{0, 1, 0};
    anim::Vec3d up{0, 1, 0};
    double fovYDegrees = 30;
    double zNear = 0.1;
    double zFar = 100;
    /// When set, the projection is this camera's (fovYDegrees and the aspect are not used).
    std::optional<Pinhole> pinhole;
};

/// A camera looking at the box's centre from `azimuthDegrees` about +y (0: from +z, in front of a
/// character facing +z; 90: from +x, its left) and `elevationDegrees` above the horizon, just far
/// enough for the box's bounding sphere to fit the view at this aspect ratio (width / height).
CameraView frameBounds(const Bounds& bounds, double azimuthDegrees, double elevationDegrees, double aspect,
                       double fovYDegrees = 30);

osg::Matrixd viewMatrix(const CameraView& view);
osg::Matrixd projectionMatrix(const CameraView& view, double aspect);

/// A rectangle in pixels, x to the right and y down from the top-left corner of the image.
struct PixelRect {
    double left = 0, top = 0, right = 0, bottom = 0;
};

/// The smallest rectangle holding the projections of the points (all in front of the camera)
/// into an image of width × height pixels.
PixelRect projectToPixels(std::span<const anim::Vec3> points, const CameraView& view, int width, int height);

} // namespace thespis::core::render
