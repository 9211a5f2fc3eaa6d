// The default humanoid's face rig (humanoid_face.h): MPEG-4 feature points placed on the modelled
// face, the FAP units measured between them, each low-level FAP's influence over the surface as a
// morph target per FAP unit (weights falling off from the feature point it moves, kept to its
// side of the mouth), the jaw, eyeballs and lids as rigid parts, the head FAPs on the skull.

#include <algorithm>
#include <cmath>
#include <functional>
#include <optional>
#include <string>

#include "scene/face_tables.h"
#include "scene/humanoid_face.h"
#include "scene/humanoid_face_layout.h"

namespace thespis::core::scene::humanoid {

namespace {

using namespace face;

class RigBuilder {
public:
    RigBuilder(const CharacterMesh& mesh, std::span<const FaceTag> tags) : m_mesh(mesh), m_tags(tags) {}

    Vec3d position(std::uint32_t v) const
    {
        const anim::Vec3& p = m_mesh.positions[v];
        return {p.x, p.y, p.z};
    }
    const FaceTag& tag(std::uint32_t v) const { return m_tags[v]; }
    std::uint32_t vertexCount() const { return std::uint32_t(m_tags.size()); }

    /// The vertex passing `accept` nearest to `target`, measured with `scale` per axis (0: ignore the axis).
    std::uint32_t nearest(Vec3d target, Vec3d scale, const std::function<bool(std::uint32_t)>& accept) const
    {
        std::uint32_t best = 0;
        double bestDistance = HUGE_VAL;
        for (std::uint32_t v = 0; v < vertexCount(); ++v) {
            if (!accept(v))
                continue;
            const Vec3d d = position(v) - target;
            const double distance = std::pow(d.x * scale.x, 2) + std::pow(d.y * scale.y, 2) + std::pow(d.z * scale.z, 2);
            if (distance < bestDistance)
                bestDistance = distance, best = v;
        }
        return best;
    }

    void addPoint(FaceRig& rig, std::string name, std::uint32_t vertex) const
    {
        rig.featurePoints.push_back({std::move(name), vertex});
    }

    Vec3d point(const FaceRig& rig, std::string_view name) const { return position(rig.findFeaturePoint(name)->vertex); }

    /// A FAP moving the vertices `accept` takes by `direction` × its unit per unit, weighted by
    /// (1 − q²)² of their ellipsoidal distance q from `centre` (radii `radii`).
    void addInfluence(FaceRig& rig, int fap, Vec3d centre, Vec3d radii, Vec3d direction, double unit,
                      const std::function<bool(std::uint32_t)>& accept,
                      const std::function<double(std::uint32_t)>& extra = {}) const
    {
        MorphTarget target;
        target.name = "fap" + std::to_string(fap);
        for (std::uint32_t v = 0; v < vertexCount(); ++v) {
            if (!accept(v))
                continue;
            const Vec3d d = position(v) - centre;
            const double q2 = std::pow(d.x / radii.x, 2) + std::pow(d.y / radii.y, 2) + std::pow(d.z / radii.z, 2);
            double weight = q2 < 1 ? (1 - q2) * (1 - q2) : 0;
            if (extra)
                weight *= extra(v);
            if (weight <= 1e-4)
                continue;
            const Vec3d offset = direction * (weight * unit);
            target.vertices.push_back(v);
            target.offsets.push_back({float(offset.x), float(offset.y), float(offset.z)});
        }
        addTarget(rig, fap, std::move(target));
    }

    static void addTarget(FaceRig& rig, int fap, MorphTarget target)
    {
        rig.drives.push_back({int(rig.targets.size()), fapChannel(fap), 1.0f});
        rig.targets.push_back(std::move(target));
    }

