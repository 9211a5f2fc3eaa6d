#include "scene/default_humanoid.h"

#include <algorithm>
#include <array>
#include <cassert>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "scene/humanoid_face.h"
#include "scene/humanoid_head.h"
#include "scene/humanoid_parts.h"

namespace thespis::core::scene {
namespace {

using namespace humanoid;

namespace hanim = anim::hanim;
using anim::Skeleton;

// ---------------------------------------------------------------------------------------------
// The body, left side and mid-line; right-side parts mirror the left ones.

constexpr Vec3d kForward{0, 0, 1};
constexpr Vec3d kUp{0, 1, 0};

/// Torso from the crotch to inside the head; its centre lies in front of the spine.
const SweepKey kTorso[] = {
    {"sacroiliac", "", 0, {0, -0.09, 0.0}, {0.100, 0.060, 0.075, 2.2}, "sacroiliac"},
    {"sacroiliac", "", 0, {0, -0.04, 0.005}, {0.158, 0.080, 0.104, 2.3}},
    {"humanoid_root", "", 0, {0, -0.03, 0.005}, {0.163, 0.088, 0.102, 2.3}, "humanoid_root"},
    {"vl5", "", 0, {0, 0, 0.025}, {0.152, 0.085, 0.086, 2.2}, "vl5"},
    {"vl3", "", 0, {0, 0, 0.035}, {0.141, 0.085, 0.080, 2.2}, "vl3"},
    {"vl1", "", 0, {0, 0, 0.040}, {0.142, 0.090, 0.084, 2.2}, "vl1"},
    {"vt10", "", 0, {0, 0, 0.055}, {0.149, 0.100, 0.094, 2.2}, "vt10"},
    {"vt6", "", 0, {0, 0, 0.070}, {0.156, 0.112, 0.100, 2.3}, "vt6"},
    {"vt6", "vt1", 0.64, {0, 0, 0.065}, {0.160, 0.105, 0.100, 2.4}},
    {"vt1", "", 0, {0, 0, 0.055}, {0.148, 0.090, 0.090, 2.4}, "vt1"},
    {"vt1", "vc4", 0.6, {0, 0, 0.035}, {0.100, 0.066, 0.070, 2.2}},
    {"vc4", "", 0, {0, 0, 0.030}, {0.066, 0.060, 0.064, 2.0}, "vc4"},
    {"vc2", "", 0, {0, 0, 0.025}, {0.060, 0.056, 0.060, 2.0}, "vc2"},
    {"skullbase", "", 0, {0, 0, 0.008}, {0.057, 0.040, 0.058, 2.0}, "skullbase"},
    {"skullbase", "", 0, {0, 0.04, 0.0}, {0.050, 0.035, 0.050, 2.0}}, // behind the mouth (humanoid_face.h)
};

/// Shoulder line (clavicle and trapezius) from the neck to the shoulder; sections: side = front
/// and back, front = up.
const SweepKey kClavicle[] = {
    {"l_sternoclavicular", "", 0, {0.02, 0.065, -0.065}, {0.045, 0.030, 0.035, 2.2}, "l_sternoclavicular"},
    {"l_acromioclavicular", "", 0, {0.01, 0.005, 0.0}, {0.042, 0.030, 0.035, 2.2}, "l_acromioclavicular"},
};

/// Arm from the deltoid to the knuckles; the hand's palm is flat towards the thigh.
const SweepKey kArm[] = {
    {"l_shoulder", "", 0, {-0.004, 0.02, 0}, {0.044, 0.046, 0.046, 2.0}},
    {"l_shoulder", "", 0, {-0.002, 0, 0}, {0.046, 0.048, 0.047, 2.0}, "l_shoulder"},
    {"l_shoulder", "l_elbow", 0.35, {0, 0, 0}, {0.046, 0.046, 0.046, 2.0}},
    {"l_shoulder", "l_elbow", 0.7, {0, 0, 0}, {0.040, 0.040, 0.043, 2.0}},
    {"l_elbow", "", 0, {0, 0, 0}, {0.036, 0.035, 0.037, 2.0}, "l_elbow"},
    {"l_elbow", "l_radiocarpal", 0.22, {0, 0, 0.003}, {0.039, 0.041, 0.039, 2.0}},
    {"l_elbow", "l_radiocarpal", 0.6, {0, 0, 0}, {0.031, 0.034, 0.032, 2.0}},
    {"l_radiocarpal", "", 0, {0, 0, 0}, {0.021, 0.029, 0.027, 2.2}, "l_radiocarpal"},
    {"l_radiocarpal", "", 0, {0.004, -0.03, 0.002}, {0.016, 0.041, 0.040, 2.6}},
    {"l_radiocarpal", "", 0, {0.007, -0.075, 0.002}, {0.015, 0.044, 0.043, 2.8}},
};

/// Leg from the top of the thigh (inside the pelvis) to the ankle (inside the shoe).
const SweepKey kLeg[] = {
    {"l_hip", "", 0, {0.0, 0.03, 0}, {0.072, 0.072, 0.080, 2.0}},
    {"l_hip", "", 0, {0.002, 0, -0.005}, {0.080, 0.080, 0.092, 2.0}, "l_hip"},
    {"l_hip", "l_knee", 0.3, {0, 0, 0.003}, {0.078, 0.080, 0.080, 2.0}},
    {"l_hip", "l_knee", 0.65, {0, 0, 0.003}, {0.065, 0.066, 0.064, 2.0}},
    {"l_knee", "", 0, {0, 0, 0}, {0.050, 0.052, 0.048, 2.0}, "l_knee"},
    {"l_knee", "l_talocrural", 0.22, {0, 0, -0.005}, {0.050, 0.046, 0.062, 2.0}},
    {"l_knee", "l_talocrural", 0.55, {0, 0, -0.003}, {0.042, 0.040, 0.048, 2.0}},
    {"l_knee", "l_talocrural", 0.85, {0, 0, 0}, {0.032, 0.031, 0.034, 2.0}},
    {"l_talocrural", "", 0, {0, 0, 0}, {0.030, 0.031, 0.032, 2.0}, "l_talocrural"},
    {"l_talocrural", "", 0, {0, -0.025, 0.005}, {0.030, 0.032, 0.032, 2.0}},
};

/// Shoe from heel to toe along +Z; sections: front = up, back = down to the sole at y = 0.
const SweepKey kFoot[] = {
    {"l_talocrural", "", 0, {0, -0.045, -0.035}, {0.032, 0.035, 0.035, 2.6}, "l_talocrural"},
    {"l_talocrural", "", 0, {0, -0.035, 0.0}, {0.035, 0.045, 0.045, 2.6}},
    {"l_tarsometatarsal", "", 0, {0, -0.01, 0}, {0.042, 0.032, 0.030, 2.6}, "l_tarsometatarsal"},
    {"l_metatarsophalangeal", "", 0, {0.004, 0, 0}, {0.047, 0.020, 0.020, 2.6}, "l_metatarsophalangeal"},
    {"l_tarsal_interphalangeal", "", 0, {0.004, 0, 0}, {0.042, 0.016, 0.015, 2.6}, "l_tarsal_interphalangeal"},
};

/// A finger or the thumb: its joints from the base (inside the palm) out, and its radius.
struct Digit {
    std::string_view parent;              ///< the joint the digit hangs from
    std::array<std::string_view, 3> joints; ///< joints starting its three bones
    double radius;
    bool thumb = false;
};

const Digit kDigits[] = {
    {"l_radiocarpal", {"l_carpometacarpal_1", "l_metacarpophalangeal_1", "l_carpal_interphalangeal_1"}, 0.011, true},
    {"l_carpometacarpal_2", {"l_metacarpophalangeal_2", "l_carpal_proximal_interphalangeal_2", "l_carpal_distal_interphalangeal_2"}, 0.0092},
    {"l_carpometacarpal_3", {"l_metacarpophalangeal_3", "l_carpal_proximal_interphalangeal_3", "l_carpal_distal_interphalangeal_3"}, 0.0095},
    {"l_carpometacarpal_4", {"l_metacarpophalangeal_4", "l_carpal_proximal_interphalangeal_4", "l_carpal_distal_interphalangeal_4"}, 0.009},
    {"l_carpometacarpal_5", {"l_metacarpophalangeal_5", "l_carpal_proximal_interphalangeal_5", "l_carpal_distal_interphalangeal_5"}, 0.008},
};

/// Keys of a digit: from a little before its first joint (inside the palm) to past its last
/// joint by about one bone, tapering; the thumb's first bone is the fleshy metacarpal.
std::vector<SweepKey> digitKeys(const Digit& digit)
{
    const auto [first, second, third] = digit.joints;
    auto section = [&](double scale) { return Section{digit.radius * scale, digit.radius * scale, digit.radius * scale, 2.0}; };
    if (digit.thumb)
        return {{first, "", 0, {}, section(1.3), first},
                {first, second, 0.5, {}, section(1.2)},
                {second, "", 0, {}, section(1.0), second},
                {third, "", 0, {}, section(0.9), third},
                {third, second, -0.7, {}, section(0.8)}};
    return {{first, second, -0.35, {}, section(1.0)},
            {first, "", 0, {}, section(1.0), first},
            {second, "", 0, {}, section(0.93), second},
            {third, "", 0, {}, section(0.86), third},
            {third, second, -0.55, {}, section(0.8)}};
}

// ---------------------------------------------------------------------------------------------
// Segment names, materials.

/// H-Anim 2.0 segment of each joint, by the joint name without its side prefix; a trailing
/// "_N" (finger number) carries over.
constexpr std::pair<std::string_view, std::string_view> kSegmentOfJoint[] = {
    {"humanoid_root", "sacrum"},
    {"sacroiliac", "pelvis"},
    {"hip", "thigh"},
    {"knee", "calf"},
    {"talocrural", "talus"},
    {"tarsometatarsal", "metatarsal"},
    {"metatarsophalangeal", "tarsal_proximal_phalanx"},
    {"tarsal_interphalangeal", "tarsal_distal_phalanx"},
    {"skullbase", "skull"},
    {"sternoclavicular", "clavicle"},
    {"acromioclavicular", "scapula"},
    {"shoulder", "upperarm"},
    {"elbow", "forearm"},
    {"radiocarpal", "carpal"},
    {"carpometacarpal", "metacarpal"},
    {"metacarpophalangeal", "carpal_proximal_phalanx"},
    {"carpal_proximal_interphalangeal", "carpal_middle_phalanx"},
    {"carpal_distal_interphalangeal", "carpal_distal_phalanx"},
    {"carpal_interphalangeal", "carpal_distal_phalanx"},
};

std::string segmentName(std::string_view joint)
{
    // Vertebrae: the joint above vertebra X is "vX" (vl5 → l5, vt1 → t1, vc4 → c4).
    if (joint.size() > 2 && joint[0] == 'v' && (joint[1] == 'l' || joint[1] == 't' || joint[1] == 'c'))
        return std::string(joint.substr(1));
    const bool sided = joint.starts_with("l_") || joint.starts_with("r_");
    const std::string_view side = sided ? joint.substr(0, 2) : std::string_view{};
    std::string_view stem = sided ? joint.substr(2) : joint;
    std::string_view number;
    if (const std::size_t underscore = stem.rfind('_');
        underscore != std::string_view::npos && underscore + 2 == stem.size() && std::isdigit(static_cast<unsigned char>(stem.back()))) {
        number = stem.substr(underscore);
        stem = stem.substr(0, underscore);
    }
    for (const auto& [jointStem, segmentStem] : kSegmentOfJoint)
        if (stem == jointStem)
            return std::string(side) + std::string(segmentStem) + std::string(number);
    return std::string(joint);
}

/// Indices into humanoidMaterials().
enum MaterialIndex {
    SkinMaterial,
    HairMaterial,
    ShirtMaterial,
    TrousersMaterial,
    ShoesMaterial,
    FaceMaterial,
    ScleraMaterial,
    IrisMaterial,
    PupilMaterial,
    TeethMaterial,
    TongueMaterial,
    MouthMaterial
};

constexpr std::array<float, 3> kSkin{0.72f, 0.42f, 0.31f};

std::vector<Material> humanoidMaterials(const std::array<float, 3>& shirt)
{
    // Linear base colours: light skin, dark brown hair, the shirt, grey-blue trousers, brown shoes;
    // the head's skin is its picture (lips, brows); eyes, teeth, tongue, the inside of the mouth.
    return {{"skin", {kSkin[0], kSkin[1], kSkin[2], 1.0f}},
            {"hair", {0.10f, 0.05f, 0.025f, 1.0f}},
            {"shirt", {shirt[0], shirt[1], shirt[2], 1.0f}},
            {"trousers", {0.10f, 0.11f, 0.15f, 1.0f}},
            {"shoes", {0.05f, 0.03f, 0.02f, 1.0f}},
            {"face", {1.0f, 1.0f, 1.0f, 1.0f}, 0},
            {"sclera", {0.80f, 0.78f, 0.74f, 1.0f}},
            {"iris", {0.16f, 0.075f, 0.03f, 1.0f}},
            {"pupil", {0.01f, 0.01f, 0.01f, 1.0f}},
            {"teeth", {0.78f, 0.74f, 0.62f, 1.0f}},
            {"tongue", {0.42f, 0.08f, 0.09f, 1.0f}},
            {"mouth", {0.16f, 0.03f, 0.03f, 1.0f}}};
}

constexpr FaceMaterials kFaceMaterials{FaceMaterial, SkinMaterial, HairMaterial, ScleraMaterial, IrisMaterial,
                                       PupilMaterial, TeethMaterial, TongueMaterial, MouthMaterial};

/// The face's own segments (humanoid_face.h), in the order they follow the body's.
constexpr std::string_view kFaceSegments[] = {"l_eyeball", "r_eyeball", "l_iris",      "r_iris",      "l_pupil",
                                              "r_pupil",   "l_eyelid",  "r_eyelid",    "l_eyelash",   "r_eyelash",
                                              "upper_teeth", "lower_teeth", "tongue", "mouth"};

int materialOfJoint(std::string_view joint)
{
    const std::string_view stem = joint.starts_with("l_") || joint.starts_with("r_") ? joint.substr(2) : joint;
    for (std::string_view name : {"humanoid_root", "sacroiliac", "hip", "knee"})
        if (stem == name)
            return TrousersMaterial;
    for (std::string_view name : {"talocrural", "tarsometatarsal", "metatarsophalangeal", "tarsal_interphalangeal"})
        if (stem == name)
            return ShoesMaterial;
    for (std::string_view name : {"vl5", "vl3", "vl1", "vt10", "vt6", "vt1", "sternoclavicular", "acromioclavicular", "shoulder"})
        if (stem == name)
            return ShirtMaterial;
    return SkinMaterial; // neck, head, forearms (short sleeves), hands
}

// ---------------------------------------------------------------------------------------------
// Building the pieces on a skeleton of some level.

class BodyBuilder {
public:
    BodyBuilder(const Skeleton& skeleton, double spacing) : m_skeleton(skeleton), m_spacing(spacing) {}

