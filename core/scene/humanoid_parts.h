#pragma once
// Private to the default humanoid (default_humanoid.cpp): its modelling toolkit — vector helpers,
// pieces (surfaces bound to one segment, built in the rest pose) and sweeps (generalised
// cylinders along keys placed on the rest H-Anim skeleton).

#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <span>
#include <string_view>
#include <vector>

#include "anim/hanim.h"
#include "anim/quat.h"

namespace thespis::core::scene::humanoid {

using anim::Vec3d;
namespace hanim = anim::hanim;

// ---------------------------------------------------------------------------------------------
// Small vector helpers (double precision while modelling; the mesh stores floats).

using anim::dot;
inline Vec3d cross(Vec3d a, Vec3d b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }
inline Vec3d normalized(Vec3d v)
{
    const double length = std::sqrt(dot(v, v));
    return length > 0 ? v * (1 / length) : v;
}
inline Vec3d lerp(Vec3d a, Vec3d b, double t) { return a + (b - a) * t; }
inline double smoothstep(double x)
{
    x = std::clamp(x, 0.0, 1.0);
    return x * x * (3 - 2 * x);
}

constexpr double kPi = std::numbers::pi;
/// Target edge length of the tessellation at detail 1, metres (gives about 20k triangles).
constexpr double kSpacing = 0.02;
/// The face needs a finer tessellation than the body to show its features.
constexpr double kHeadSpacingScale = 0.65;
/// Half-width of the band over which the skin blends between two joints, metres (narrower where
/// the bones are short: at most 40 % of the shorter neighbouring band).
constexpr double kBlendHalfWidth = 0.035;

// ---------------------------------------------------------------------------------------------
// Pieces: surfaces bound to one segment, built in the rest pose.

/// Skin influences per vertex (Skin::influences). A vertex blends at most two joints, the ones on
/// either side of the nearest joint; unused slots have weight 0.
constexpr int kInfluences = 4;

struct Influences {
    std::array<int, kInfluences> joints{};
    std::array<float, kInfluences> weights{};
};

inline Influences rigid(int joint) { return {{joint, 0, 0, 0}, {1.0f, 0, 0, 0}}; }

struct SurfacePoint {
    Vec3d position;
    Vec3d normal; ///< unit, outward
};

/// What a vertex of the face is, for its rig (humanoid_face.h); None off the face.
enum class FacePart : std::uint8_t {
    None,
    Skin,       ///< the head's skin (side: above or below the mouth's opening)
    LipRoll,    ///< the lips' inner surface, turning into the mouth
    Eyelid,     ///< side: upper or lower; eye: which
    Eyelash,
    Eyeball,    ///< sclera and iris
    Pupil,
    UpperTeeth,
    LowerTeeth,
    Tongue,
    Mouth       ///< the inside of the mouth
};

struct FaceTag {
    FacePart part = FacePart::None;
    std::int8_t side = 0; ///< +1 above the mouth's opening (or an upper lid), −1 below
    std::int8_t eye = 0;  ///< +1 the left eye (+x), −1 the right
    std::int16_t slit = -1; ///< the mouth's edge: its column along the opening (pairs upper and lower)
};

/// A surface of the body that belongs to one segment; its triangles index its own vertices.
struct Piece {
    int joint = 0; ///< skeleton joint of the segment
    bool hair = false;
    std::string_view segment; ///< a segment of its own (the face's parts), or "" for the joint's
    int material = -1;        ///< the segment's material when it has its own, else by joint
    std::vector<Vec3d> positions;
    std::vector<Vec3d> normals;
    std::vector<Influences> influences;
    std::vector<std::uint32_t> triangles;
    std::vector<FaceTag> face; ///< per vertex, or empty (no face part)
};

/// Appends to `piece` a grid of rings of `around` vertices at parameters `rings` (the angle runs
/// over [0, 2π) around each ring); a tip ring is a single vertex (a pole). `pointAt(u, angle)`
/// gives each vertex; the surface faces outward where cross(∂/∂angle, ∂/∂u) points out, and
/// `flip` reverses the winding for surfaces parameterised the other way. Triangles are
/// counter-clockwise seen from outside.
template <class PointAt, class InfluencesAt>
void addRings(Piece& piece, std::span<const double> rings, int around, bool startTip, bool endTip, bool flip,
              const PointAt& pointAt, const InfluencesAt& influencesAt)
{
    std::vector<std::uint32_t> ringStart;
    for (std::size_t i = 0; i < rings.size(); ++i) {
        ringStart.push_back(std::uint32_t(piece.positions.size()));
        const bool tip = (i == 0 && startTip) || (i + 1 == rings.size() && endTip);
        const Influences influences = influencesAt(rings[i]);
        for (int k = 0; k < (tip ? 1 : around); ++k) {
            const SurfacePoint point = pointAt(rings[i], 2 * kPi * k / around);
            piece.positions.push_back(point.position);
            piece.normals.push_back(point.normal);
            piece.influences.push_back(influences);
        }
    }
    auto vertex = [&](std::size_t ring, int k) {
        const bool tip = (ring == 0 && startTip) || (ring + 1 == rings.size() && endTip);
        return ringStart[ring] + (tip ? 0 : std::uint32_t(k % around));
    };
    auto triangle = [&](std::uint32_t a, std::uint32_t b, std::uint32_t c) {
        piece.triangles.insert(piece.triangles.end(), {a, flip ? c : b, flip ? b : c});
    };
    for (std::size_t i = 0; i + 1 < rings.size(); ++i) {
        for (int k = 0; k < around; ++k) {
            const std::uint32_t a = vertex(i, k), b = vertex(i, k + 1), c = vertex(i + 1, k + 1), d = vertex(i + 1, k);
            if (a != b)
                triangle(a, b, c);
            if (c != d)
                triangle(a, c, d);
        }
    }
}

/// `count` + 1 parameters evenly spaced from `from` to `to`, both ends exact (so that a ring
/// shared by two neighbouring pieces is computed from the same parameter).
inline std::vector<double> evenRings(double from, double to, int count)
{
    std::vector<double> rings;
    for (int i = 0; i <= count; ++i)
        rings.push_back(i == count ? to : from + (to - from) * i / count);
    return rings;
}

inline int stepsFor(double length, double spacing) { return std::max(1, int(std::ceil(length / spacing - 1e-9))); }
/// Vertices around a ring of this perimeter: a multiple of 4 so that sections stay symmetric.
inline int aroundFor(double perimeter, double spacing, int minimum)
{
    return std::max(minimum, 4 * int(std::lround(perimeter / spacing / 4)));
}

// ---------------------------------------------------------------------------------------------
// Sweeps: generalised cylinders along a centre line through keys placed on the rest skeleton,
// with superelliptic sections and rounded (half-ellipsoid) ends.

/// A cross-section around the centre line: half-widths to the side and to the front and back (in
/// the sweep's frame, see SweepSpec), and a superellipse exponent (2: an ellipse; more: boxier).
struct Section {
    double side, front, back, squareness;
};

/// A key of a sweep: its centre lies `along` the way from joint `from` to joint `to` (beyond 0…1
/// it extrapolates; no `to` means at `from`), moved by `offset`. When `joint` is set, that
/// joint's segment starts at this key.
struct SweepKey {
    std::string_view from;
    std::string_view to;
    double along = 0;
    Vec3d offset;
    Section section;
    std::string_view joint = {};
};

/// A swept body part. The section's front points along `front` made perpendicular to the
/// centre line, its side along tangent × front. The part before the first key with a joint
/// belongs to that joint's segment; the skin there blends into `parent` (the body part it hangs
/// from) across the first joint.
struct SweepSpec {
    std::span<const SweepKey> keys;
    Vec3d front;
    double startCap = 0; ///< length of the rounded end before the first key
    double endCap = 0;   ///< … and after the last key
    std::string_view parent = {};
};

/// World rest positions of every LOA 2 joint.
inline Vec3d restPosition(std::string_view joint)
{
    static const std::vector<Vec3d> positions = [] {
        const anim::Skeleton& loa2 = hanim::skeleton(hanim::Level::Loa2);
        return loa2.worldPositions(loa2.restFrame());
    }();
    const int index = hanim::skeleton(hanim::Level::Loa2).find(joint);
    assert(index >= 0);
    return positions[std::size_t(index)];
}

inline double meanRadius(const Section& s) { return (s.side + (s.front + s.back) / 2) / 2; }

class Sweep {
public:
    explicit Sweep(const SweepSpec& spec) : m_front(spec.front), m_startCap(spec.startCap), m_endCap(spec.endCap)
    {
        assert(spec.keys.size() >= 2);
        for (const SweepKey& key : spec.keys) {
            const Vec3d from = restPosition(key.from);
            const Vec3d centre = (key.to.empty() ? from : lerp(from, restPosition(key.to), key.along)) + key.offset;
            const Section& s = key.section;
            m_values.push_back({centre.x, centre.y, centre.z, s.side, s.front, s.back, s.squareness});
            const Values& previous = m_values.size() > 1 ? m_values[m_values.size() - 2] : m_values.back();
            const double chord = std::hypot(centre.x - previous[0], centre.y - previous[1], centre.z - previous[2]);
            m_knots.push_back(m_knots.empty() ? 0.0 : m_knots.back() + chord);
        }
        // Hermite slopes: the derivative of the parabola through each key and its neighbours
        // (one-sided at the ends), which follows unevenly spaced keys without overshooting much.
        const std::size_t n = m_values.size();
        for (std::size_t k = 0; k < n; ++k) {
            Values slope{};
            for (std::size_t c = 0; c < slope.size(); ++c) {
                if (k == 0 || k + 1 == n) {
                    const std::size_t a = k == 0 ? 0 : k - 1;
                    slope[c] = (m_values[a + 1][c] - m_values[a][c]) / (m_knots[a + 1] - m_knots[a]);
                } else {
                    const double h0 = m_knots[k] - m_knots[k - 1], h1 = m_knots[k + 1] - m_knots[k];
                    const double d0 = (m_values[k][c] - m_values[k - 1][c]) / h0;
                    const double d1 = (m_values[k + 1][c] - m_values[k][c]) / h1;
                    slope[c] = (d0 * h1 + d1 * h0) / (h0 + h1);
                }
            }
            m_slopes.push_back(slope);
        }
        // Rounded ends: their parameter runs over about their arc length (a quarter ellipse).
        m_startCapArc = kPi / 4 * (m_startCap + meanRadius(sliceAt(0).section));
        m_endCapArc = kPi / 4 * (m_endCap + meanRadius(sliceAt(m_knots.back()).section));
    }