    std::vector<std::uint32_t> where(const std::function<bool(std::uint32_t)>& accept) const
    {
        std::vector<std::uint32_t> out;
        for (std::uint32_t v = 0; v < vertexCount(); ++v)
            if (accept(v))
                out.push_back(v);
        return out;
    }

private:
    const CharacterMesh& m_mesh;
    std::span<const FaceTag> m_tags;
};

const Vec3d kXY{1, 1, 0}, kXYZ{1, 1, 1};

// The jaw's share of a skin vertex below the mouth: the whole chin and lower lip; towards the
// ears it fades along a line from the mouth's corners to the jaw's hinge, and towards the neck.
double jawWeight(Vec3d p)
{
    const double frontZ = 0.09, along = std::clamp((frontZ - p.z) / (frontZ - kJawPivot.z), 0.0, 1.0);
    const double boundary = mouthLineY(p.x) + (kJawPivot.y - kMouthY) * along;
    const double ramp = 0.002 + 0.5 * std::max(0.0, std::abs(p.x) - kMouthCorner);
    const double below = smoothstep((boundary - p.y) / ramp + 0.5);
    const double front = smoothstep((p.z + 0.005) / 0.035);
    const double neck = smoothstep((p.y - 1.545) / 0.02);
    return below * front * neck;
}

} // namespace

FaceRig makeFaceRig(const CharacterMesh& mesh, std::span<const FaceTag> tags, const anim::Skeleton& skeleton)
{
    FaceRig rig;
    const RigBuilder b(mesh, tags);
    const auto is = [&](FacePart part) { return [&b, part](std::uint32_t v) { return b.tag(v).part == part; }; };
    const auto skin = [&b](std::uint32_t v) { return b.tag(v).part == FacePart::Skin; };
    const auto frontSkin = [&b](std::uint32_t v) { return b.tag(v).part == FacePart::Skin && b.position(v).z > 0.05; };
    const auto lips = [&b](int side) {
        return [&b, side](std::uint32_t v) {
            const FaceTag& t = b.tag(v);
            return (t.part == FacePart::Skin || t.part == FacePart::LipRoll) && (side == 0 || t.side == side);
        };
    };
    const auto slit = [&b](int side) {
        return [&b, side](std::uint32_t v) { return b.tag(v).slit >= 0 && b.tag(v).side == side; };
    };

    // ---- Feature points (ISO/IEC 14496-2 Figure C-1); "l" is the face's left (+x).
    b.addPoint(rig, "2.1", b.nearest({0, 1.5720, 0}, kXY, frontSkin));
    b.addPoint(rig, "2.2", b.nearest({0, kMouthY, 0}, kXY, slit(1)));
    b.addPoint(rig, "2.3", b.nearest({0, kMouthY, 0}, kXY, slit(-1)));
    for (const int side : {1, -1}) {
        const double half = side * 0.5 * kMouthCorner;
        const std::string corner = side > 0 ? "2.4" : "2.5";
        b.addPoint(rig, corner, b.nearest({side * kMouthCorner, mouthLineY(kMouthCorner), 0}, kXY, frontSkin));
        b.addPoint(rig, side > 0 ? "2.6" : "2.7", b.nearest({half, kMouthY, 0}, kXY, slit(1)));
        b.addPoint(rig, side > 0 ? "2.8" : "2.9", b.nearest({half, kMouthY, 0}, kXY, slit(-1)));
        b.addPoint(rig, side > 0 ? "8.3" : "8.4",
                   b.nearest({side * (kMouthCorner + 0.0015), mouthLineY(kMouthCorner), 0}, kXY, frontSkin));
        b.addPoint(rig, side > 0 ? "8.5" : "8.6",
                   b.nearest({half, mouthLineY(half) + upperLipHeight(half), 0}, kXY, lips(1)));
        b.addPoint(rig, side > 0 ? "8.7" : "8.8",
                   b.nearest({half, mouthLineY(half) - lowerLipHeight(half), 0}, kXY, lips(-1)));
    }
    b.addPoint(rig, "2.10", b.nearest({0, 1.5850, 0}, kXY, frontSkin));
    b.addPoint(rig, "8.1", b.nearest({0, kMouthY + upperLipHeight(0), 0}, kXY, lips(1)));
    b.addPoint(rig, "8.2", b.nearest({0, kMouthY - lowerLipHeight(0), 0}, kXY, lips(-1)));
    for (const int eye : {1, -1}) {
        const bool left = eye > 0;
        const auto lid = [&b, eye](int side) {
            return [&b, eye, side](std::uint32_t v) {
                return b.tag(v).part == FacePart::Eyelid && b.tag(v).eye == eye && b.tag(v).side == side;
            };
        };
        b.addPoint(rig, left ? "3.1" : "3.2", b.nearest(onEye(eye, kUpperLidRadius, kUpperMargin, 0), kXYZ, lid(1)));
        b.addPoint(rig, left ? "3.3" : "3.4", b.nearest(onEye(eye, kLowerLidRadius, -kLowerMargin, 0), kXYZ, lid(-1)));
        b.addPoint(rig, left ? "3.5" : "3.6", b.nearest(onEye(eye, kEyeballRadius + 0.001, 0, 0), kXYZ, [&b, eye](std::uint32_t v) {
            return b.tag(v).part == FacePart::Pupil && b.tag(v).eye == eye;
        }));
        b.addPoint(rig, left ? "3.7" : "3.8", b.nearest(onEye(eye, kUpperLidRadius, 0, kOuterCorner), kXYZ, lid(1)));
        b.addPoint(rig, left ? "3.11" : "3.12", b.nearest(onEye(eye, kUpperLidRadius, 0, -kInnerCorner), kXYZ, lid(1)));
        const double x = eye;
        b.addPoint(rig, left ? "4.1" : "4.2", b.nearest({x * kBrowInner, browY(kBrowInner), 0}, kXY, frontSkin));
        b.addPoint(rig, left ? "4.3" : "4.4", b.nearest({x * kBrowMiddle, browY(kBrowMiddle), 0}, kXY, frontSkin));
        b.addPoint(rig, left ? "4.5" : "4.6", b.nearest({x * kBrowOuter, browY(kBrowOuter), 0}, kXY, frontSkin));
        b.addPoint(rig, left ? "5.1" : "5.2", b.nearest({x * 0.045, 1.6300, 0}, kXY, frontSkin));
        b.addPoint(rig, left ? "5.3" : "5.4", b.nearest({x * 0.047, 1.6560, 0}, kXY, frontSkin));
        b.addPoint(rig, left ? "9.1" : "9.2", b.nearest({x * 0.0095, 1.6300, 0}, kXY, frontSkin));
        const auto ear = [&b, eye](std::uint32_t v) {
            return b.tag(v).part == FacePart::Skin && b.position(v).x * eye > 0.07;
        };
        b.addPoint(rig, left ? "10.1" : "10.2", b.nearest({x * 0.090, 1.6950, 0.005}, kXYZ, ear));
        b.addPoint(rig, left ? "10.3" : "10.4", b.nearest({x * 0.094, 1.6700, 0.005}, kXYZ, ear));
    }
    b.addPoint(rig, "9.3", b.nearest({0, 1.6370, 0.13}, kXYZ, frontSkin));
    b.addPoint(rig, "9.15", b.nearest({0, 1.6250, 0}, kXY, frontSkin));
    const auto tongue = b.where(is(FacePart::Tongue));
    const auto extreme = [&](const std::vector<std::uint32_t>& vertices, auto score) {
        return *std::max_element(vertices.begin(), vertices.end(),
                                 [&](std::uint32_t a, std::uint32_t c) { return score(b.position(a)) < score(b.position(c)); });
    };
    b.addPoint(rig, "6.1", extreme(tongue, [](Vec3d p) { return p.z; }));
    b.addPoint(rig, "6.2", extreme(tongue, [](Vec3d p) { return p.y - 10 * std::abs(p.x); }));
    b.addPoint(rig, "6.3", extreme(tongue, [](Vec3d p) { return p.x; }));
    b.addPoint(rig, "6.4", extreme(tongue, [](Vec3d p) { return -p.x; }));

    // ---- FAP units (Figure C-2): distances of the neutral face over 1024.
    FapUnits& u = rig.units;
    u.irisd = (b.point(rig, "3.1").y - b.point(rig, "3.3").y) / 1024;
    u.es = (b.point(rig, "3.5").x - b.point(rig, "3.6").x) / 1024;
    u.ens = (b.point(rig, "3.5").y - b.point(rig, "9.15").y) / 1024;
    u.mns = (b.point(rig, "9.15").y - b.point(rig, "2.2").y) / 1024;
    u.mw = (b.point(rig, "8.3").x - b.point(rig, "8.4").x) / 1024;

    // ---- Lips: inner contour (2.x) and outer (8.x), each on its own side of the opening.
    const Vec3d up{0, 1, 0}, down{0, -1, 0}, forward{0, 0, 1}, toLeft{1, 0, 0}, toRight{-1, 0, 0};
    const Vec3d innerLip{0.011, 0.0075, 0.02}, outerLip{0.012, 0.0095, 0.02}, cornerLip{0.014, 0.011, 0.02};
    b.addInfluence(rig, 4, b.point(rig, "2.2"), innerLip, down, u.mns, lips(1));
    b.addInfluence(rig, 5, b.point(rig, "2.3"), innerLip, up, u.mns, lips(-1));
    b.addInfluence(rig, 51, b.point(rig, "8.1"), outerLip, down, u.mns, lips(1));
    b.addInfluence(rig, 52, b.point(rig, "8.2"), outerLip, up, u.mns, lips(-1));
    b.addInfluence(rig, 17, b.point(rig, "2.2"), {0.022, 0.010, 0.02}, forward, u.mns, lips(1));
    b.addInfluence(rig, 16, b.point(rig, "2.3"), {0.022, 0.011, 0.02}, forward, u.mns, lips(-1));
    b.addInfluence(rig, 18, b.point(rig, "2.10"), {0.020, 0.012, 0.02}, up, u.mns, lips(-1));
    for (const int side : {1, -1}) {
        const bool left = side > 0;
        const Vec3d outward = left ? toLeft : toRight;
        b.addInfluence(rig, left ? 6 : 7, b.point(rig, left ? "2.4" : "2.5"), cornerLip, outward, u.mw, lips(0));
        b.addInfluence(rig, left ? 12 : 13, b.point(rig, left ? "2.4" : "2.5"), cornerLip, up, u.mns, lips(0));
        b.addInfluence(rig, left ? 53 : 54, b.point(rig, left ? "8.3" : "8.4"), cornerLip, outward, u.mw, lips(0));
        b.addInfluence(rig, left ? 59 : 60, b.point(rig, left ? "8.3" : "8.4"), cornerLip, up, u.mns, lips(0));
        const Vec3d sideLip{0.009, 0.0075, 0.02};
        b.addInfluence(rig, left ? 8 : 9, b.point(rig, left ? "2.6" : "2.7"), sideLip, down, u.mns, lips(1));
        b.addInfluence(rig, left ? 10 : 11, b.point(rig, left ? "2.8" : "2.9"), sideLip, up, u.mns, lips(-1));
        b.addInfluence(rig, left ? 55 : 56, b.point(rig, left ? "8.5" : "8.6"), sideLip, down, u.mns, lips(1));
        b.addInfluence(rig, left ? 57 : 58, b.point(rig, left ? "8.7" : "8.8"), sideLip, up, u.mns, lips(-1));

        // Brows (the skin above the eyes, each on its side), cheeks, nose and ears. A brow's three
        // points reach each other's, so that together they bend it smoothly.
        // Across the mid-line the two sides share (half each there), so that both brows raised
        // together move the forehead evenly.
        const auto ownSide = [&b, side](std::uint32_t v) { return smoothstep(b.position(v).x * side / 0.006 + 0.5); };
        const Vec3d brow{0.0215, 0.013, 0.03};
        b.addInfluence(rig, left ? 31 : 32, b.point(rig, left ? "4.1" : "4.2"), brow, up, u.ens, frontSkin, ownSide);
        b.addInfluence(rig, left ? 33 : 34, b.point(rig, left ? "4.3" : "4.4"), brow, up, u.ens, frontSkin, ownSide);
        b.addInfluence(rig, left ? 35 : 36, b.point(rig, left ? "4.5" : "4.6"), brow, up, u.ens, frontSkin, ownSide);
        b.addInfluence(rig, left ? 37 : 38, b.point(rig, left ? "4.1" : "4.2"), brow, left ? toRight : toLeft, u.es,
                       frontSkin, ownSide);
        b.addInfluence(rig, left ? 39 : 40, b.point(rig, left ? "5.1" : "5.2"), {0.022, 0.022, 0.03}, outward, u.es,
                       skin);
        b.addInfluence(rig, left ? 41 : 42, b.point(rig, left ? "5.3" : "5.4"), {0.020, 0.016, 0.03}, up, u.ens, skin);
        b.addInfluence(rig, left ? 61 : 62, b.point(rig, left ? "9.1" : "9.2"), {0.008, 0.007, 0.015}, outward, u.ens,
                       frontSkin);
        const Vec3d earSize{0.02, 0.035, 0.035};
        b.addInfluence(rig, left ? 65 : 66, b.point(rig, left ? "10.1" : "10.2"), earSize, up, u.ens, skin);
        b.addInfluence(rig, left ? 67 : 68, b.point(rig, left ? "10.3" : "10.4"), earSize, outward, u.ens, skin);

        // The pupil widens (its rim moves out by the FAP's value).
        const auto pupil = [&b, side](std::uint32_t v) { return b.tag(v).part == FacePart::Pupil && b.tag(v).eye == side; };
        MorphTarget dilate;
        dilate.name = left ? "fap29" : "fap30";
        const Vec3d centre = eyeCentre(side);
        const double rim = (kEyeballRadius + 0.00024) * std::sin(kPupilAngle);
        for (const std::uint32_t v : b.where(pupil)) {
            const Vec3d r = b.position(v) - centre, across{r.x, r.y, 0};
            const double length = std::sqrt(dot(across, across));
            if (length < 1e-9)
                continue;
            const Vec3d offset = across * (u.irisd / rim);
            dilate.vertices.push_back(v);
            dilate.offsets.push_back({float(offset.x), float(offset.y), float(offset.z)});
        }
        RigBuilder::addTarget(rig, left ? 29 : 30, std::move(dilate));
    }
    b.addInfluence(rig, 63, b.point(rig, "9.3"), {0.012, 0.014, 0.02}, up, u.ens, frontSkin);
    b.addInfluence(rig, 64, b.point(rig, "9.3"), {0.012, 0.014, 0.02}, toRight, u.ens, frontSkin);

    // ---- The tongue: its tip, its body, its sides (which roll up).
    const Vec3d tip = b.point(rig, "6.1");
    const auto towardsTip = [&b, tip](std::uint32_t v) { return std::pow(smoothstep((b.position(v).z - tip.z + 0.035) / 0.035), 2); };
    const auto isTongue = is(FacePart::Tongue);
    const Vec3d wholeTongue{1, 1, 1};
    b.addInfluence(rig, 43, tip, wholeTongue, toRight, u.mw, isTongue, towardsTip);
    b.addInfluence(rig, 44, tip, wholeTongue, up, u.mns, isTongue, towardsTip);
    b.addInfluence(rig, 45, tip, wholeTongue, forward, u.mw, isTongue, towardsTip);
    b.addInfluence(rig, 46, b.point(rig, "6.2"), {0.03, 0.03, 0.03}, up, u.mns, isTongue);
    b.addInfluence(rig, 47, kTongueCentre, wholeTongue, up, FapUnits::au, isTongue,
                   [&b](std::uint32_t v) { return std::abs(b.position(v).x - kTongueCentre.x); });

    // ---- Rigid parts: the jaw (with the lower teeth, the tongue and the mouth's floor), the
    // eyeballs, the lids.
    RigidFacePart jaw;
    jaw.name = "jaw";
    jaw.pivot = kJawPivot;
    for (std::uint32_t v = 0; v < b.vertexCount(); ++v) {
        const FaceTag& t = b.tag(v);
        const Vec3d p = b.position(v);
        double weight = 0;
        if (t.part == FacePart::Skin && t.side < 0)
            weight = jawWeight(p);
        else if ((t.part == FacePart::LipRoll && t.side < 0) || t.part == FacePart::LowerTeeth || t.part == FacePart::Tongue)
            weight = 1;
        else if (t.part == FacePart::Mouth) // its floor at the front; its back wall stays before the throat
            weight = smoothstep((kMouthY + 0.002 - p.y) / 0.007) * smoothstep((p.z - kMouthCentre.z + 0.012) / 0.02);
        if (weight > 0)
            jaw.vertices.push_back(v), jaw.weights.push_back(float(weight));
    }
    jaw.drop = {fapChannel(3), {1, 0, 0}, b.point(rig, "2.1"), u.mns};
    jaw.shifts = {{fapChannel(14), forward, u.mns}, {fapChannel(15), toRight, u.mw}};
    rig.parts.push_back(std::move(jaw));
    for (const int eye : {1, -1}) {
        const bool left = eye > 0;
        RigidFacePart ball;
        ball.name = left ? "l_eyeball" : "r_eyeball";
        ball.pivot = eyeCentre(eye);
        ball.vertices = b.where([&b, eye](std::uint32_t v) {
            return (b.tag(v).part == FacePart::Eyeball || b.tag(v).part == FacePart::Pupil) && b.tag(v).eye == eye;
        });
        ball.weights.assign(ball.vertices.size(), 1.0f);
        ball.turns = {{fapChannel(left ? 25 : 26), {1, 0, 0}, FapUnits::au}, {fapChannel(left ? 23 : 24), {0, 1, 0}, FapUnits::au}};
        ball.shifts = {{fapChannel(left ? 27 : 28), forward, u.es}};
        rig.parts.push_back(std::move(ball));
        for (const int side : {1, -1}) {
            RigidFacePart lid;
            lid.name = std::string(left ? "l_" : "r_") + (side > 0 ? "upper_lid" : "lower_lid");
            lid.pivot = eyeCentre(eye);
            lid.vertices = b.where([&b, eye, side](std::uint32_t v) {
                const FaceTag& t = b.tag(v);
                return (t.part == FacePart::Eyelid || t.part == FacePart::Eyelash) && t.eye == eye && t.side == side;
            });
            lid.weights.assign(lid.vertices.size(), 1.0f);
            const int fap = side > 0 ? (left ? 19 : 20) : (left ? 21 : 22);
            lid.drop = {fapChannel(fap), {1, 0, 0}, b.point(rig, side > 0 ? (left ? "3.1" : "3.2") : (left ? "3.3" : "3.4")),
                        side > 0 ? u.irisd : -u.irisd};
            rig.parts.push_back(std::move(lid));
        }
    }

    // ---- The head's FAPs turn the skull; the lips meet and never pass.
    if (const int skull = skeleton.find("skullbase"); skull >= 0)
        rig.joints = {{skull, fapChannel(48), {1, 0, 0}, FapUnits::au},
                      {skull, fapChannel(49), {0, 1, 0}, FapUnits::au},
                      {skull, fapChannel(50), {0, 0, 1}, FapUnits::au}};
    for (const std::uint32_t upper : b.where(slit(1)))
        for (const std::uint32_t lower : b.where(slit(-1)))
            if (b.tag(upper).slit == b.tag(lower).slit)
                rig.lipContacts.push_back({upper, lower});
    for (int v = 1; v <= kVisemeCount; ++v)
        rig.visemes[std::size_t(v - 1)] = visemeFaps(v);
    for (int e = 1; e <= kExpressionCount; ++e)
        rig.expressions[std::size_t(e - 1)] = expressionFaps(e);
    return rig;
}

} // namespace thespis::core::scene::humanoid