    /// Skeleton index of an LOA 2 joint, or of its nearest ancestor the level has.
    int jointOf(std::string_view name) const
    {
        while (m_skeleton.find(name) < 0) {
            assert(!name.empty());
            name = hanim::parentName(name);
        }
        return m_skeleton.find(name);
    }

    /// One piece per segment the sweep crosses (neighbouring keys on joints the level merges
    /// share a piece), split at rings shared by both neighbours.
    void addSweep(const SweepSpec& spec, std::vector<Piece>& pieces) const
    {
        const Sweep sweep(spec);
        struct Station {
            double u;
            int joint;
        };
        std::vector<Station> stations;
        for (std::size_t k = 0; k < spec.keys.size(); ++k)
            if (!spec.keys[k].joint.empty()) {
                const int joint = jointOf(spec.keys[k].joint);
                if (stations.empty() || stations.back().joint != joint)
                    stations.push_back({sweep.knot(k), joint});
            }
        assert(!stations.empty());
        const int parent = spec.parent.empty() ? -1 : jointOf(spec.parent);
        const bool blendParent = parent >= 0 && parent != stations.front().joint;

        // Blend half-widths at each station (the first one blends into the parent, if any).
        const double start = sweep.startParameter(), end = sweep.endParameter();
        std::vector<double> halfWidth;
        for (std::size_t j = 0; j < stations.size(); ++j) {
            const double before = stations[j].u - (j == 0 ? start : stations[j - 1].u);
            const double after = (j + 1 < stations.size() ? stations[j + 1].u : end) - stations[j].u;
            halfWidth.push_back(std::min(kBlendHalfWidth, 0.4 * std::min(before, after)));
        }
        auto rampAt = [&](std::size_t j, double u) { // 0 before station j's blend, 1 after it
            if (j >= stations.size())
                return 0.0;
            if (j == 0 && !blendParent)
                return 1.0;
            return smoothstep((u - stations[j].u + halfWidth[j]) / (2 * halfWidth[j]));
        };
        auto influencesAt = [&](double u) {
            Influences influences{};
            int used = 0;
            auto add = [&](int joint, double weight) {
                if (weight > 0 && used < kInfluences) {
                    influences.joints[std::size_t(used)] = joint;
                    influences.weights[std::size_t(used++)] = float(weight);
                }
            };
            if (blendParent)
                add(parent, 1 - rampAt(0, u));
            for (std::size_t j = 0; j < stations.size(); ++j)
                add(stations[j].joint, rampAt(j, u) - rampAt(j + 1, u));
            float sum = 0;
            for (float w : influences.weights)
                sum += w;
            for (float& w : influences.weights)
                w /= sum;
            return influences;
        };

        const int around = aroundFor(sweep.largestPerimeter(), m_spacing, 8);
        // Thin parts (fingers) keep their rings about as close as their vertices around.
        const double ringSpacing = std::min(m_spacing, 1.5 * sweep.largestPerimeter() / around);
        for (std::size_t j = 0; j < stations.size(); ++j) {
            const double from = j == 0 ? start : stations[j].u;
            const double to = j + 1 < stations.size() ? stations[j + 1].u : end;
            // Rings evenly spaced along the tube and along each rounded end, which gets at least
            // three so that it stays round.
            std::vector<double> rings{from};
            for (const double stop : {0.0, sweep.knot(spec.keys.size() - 1), to}) {
                const double last = rings.back();
                if (stop <= last || stop > to)
                    continue;
                const bool cap = stop <= 0 || last >= sweep.knot(spec.keys.size() - 1);
                const std::vector<double> part = evenRings(last, stop, std::max(cap ? 3 : 1, stepsFor(stop - last, ringSpacing)));
                rings.insert(rings.end(), part.begin() + 1, part.end());
            }
            Piece piece;
            piece.joint = stations[j].joint;
            addRings(piece, rings, around, j == 0, j + 1 == stations.size(), false,
                     [&](double u, double angle) { return sweep.pointAt(u, angle); }, influencesAt);
            pieces.push_back(std::move(piece));
        }
    }

