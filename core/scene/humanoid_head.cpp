#include "scene/humanoid_head.h"

#include <cmath>

namespace thespis::core::scene::humanoid {

namespace {

/// Distance from `origin` (inside the ellipsoid) along a unit direction to its surface.
double distanceToEllipsoid(const Ellipsoid& ellipsoid, Vec3d origin, Vec3d direction)
{
    const Vec3d& r = ellipsoid.radii;
    const Vec3d q{(origin.x - ellipsoid.centre.x) / r.x, (origin.y - ellipsoid.centre.y) / r.y, (origin.z - ellipsoid.centre.z) / r.z};
    const Vec3d e{direction.x / r.x, direction.y / r.y, direction.z / r.z};
    const double a = dot(e, e), b = dot(q, e), c = dot(q, q) - 1;
    return (-b + std::sqrt(b * b - a * c)) / a;
}

/// A bump in the head's radius around a direction; `width` across and `height` up and down are
/// angular spreads (radians), `amount` metres (negative: a hollow).
struct Bump {
    Vec3d direction;
    double width, height, amount;
};

} // namespace

const Vec3d kHeadCentre{0.0, 1.665, 0.02};
const Ellipsoid kCranium{{0.0, 1.685, -0.008}, {0.079, 0.108, 0.101}};

namespace {

const Ellipsoid kFace{{0.0, 1.628, 0.028}, {0.056, 0.068, 0.070}};
/// Mid-line and left-side bumps; those off the mid-line are mirrored to the right side.
const Bump kHeadBumps[] = {
    {{0.0, -0.28, 0.96}, 0.09, 0.08, 0.018},    // nose tip
    {{0.0, 0.02, 1.0}, 0.07, 0.18, 0.010},      // nose bridge
    {{0.0, 0.33, 0.94}, 0.40, 0.09, 0.004},     // brow
    {{0.34, 0.20, 0.92}, 0.12, 0.08, -0.008},   // eye socket
    {{0.50, -0.15, 0.85}, 0.18, 0.14, 0.004},   // cheek
    {{0.0, -0.60, 0.80}, 0.16, 0.07, 0.004},    // lips
    {{0.0, -0.84, 0.54}, 0.16, 0.12, 0.008},    // chin
    {{1.0, 0.05, -0.12}, 0.10, 0.17, 0.013},    // ear
};

} // namespace

double headRadius(Vec3d d)
{
    const double cranium = distanceToEllipsoid(kCranium, kHeadCentre, d);
    const double face = distanceToEllipsoid(kFace, kHeadCentre, d);
    double r = std::pow(std::pow(cranium, 10) + std::pow(face, 10), 0.1); // soft maximum
    for (const Bump& bump : kHeadBumps) {
        for (const double side : {1.0, -1.0}) {
            if (side < 0 && bump.direction.x == 0)
                continue;
            const Vec3d centre = normalized({bump.direction.x * side, bump.direction.y, bump.direction.z});
            const Vec3d delta = d - centre;
            const double across = dot(delta, delta) - delta.y * delta.y;
            r += bump.amount * std::exp(-0.5 * (across / (bump.width * bump.width) + delta.y * delta.y / (bump.height * bump.height)));
        }
    }
    return r;
}

Vec3d headPoint(Vec3d direction) { return kHeadCentre + direction * headRadius(direction); }

SurfacePoint headSurface(Vec3d direction, double lift)
{
    // Normal from two small steps across the surface, which works at the poles too.
    const Vec3d helper = std::abs(direction.y) < 0.9 ? Vec3d{0, 1, 0} : Vec3d{1, 0, 0};
    const Vec3d e1 = normalized(cross(direction, helper));
    const Vec3d e2 = cross(direction, e1);
    constexpr double step = 1e-5;
    const Vec3d d1 = headPoint(normalized(direction + e1 * step)) - headPoint(normalized(direction - e1 * step));
    const Vec3d d2 = headPoint(normalized(direction + e2 * step)) - headPoint(normalized(direction - e2 * step));
    Vec3d normal = normalized(cross(d1, d2));
    if (dot(normal, direction) < 0)
        normal = normal * -1.0;
    return {headPoint(direction) + normal * lift, normal};
}

Vec3d sphereDirection(double polar, double angle, double pole)
{
    return {std::sin(polar) * std::sin(angle), pole * std::cos(polar), std::sin(polar) * std::cos(angle)};
}

double hairOuter(double t) { return 0.0045 + 0.0045 * (1 - t * t); }
double hairline(double angle) { return std::acos(0.045 + 0.62 * std::cos(angle) - 0.045 * std::cos(2 * angle)); }

} // namespace thespis::core::scene::humanoid