    /// The parameter runs about along the arc length: from the tip of the start cap (negative)
    /// through the keys (key k at knot(k)) to the tip of the end cap.
    double startParameter() const { return -m_startCapArc; }
    double endParameter() const { return m_knots.back() + m_endCapArc; }
    double knot(std::size_t key) const { return m_knots[key]; }
    double largestPerimeter() const
    {
        double largest = 0;
        for (const Values& v : m_values)
            largest = std::max(largest, 2 * kPi * std::sqrt((v[3] * v[3] + std::pow((v[4] + v[5]) / 2, 2)) / 2));
        return largest;
    }

    SurfacePoint pointAt(double u, double angle) const
    {
        if (u <= startParameter())
            return {positionAt(u, 0), sliceAt(0).tangent * -1.0};
        if (u >= endParameter())
            return {positionAt(u, 0), sliceAt(m_knots.back()).tangent};
        constexpr double du = 1e-5, dAngle = 1e-5;
        const Vec3d alongU = positionAt(u + du, angle) - positionAt(u - du, angle);
        const Vec3d alongAngle = positionAt(u, angle + dAngle) - positionAt(u, angle - dAngle);
        return {positionAt(u, angle), normalized(cross(alongAngle, alongU))};
    }

private:
    using Values = std::array<double, 7>; // centre x y z, side, front, back, squareness