    void addHead(std::vector<Piece>& pieces) const
    {
        addFace(jointOf("skullbase"), m_spacing, kFaceMaterials, pieces);
    }

    /// The hair shell: outer and inner surfaces over the same skull directions, closed by a rim
    /// strip along the hairline (its own vertices, so the edge stays crisp).
    void addHair(std::vector<Piece>& pieces) const
    {
        Piece hair;
        hair.joint = jointOf("skullbase");
        hair.hair = true;
        const double spacing = m_spacing * kHeadSpacingScale;
        const int around = aroundFor(2 * kPi * kCranium.radii.z, spacing, 16);
        const std::vector<double> rings = evenRings(0, 1, stepsFor(hairline(kPi) * kCranium.radii.y, spacing));
        auto direction = [](double t, double angle) { return sphereDirection(t * hairline(angle), angle, 1); };
        auto influences = [&](double) { return rigid(hair.joint); };
        // Rings run from the crown down, so cross(∂angle, ∂t) points into the head: the outer
        // surface flips its winding, the inner one (facing the skull) keeps it.
        addRings(hair, rings, around, true, false, true,
                 [&](double t, double angle) { return headSurface(direction(t, angle), hairOuter(t)); }, influences);
        addRings(hair, rings, around, true, false, false,
                 [&](double t, double angle) {
                     const SurfacePoint p = headSurface(direction(t, angle), kHairInner);
                     return SurfacePoint{p.position, p.normal * -1.0};
                 },
                 influences);
        const double rim[] = {hairOuter(1), kHairInner};
        addRings(hair, rim, around, false, false, true,
                 [&](double lift, double angle) {
                     const SurfacePoint edge = headSurface(direction(1, angle), lift);
                     const Vec3d away = headPoint(direction(1, angle)) - headPoint(direction(0.99, angle));
                     return SurfacePoint{edge.position, normalized(away - edge.normal * dot(away, edge.normal))};
                 },
                 influences);
        pieces.push_back(std::move(hair));
    }

