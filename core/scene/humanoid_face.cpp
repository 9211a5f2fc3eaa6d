#include "scene/humanoid_face.h"

#include <algorithm>
#include <cmath>

#include "scene/humanoid_face_layout.h"
#include "scene/humanoid_head.h"

namespace thespis::core::scene::humanoid {

namespace {

using namespace face;

double gauss(double x, double sigma) { return std::exp(-0.5 * x * x / (sigma * sigma)); }
double flatTop(double x, double width) { return std::exp(-std::pow(std::abs(x) / width, 4)); }

// The lips on the skull: an upper and a lower bulge with a shallow groove where they meet.
double lipsRelief(Vec3d p)
{
    if (p.z < 0.05)
        return 0;
    const double upper = 0.0016 * flatTop(p.x, 0.021) * gauss(p.y - (kMouthY + 0.0042), 0.0036);
    const double lower = 0.0022 * flatTop(p.x, 0.019) * gauss(p.y - (kMouthY - 0.0050), 0.0042);
    const double groove = -0.0010 * flatTop(p.x, 0.026) * gauss(p.y - mouthLineY(p.x), 0.0012);
    return upper + lower + groove;
}

// The eyes' sockets: the skin sinks behind the eyeball, so that the lids (humanoid_face_layout.h)
// and not the skin frame the eye's opening.
double socketRelief(Vec3d p)
{
    double depth = 0;
    for (const int eye : {1, -1}) {
        const Vec3d e = eyeCentre(eye);
        const double rho2 = std::pow((p.x - e.x) / 0.0175, 2) + std::pow((p.y - e.y) / 0.0135, 2);
        if (rho2 < 1 && p.z > 0.05)
            depth += 0.0065 * (1 - rho2) * (1 - rho2);
    }
    return -depth;
}

Vec3d skinPoint(Vec3d direction)
{
    const Vec3d base = headPoint(direction);
    return kHeadCentre + direction * (headRadius(direction) + lipsRelief(base) + socketRelief(base));
}

// Azimuth from +z towards +x and polar angle from −y (as sphereDirection with pole −1).
Vec3d skinAt(double polar, double azimuth) { return skinPoint(sphereDirection(polar, azimuth, -1)); }

// Samples from `from` to `to` (from < to) at about `step`, with `through` among them.
std::vector<double> samplesThrough(double from, double to, double step, double through)
{
    const int before = std::max(1, int(std::lround((through - from) / step)));
    const int after = std::max(1, int(std::lround((to - through) / step)));
    std::vector<double> out;
    for (int i = 0; i < before; ++i)
        out.push_back(from + (through - from) * i / before);
    for (int i = 0; i <= after; ++i)
        out.push_back(through + (to - through) * i / after);
    return out;
}

// `count` steps over [from, to), the end left out.
void appendEven(std::vector<double>& out, double from, double to, int count)
{
    for (int i = 0; i < count; ++i)
        out.push_back(from + (to - from) * i / count);
}

// The polar angle at which the skin along `azimuth` reaches height y (bisection near `guess`).
double polarAtHeight(double azimuth, double y, double guess)
{
    double lo = guess - 0.35, hi = guess + 0.35; // height grows with the polar angle here
    for (int i = 0; i < 60; ++i) {
        const double mid = 0.5 * (lo + hi);
        (skinAt(mid, azimuth).y < y ? lo : hi) = mid;
    }
    return 0.5 * (lo + hi);
}

// Adds a triangle facing `outward` (its winding chosen so).
void addFacing(Piece& piece, std::uint32_t a, std::uint32_t b, std::uint32_t c, Vec3d outward)
{
    const Vec3d n = cross(piece.positions[b] - piece.positions[a], piece.positions[c] - piece.positions[a]);
    if (dot(n, outward) >= 0)
        piece.triangles.insert(piece.triangles.end(), {a, b, c});
    else
        piece.triangles.insert(piece.triangles.end(), {a, c, b});
}

std::uint32_t addVertex(Piece& piece, Vec3d position, FaceTag tag)
{
    piece.positions.push_back(position);
    piece.normals.push_back({});
    piece.face.push_back(tag);
    return std::uint32_t(piece.positions.size() - 1);
}

// Winds every triangle to face away from `centre` (towards it with `inside`).
void faceAwayFrom(Piece& piece, Vec3d centre, bool inside = false)
{
    std::vector<std::uint32_t> triangles;
    triangles.swap(piece.triangles);
    for (std::size_t t = 0; t < triangles.size(); t += 3) {
        const std::uint32_t a = triangles[t], b = triangles[t + 1], c = triangles[t + 2];
        const Vec3d centroid = (piece.positions[a] + piece.positions[b] + piece.positions[c]) * (1.0 / 3);
        addFacing(piece, a, b, c, (centroid - centre) * (inside ? -1.0 : 1.0));
    }
}

// Smooth normals from the triangles (area-weighted).
void computeNormals(Piece& piece)
{
    std::vector<Vec3d> sum(piece.positions.size());
    for (std::size_t t = 0; t < piece.triangles.size(); t += 3) {
        const std::uint32_t a = piece.triangles[t], b = piece.triangles[t + 1], c = piece.triangles[t + 2];
        const Vec3d n = cross(piece.positions[b] - piece.positions[a], piece.positions[c] - piece.positions[a]);
        for (const std::uint32_t v : {a, b, c})
            sum[v] = sum[v] + n;
    }
    for (std::size_t v = 0; v < sum.size(); ++v)
        piece.normals[v] = normalized(sum[v]);
}

Piece startPiece(int joint, std::string_view segment, int material)
{
    Piece piece;
    piece.joint = joint;
    piece.segment = segment;
    piece.material = material;
    return piece;
}

void finish(Piece& piece, std::vector<Piece>& pieces)
{
    computeNormals(piece);
    piece.influences.assign(piece.positions.size(), rigid(piece.joint));
    pieces.push_back(std::move(piece));
}

// ---------------------------------------------------------------------------------------------
// The skin: a grid over azimuth and polar angle, fine over the face, with the mouth's opening
// along one row between the corners (that row's vertices doubled: the upper lip's and the
// lower's), and each lip's edge turning into the mouth.

void addSkin(int joint, double spacing, const FaceMaterials& materials, std::vector<Piece>& pieces)
{
    Piece skin = startPiece(joint, "", materials.face);
    const double fine = std::clamp(spacing * 0.16, 0.0016, 0.010), coarse = spacing * kHeadSpacingScale;
    const double frontRadius = 0.09;
    const double middlePolar = polarAtHeight(0, kMouthY, 1.1);
    const double cornerAzimuth = [&] { // the azimuth whose skin is at the mouth's corner
        double lo = 0, hi = 0.8;
        for (int i = 0; i < 50; ++i) {
            const double mid = 0.5 * (lo + hi);
            (skinAt(polarAtHeight(mid, mouthLineY(kMouthCorner), middlePolar), mid).x < kMouthCorner ? lo : hi) = mid;
        }
        return 0.5 * (lo + hi);
    }();

    // Columns: fine over ±0.9 rad with the corners among them, coarse round the back.
    constexpr double FaceAzimuth = 0.78;
    std::vector<double> azimuths;
    const double fineAzimuth = fine / frontRadius;
    const int toCorner = std::max(2, int(std::lround(cornerAzimuth / fineAzimuth)));
    const int toEdge = std::max(1, int(std::lround((FaceAzimuth - cornerAzimuth) / fineAzimuth)));
    const int back = std::max(4, int(std::lround((2 * kPi - 2 * FaceAzimuth) * frontRadius / coarse)));
    appendEven(azimuths, -FaceAzimuth, -cornerAzimuth, toEdge);
    appendEven(azimuths, -cornerAzimuth, cornerAzimuth, 2 * toCorner);
    appendEven(azimuths, cornerAzimuth, FaceAzimuth, toEdge);
    appendEven(azimuths, FaceAzimuth, 2 * kPi - FaceAzimuth, back);
    const int columns = int(azimuths.size());
    const int leftCorner = toEdge + 2 * toCorner, rightCorner = toEdge; // columns of the corners (+x, −x)

    // Rows: from the chin's pole up, fine from below the chin to above the brows.
    constexpr double FaceLow = 0.42, FaceHigh = 2.15;
    std::vector<double> polars;
    const double finePolar = fine / frontRadius;
    appendEven(polars, 0, FaceLow, std::max(2, int(std::lround(FaceLow * frontRadius / coarse))));
    const std::vector<double> face = samplesThrough(FaceLow, FaceHigh, finePolar, middlePolar);
    polars.insert(polars.end(), face.begin(), face.end() - 1);
    appendEven(polars, FaceHigh, kPi, std::max(3, int(std::lround((kPi - FaceHigh) * 0.1 / coarse))));
    polars.push_back(kPi);
    const int rows = int(polars.size());
    const int mouthRow = int(std::find(polars.begin(), polars.end(), middlePolar) - polars.begin());

    // Each column's rows near the mouth bend so that the mouth row follows the mouth line.
    std::vector<double> bend(std::size_t(columns), 0.0);
    for (int c = 0; c < columns; ++c) {
        const double a = azimuths[std::size_t(c)];
        const double clamped = std::clamp(a, -cornerAzimuth, cornerAzimuth);
        double polar = polarAtHeight(clamped, kMouthY, middlePolar);
        polar = polarAtHeight(clamped, mouthLineY(skinAt(polar, clamped).x), middlePolar);
        const double fade = std::abs(a) <= cornerAzimuth ? 1.0 : std::max(0.0, 1 - (std::abs(a) - cornerAzimuth) / 0.35);
        bend[std::size_t(c)] = (polar - middlePolar) * smoothstep(fade);
    }
    constexpr int BendRows = 5;

    std::vector<std::uint32_t> grid(std::size_t(rows * columns));
    const auto at = [&](int r, int c) -> std::uint32_t& { return grid[std::size_t(r * columns + ((c % columns) + columns) % columns)]; };
    std::vector<std::uint32_t> lowerEdge(std::size_t(columns), 0); // the lower lip's copy of the mouth row
    const auto isOpening = [&](int c) { return c > rightCorner && c < leftCorner; };
    for (int r = 0; r < rows; ++r) {
        const bool pole = r == 0 || r == rows - 1;
        for (int c = 0; c < (pole ? 1 : columns); ++c) {
            const double nearMouth = std::max(0.0, 1 - std::abs(r - mouthRow) / double(BendRows));
            const double polar = polars[std::size_t(r)] + bend[std::size_t(c)] * nearMouth;
            const Vec3d p = pole ? skinAt(polars[std::size_t(r)], 0) : skinAt(polar, azimuths[std::size_t(c)]);
            FaceTag tag{FacePart::Skin, std::int8_t(r >= mouthRow ? 1 : -1), 0, -1};
            if (r == mouthRow && isOpening(c))
                tag.slit = std::int16_t(c);
            at(r, c) = addVertex(skin, p, tag);
            if (r == mouthRow && isOpening(c)) {
                tag.side = -1;
                lowerEdge[std::size_t(c)] = addVertex(skin, p, tag);
            }
        }
        if (pole)
            for (int c = 1; c < columns; ++c)
                at(r, c) = at(r, 0);
    }
    for (int r = 0; r + 1 < rows; ++r)
        for (int c = 0; c < columns; ++c) {
            std::uint32_t a = at(r, c), b = at(r, c + 1), d = at(r + 1, c + 1), e = at(r + 1, c);
            if (r + 1 == mouthRow) { // below the opening: the lower lip's copies
                if (isOpening(c))
                    e = lowerEdge[std::size_t(c)];
                if (isOpening(c + 1))
                    d = lowerEdge[std::size_t(c + 1)];
            }
            const Vec3d out = (skin.positions[a] + skin.positions[d]) * 0.5 - kHeadCentre;
            if (a != b)
                addFacing(skin, a, b, d, out);
            if (d != e)
                addFacing(skin, a, d, e, out);
        }

    // The lips' edges turn into the mouth: rows from each edge inwards (upwards for the upper
    // lip, downwards for the lower), thinning to nothing at the corners.
    for (const int side : {1, -1}) {
        std::vector<std::vector<std::uint32_t>> roll(std::size_t(kLipRollRows + 1), std::vector<std::uint32_t>(std::size_t(columns)));
        for (int c = rightCorner; c <= leftCorner; ++c) {
            const std::uint32_t edge = isOpening(c) ? (side > 0 ? at(mouthRow, c) : lowerEdge[std::size_t(c)]) : at(mouthRow, c);
            roll[0][std::size_t(c)] = edge;
            for (int k = 1; k <= kLipRollRows; ++k) {
                if (!isOpening(c)) {
                    roll[std::size_t(k)][std::size_t(c)] = edge;
                    continue;
                }
                const Vec3d p = skin.positions[edge];
                const double t = double(k) / kLipRollRows, taper = std::sqrt(std::max(0.0, 1 - std::pow(p.x / kMouthCorner, 2)));
                const Vec3d inward = normalized(Vec3d{0, 0, kMouthCentre.z} - Vec3d{0, 0, p.z});
                const Vec3d q = p + inward * (kLipRollDepth * t * taper) + Vec3d{0, (side > 0 ? 0.0030 : -0.0045) * t * t * taper, 0};
                roll[std::size_t(k)][std::size_t(c)] =
                    addVertex(skin, q, FaceTag{FacePart::LipRoll, std::int8_t(side), 0, -1});
            }
        }
        const Vec3d facing{0, -side * 1.0, 0.3};
        for (int k = 0; k < kLipRollRows; ++k)
            for (int c = rightCorner; c < leftCorner; ++c) {
                const std::uint32_t a = roll[std::size_t(k)][std::size_t(c)], b = roll[std::size_t(k)][std::size_t(c + 1)];
                const std::uint32_t d = roll[std::size_t(k + 1)][std::size_t(c + 1)], e = roll[std::size_t(k + 1)][std::size_t(c)];
                if (a != d && b != d)
                    addFacing(skin, a, b, d, facing);
                if (a != e && d != e)
                    addFacing(skin, a, d, e, facing);
            }
    }
    finish(skin, pieces);
}

// ---------------------------------------------------------------------------------------------
// Eyes: the eyeball (sclera), the iris and pupil as caps in front of it, the lids as shells over
// it, the lashes along the upper lid.

// A cap of the eye (polar 0 … angle from its axis) at `radius`, or the whole ball (angle π).
void addEyeCap(int joint, int eye, std::string_view segment, int material, double radius, double angle, FacePart part,
               double spacing, std::vector<Piece>& pieces)
{
    Piece cap = startPiece(joint, segment, material);
    const Vec3d centre = eyeCentre(eye);
    const bool ball = angle >= kPi - 1e-9;
    const int around = std::max(16, aroundFor(2 * kPi * radius * std::sin(std::min(angle, kPi / 2)), spacing, 16));
    const std::vector<double> rings = evenRings(0, angle, std::max(3, stepsFor(radius * angle, spacing)));
    addRings(cap, rings, around, true, ball, false,
             [&](double polar, double a) {
                 const Vec3d d{eye * std::sin(polar) * std::cos(a), std::sin(polar) * std::sin(a), std::cos(polar)};
                 return SurfacePoint{centre + d * radius, d};
             },
             [&](double) { return rigid(joint); });
    faceAwayFrom(cap, centre);
    cap.face.assign(cap.positions.size(), FaceTag{part, 0, std::int8_t(eye), -1});
    finish(cap, pieces);
}

// The margin of a lid: its angle above (upper) or below (lower) the axis at `out`, zero at the
// corners and beyond.
double lidMargin(int side, double out)
{
    const double corner = out > 0 ? kOuterCorner : kInnerCorner;
    if (std::abs(out) >= corner)
        return 0;
    const double shape = std::pow(std::cos(0.5 * kPi * out / corner), 0.8);
    return (side > 0 ? kUpperMargin : kLowerMargin) * shape;
}

void addLid(int joint, int eye, int side, double spacing, const FaceMaterials& materials, std::vector<Piece>& pieces)
{
    Piece lid = startPiece(joint, eye > 0 ? "l_eyelid" : "r_eyelid", materials.skin);
    const double radius = side > 0 ? kUpperLidRadius : kLowerLidRadius;
    const int across = std::max(12, stepsFor(2 * kLidReach * radius, spacing));
    const int down = std::max(5, stepsFor(kLidTop * radius, spacing));
    const FaceTag tag{FacePart::Eyelid, std::int8_t(side), std::int8_t(eye), -1};
    // Row 0 is the margin's inner edge (just over the eyeball), row 1 the margin, then up to the top.
    std::vector<std::vector<std::uint32_t>> grid(std::size_t(down + 2));
    for (int i = 0; i <= across; ++i) {
        const double out = -kLidReach + 2 * kLidReach * i / across;
        const double margin = lidMargin(side, out);
        grid[0].push_back(addVertex(lid, onEye(eye, kEyeballRadius + 0.0003, side * (margin - 0.02), out), tag));
        for (int j = 0; j <= down; ++j) {
            const double up = margin + (kLidTop - margin) * j / down;
            grid[std::size_t(j + 1)].push_back(addVertex(lid, onEye(eye, radius, side * up, out), tag));
        }
    }
    const Vec3d centre = eyeCentre(eye);
    for (std::size_t j = 0; j + 1 < grid.size(); ++j)
        for (int i = 0; i < across; ++i) {
            const std::uint32_t a = grid[j][std::size_t(i)], b = grid[j][std::size_t(i + 1)];
            const std::uint32_t d = grid[j + 1][std::size_t(i + 1)], e = grid[j + 1][std::size_t(i)];
            // The rim faces the opening; the shell faces away from the eye.
            const Vec3d out = j == 0 ? Vec3d{0, -side * 1.0, 0.5} : (lid.positions[a] - centre);
            addFacing(lid, a, b, d, out);
            addFacing(lid, a, d, e, out);
        }
    finish(lid, pieces);

    if (side < 0)
        return;
    // The upper lashes: a short strip from the margin, out and up, densest in the middle.
    Piece lashes = startPiece(joint, eye > 0 ? "l_eyelash" : "r_eyelash", materials.hair);
    const FaceTag lashTag{FacePart::Eyelash, 1, std::int8_t(eye), -1};
    std::vector<std::uint32_t> base, tip;
    for (int i = 0; i <= across; ++i) {
        const double out = -kInnerCorner * 0.92 + (kInnerCorner + kOuterCorner) * 0.92 * i / across;
        const double margin = lidMargin(1, out);
        const Vec3d root = onEye(eye, kUpperLidRadius + 0.0001, margin, out);
        const double length = 0.0008 + 0.0022 * std::sin(kPi * i / across);
        const Vec3d away = normalized(root - centre);
        base.push_back(addVertex(lashes, root, lashTag));
        tip.push_back(addVertex(lashes, root + normalized(away + Vec3d{0, 0.9, 0}) * length, lashTag));
    }
    for (int i = 0; i < across; ++i) {
        const Vec3d out{0, -0.3, 1};
        addFacing(lashes, base[std::size_t(i)], base[std::size_t(i + 1)], tip[std::size_t(i + 1)], out);
        addFacing(lashes, base[std::size_t(i)], tip[std::size_t(i + 1)], tip[std::size_t(i)], out);
    }
    finish(lashes, pieces);
}

// ---------------------------------------------------------------------------------------------
// Inside the mouth.

// A row of teeth: a band along the dental arch, closed at its ends, between heights y0 and y1.
void addTeeth(int joint, bool upper, double spacing, const FaceMaterials& materials, std::vector<Piece>& pieces)
{
    Piece teeth = startPiece(joint, upper ? "upper_teeth" : "lower_teeth", materials.teeth);
    const double y0 = upper ? kMouthY - 0.0018 : kLowerTeethBottom, y1 = upper ? kUpperTeethTop : kMouthY - 0.0002;
    const double halfWidth = upper ? 0.0235 : 0.0215, depth = upper ? 0.030 : 0.029, front = upper ? kTeethFront : kTeethFront - 0.0025;
    constexpr double Thickness = 0.0055;
    const auto archPoint = [&](double s) { return Vec3d{s * halfWidth, 0, front - depth * s * s}; };
    const std::vector<double> rings = evenRings(-1, 1, std::max(12, stepsFor(2.4 * halfWidth + 2 * depth, spacing)));
    addRings(teeth, rings, 12, true, true, false,
             [&](double s, double angle) {
                 const Vec3d tangent = normalized(archPoint(s + 1e-4) - archPoint(s - 1e-4));
                 const Vec3d outward = normalized(cross(tangent, Vec3d{0, 1, 0})) * -1.0;
                 const double c = std::cos(angle), sn = std::sin(angle);
                 const double boxC = std::copysign(std::pow(std::abs(c), 0.4), c), boxS = std::copysign(std::pow(std::abs(sn), 0.4), sn);
                 const Vec3d centre = archPoint(s) - outward * (0.5 * Thickness) + Vec3d{0, 0.5 * (y0 + y1), 0};
                 return SurfacePoint{centre + outward * (0.5 * Thickness * boxC) + Vec3d{0, 0.5 * (y1 - y0) * boxS, 0},
                                     outward};
             },
             [&](double) { return rigid(joint); });
    teeth.face.assign(teeth.positions.size(), FaceTag{upper ? FacePart::UpperTeeth : FacePart::LowerTeeth, 0, 0, -1});
    faceAwayFrom(teeth, Vec3d{0, 0.5 * (y0 + y1), front - 0.6 * depth}); // the arch's middle
    finish(teeth, pieces);
}

// An ellipsoid; `inside` turns it to face its centre (the inside of the mouth is seen from within).
void addEllipsoid(int joint, std::string_view segment, int material, Vec3d centre, Vec3d radii, bool inside,
                  FacePart part, double spacing, std::vector<Piece>& pieces)
{
    Piece piece = startPiece(joint, segment, material);
    const int around = std::max(16, aroundFor(2 * kPi * std::max(radii.x, radii.y), spacing, 16));
    const std::vector<double> rings = evenRings(0, kPi, std::max(8, stepsFor(kPi * radii.z, spacing)));
    addRings(piece, rings, around, true, true, false,
             [&](double polar, double a) {
                 const Vec3d d{std::sin(polar) * std::cos(a), std::sin(polar) * std::sin(a), -std::cos(polar)};
                 return SurfacePoint{centre + Vec3d{d.x * radii.x, d.y * radii.y, d.z * radii.z}, d};
             },
             [&](double) { return rigid(joint); });
    faceAwayFrom(piece, centre, inside);
    piece.face.resize(piece.positions.size());
    for (std::size_t v = 0; v < piece.positions.size(); ++v)
        piece.face[v] = FaceTag{part, std::int8_t(piece.positions[v].y >= kMouthY ? 1 : -1), 0, -1};
    finish(piece, pieces);
}

} // namespace

void addFace(int joint, double spacing, const FaceMaterials& materials, std::vector<Piece>& pieces)
{
    const double fine = std::clamp(spacing * 0.12, 0.0012, 0.008); // eyes and lids
    addSkin(joint, spacing, materials, pieces);
    for (const int eye : {1, -1}) {
        addEyeCap(joint, eye, eye > 0 ? "l_eyeball" : "r_eyeball", materials.sclera, kEyeballRadius, kPi,
                  FacePart::Eyeball, fine * 2, pieces);
        addEyeCap(joint, eye, eye > 0 ? "l_iris" : "r_iris", materials.iris, kEyeballRadius + 0.00012, kIrisAngle,
                  FacePart::Eyeball, fine, pieces);
        addEyeCap(joint, eye, eye > 0 ? "l_pupil" : "r_pupil", materials.pupil, kEyeballRadius + 0.00024, kPupilAngle,
                  FacePart::Pupil, fine, pieces);
        addLid(joint, eye, 1, fine, materials, pieces);
        addLid(joint, eye, -1, fine, materials, pieces);
    }
    addTeeth(joint, true, fine * 2.5, materials, pieces);
    addTeeth(joint, false, fine * 2.5, materials, pieces);
    addEllipsoid(joint, "tongue", materials.tongue, kTongueCentre, kTongueRadii, false, FacePart::Tongue, fine * 3, pieces);
    addEllipsoid(joint, "mouth", materials.mouth, kMouthCentre, kMouthRadii, true, FacePart::Mouth, fine * 4, pieces);
}

} // namespace thespis::core::scene::humanoid