    struct Slice {
        Vec3d centre;
        Vec3d tangent;
        Section section;
    };

    Slice sliceAt(double u) const
    {
        if (u < 0 || u > m_knots.back()) {
            // Half-ellipsoid cap: the centre moves on along the end tangent while the section shrinks.
            const bool start = u < 0;
            const Slice end = sliceAt(start ? 0 : m_knots.back());
            const double phi = std::min(1.0, start ? -u / m_startCapArc : (u - m_knots.back()) / m_endCapArc) * kPi / 2;
            const double scale = std::cos(phi);
            const double direction = start ? -1 : 1;
            return {end.centre + end.tangent * (direction * (start ? m_startCap : m_endCap) * std::sin(phi)), end.tangent,
                    {end.section.side * scale, end.section.front * scale, end.section.back * scale,
                     end.section.squareness}};
        }
        const std::size_t k = std::min<std::size_t>(
            std::size_t(std::upper_bound(m_knots.begin(), m_knots.end(), u) - m_knots.begin()) - 1, m_knots.size() - 2);
        const double h = m_knots[k + 1] - m_knots[k];
        const double s = (u - m_knots[k]) / h;
        const double s2 = s * s, s3 = s2 * s;
        const double h00 = 2 * s3 - 3 * s2 + 1, h10 = s3 - 2 * s2 + s, h01 = -2 * s3 + 3 * s2, h11 = s3 - s2;
        const double d00 = 6 * s2 - 6 * s, d10 = 3 * s2 - 4 * s + 1, d01 = -6 * s2 + 6 * s, d11 = 3 * s2 - 2 * s;
        Values v{}, dv{};
        for (std::size_t c = 0; c < v.size(); ++c) {
            const double p0 = m_values[k][c], p1 = m_values[k + 1][c];
            const double m0 = m_slopes[k][c] * h, m1 = m_slopes[k + 1][c] * h;
            v[c] = h00 * p0 + h10 * m0 + h01 * p1 + h11 * m1;
            dv[c] = (d00 * p0 + d10 * m0 + d01 * p1 + d11 * m1) / h;
        }
        return {{v[0], v[1], v[2]}, normalized(Vec3d{dv[0], dv[1], dv[2]}), {v[3], v[4], v[5], v[6]}};
    }

    Vec3d positionAt(double u, double angle) const
    {
        const Slice slice = sliceAt(u);
        const Vec3d front = normalized(m_front - slice.tangent * dot(m_front, slice.tangent));
        const Vec3d side = cross(slice.tangent, front);
        // Superellipse: |x/side|^p + |z/depth|^p = 1, with a different depth to the front and back.
        const double exponent = 2 / slice.section.squareness;
        const double c = std::cos(angle), s = std::sin(angle);
        const double x = slice.section.side * std::copysign(std::pow(std::abs(s), exponent), s);
        const double z = (c >= 0 ? slice.section.front : slice.section.back) * std::copysign(std::pow(std::abs(c), exponent), c);
        return slice.centre + side * x + front * z;
    }

    Vec3d m_front;
    double m_startCap, m_endCap;
    double m_startCapArc = 0, m_endCapArc = 0;
    std::vector<Values> m_values, m_slopes;
    std::vector<double> m_knots;
};

} // namespace thespis::core::scene::humanoid