    /// The right-side copy of a left-side piece: x mirrored, winding reversed, joints swapped.
    Piece mirrored(const Piece& left) const
    {
        Piece right = left;
        right.joint = mirroredJoint(left.joint);
        for (Vec3d& p : right.positions)
            p.x = -p.x;
        for (Vec3d& n : right.normals)
            n.x = -n.x;
        for (std::size_t t = 0; t < right.triangles.size(); t += 3)
            std::swap(right.triangles[t + 1], right.triangles[t + 2]);
        for (Influences& influences : right.influences)
            for (std::size_t i = 0; i < influences.joints.size(); ++i)
                if (influences.weights[i] > 0)
                    influences.joints[i] = mirroredJoint(influences.joints[i]);
        return right;
    }

private:
    int mirroredJoint(int joint) const { return m_skeleton.find(hanim::mirrorName(m_skeleton.joint(joint).name)); }

    const Skeleton& m_skeleton;
    double m_spacing;
};

} // namespace

Result<Character> makeDefaultHumanoid(const DefaultHumanoidOptions& options)
{
    if (!(options.detail >= 0.1 && options.detail <= 4))
        return makeError(ErrorCode::InvalidArgument,
                         "The default humanoid's detail must be between 0.1 and 4 (it is " +
                             std::to_string(options.detail) + ").");
    Character character;
    character.name = "Default humanoid";
    character.skeleton = hanim::skeleton(options.level);
    const BodyBuilder builder(character.skeleton, kSpacing / options.detail);

    std::vector<Piece> pieces;
    builder.addSweep({kTorso, kForward, 0.05, 0.03}, pieces);
    builder.addHead(pieces);
    std::vector<Piece> left;
    builder.addSweep({kClavicle, kUp, 0.03, 0.04, "vt1"}, left);
    builder.addSweep({kArm, kForward, 0.03, 0.015, "l_acromioclavicular"}, left);
    builder.addSweep({kLeg, kForward, 0.04, 0.02, "sacroiliac"}, left);
    builder.addSweep({kFoot, kUp, 0.025, 0.028}, left);
    for (const Digit& digit : kDigits) {
        const std::vector<SweepKey> keys = digitKeys(digit);
        builder.addSweep({keys, kForward, digit.radius, digit.radius, digit.parent}, left);
    }
    for (Piece& piece : left) {
        Piece right = builder.mirrored(piece);
        pieces.push_back(std::move(piece));
        pieces.push_back(std::move(right));
    }
    builder.addHair(pieces);

    // Segments in skeleton order, one per joint that has pieces, then the hair, then the face's.
    CharacterMesh& mesh = character.mesh;
    Skin& skin = character.skin;
    skin.influences = kInfluences;
    character.materials = humanoidMaterials(options.shirtColor);
    character.textures = {makeFaceTexture(kSkin)};
    std::vector<FaceTag> faceTags;
    auto appendSegment = [&](std::string name, int joint, bool hair, std::string_view own = {}) {
        Segment segment;
        segment.name = std::move(name);
        segment.joint = character.skeleton.joint(joint).name;
        segment.firstVertex = std::uint32_t(mesh.positions.size());
        segment.firstTriangle = std::uint32_t(mesh.triangleCount());
        segment.bindTranslation = restPosition(segment.joint);
        int material = -1;
        for (const Piece& piece : pieces) {
            if (piece.joint != joint || piece.hair != hair || piece.segment != own)
                continue;
            if (piece.material >= 0)
                material = piece.material;
            faceTags.insert(faceTags.end(), piece.face.begin(), piece.face.end());
            faceTags.resize(faceTags.size() + piece.positions.size() - piece.face.size());
            const std::uint32_t base = std::uint32_t(mesh.positions.size());
            for (std::size_t v = 0; v < piece.positions.size(); ++v) {
                const Vec3d& p = piece.positions[v];
                const Vec3d n = normalized(piece.normals[v]);
                mesh.positions.push_back({float(p.x), float(p.y), float(p.z)});
                mesh.normals.push_back({float(n.x), float(n.y), float(n.z)});
                for (std::size_t i = 0; i < kInfluences; ++i) {
                    skin.joints.push_back(std::uint16_t(piece.influences[v].joints[i]));
                    skin.weights.push_back(piece.influences[v].weights[i]);
                }
            }
            for (std::uint32_t index : piece.triangles)
                mesh.indices.push_back(base + index);
        }
        segment.vertexCount = std::uint32_t(mesh.positions.size()) - segment.firstVertex;
        segment.triangleCount = std::uint32_t(mesh.triangleCount()) - segment.firstTriangle;
        if (segment.vertexCount == 0)
            return;
        mesh.segments.push_back(std::move(segment));
        character.segmentMaterials.push_back(material >= 0 ? material
                                             : hair       ? HairMaterial
                                                          : materialOfJoint(mesh.segments.back().joint));
    };
    for (int joint = 0; joint < character.skeleton.jointCount(); ++joint)
        appendSegment(segmentName(character.skeleton.joint(joint).name), joint, false);
    const int skull = builder.jointOf("skullbase");
    appendSegment("hair", skull, true);
    for (const std::string_view own : kFaceSegments)
        appendSegment(std::string(own), skull, false, own);

    // The head's skin samples its picture; every other vertex keeps (0, 0) (its material has none).
    character.texcoords.assign(mesh.vertexCount(), {0.0f, 0.0f});
    const std::size_t head = std::size_t(std::find_if(mesh.segments.begin(), mesh.segments.end(), [&](const Segment& s) {
                                                           return s.joint == character.skeleton.joint(skull).name;
                                                       }) - mesh.segments.begin());
    const Segment& headSegment = mesh.segments[head];
    for (std::uint32_t v = headSegment.firstVertex; v < headSegment.firstVertex + headSegment.vertexCount; ++v) {
        const anim::Vec3& p = mesh.positions[v];
        character.texcoords[v] = faceTexcoord({p.x, p.y, p.z});
    }
    character.face = makeFaceRig(mesh, faceTags, character.skeleton);
    return character;
}

} // namespace thespis::core::scene
