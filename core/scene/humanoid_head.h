#pragma once
// Private to the default humanoid: the head's surface. A soft union of two ellipsoids (cranium,
// face and jaw) shaped by smooth bumps (nose, chin, brow, ears …), star-shaped around
// kHeadCentre, so a surface point is kHeadCentre + radius(direction)·direction. The hair follows
// this skull; the face (humanoid_face.h) adds its lips and sockets on top.

#include "scene/humanoid_parts.h"

namespace thespis::core::scene::humanoid {

struct Ellipsoid {
    Vec3d centre, radii;
};

extern const Vec3d kHeadCentre;
extern const Ellipsoid kCranium;

/// Distance from kHeadCentre along a unit direction to the skull's surface.
double headRadius(Vec3d direction);
Vec3d headPoint(Vec3d direction);
/// The skull's point along `direction`, lifted `lift` metres along its normal, with that normal.
SurfacePoint headSurface(Vec3d direction, double lift);
/// Direction at polar angle `polar` from `pole` (±Y) and azimuth `angle` from +Z towards +X.
Vec3d sphereDirection(double polar, double angle, double pole);

// Hair: a shell 3 to 9 mm above the skull (thinning towards its edge) over the top and back of
// the head, down to a hairline at the forehead, above the ears and at the nape.
constexpr double kHairInner = 0.003;
/// Outer surface height above the skull at the crown (t = 0) tapering to the hairline (t = 1).
double hairOuter(double t);
/// Polar angle (from the crown) of the hairline at an azimuth (0 = forehead, π = nape).
double hairline(double angle);

} // namespace thespis::core::scene::humanoid
