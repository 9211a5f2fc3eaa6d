#include "scene/gltf_character.h"
#include "scene/rig_repair.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <iterator>
#include <limits>
#include <map>
#include <optional>
#include <set>
#include <string_view>
#include <vector>

#include "anim/bvh_naming.h"
#include "anim/hanim.h"
#include "anim/keyframe_clip.h"
#include "scene/gltf_reader.h"

namespace thespis::core::scene {
namespace {

using anim::Quatd;
using anim::Vec3d;
using gltf::Mat4;
using NameEntry = anim::bvh::naming::NameEntry;

// ==== joint names ================================================================================

// Naming conventions of glTF rigs, beside the motion capture ones of anim/bvh_naming.h (whose
// Mixamo table serves glTF files too). As there, a joint is named after what it moves, and names
// with no H-Anim counterpart are listed with an empty name so that they count for detection.

// Unity's humanoid avatar (also VRM's humanoid bone names).
constexpr NameEntry kUnity[] = {
    {"Hips", "humanoid_root"},
    {"Spine", "vl5"},
    {"Chest", "vt10"},
    {"UpperChest", "vt1"},
    {"Neck", "vc4"},
    {"Head", "skullbase"},
    {"Jaw", ""},
    THESPIS_LR_NONE("LeftEye", "RightEye"),
    THESPIS_LR("LeftShoulder", "RightShoulder", "sternoclavicular"),
    THESPIS_LR("LeftUpperArm", "RightUpperArm", "shoulder"),
    THESPIS_LR("LeftLowerArm", "RightLowerArm", "elbow"),
    THESPIS_LR("LeftHand", "RightHand", "radiocarpal"),
    THESPIS_LR("LeftThumbProximal", "RightThumbProximal", "carpometacarpal_1"),
    THESPIS_LR("LeftThumbIntermediate", "RightThumbIntermediate", "metacarpophalangeal_1"),
    THESPIS_LR("LeftThumbDistal", "RightThumbDistal", "carpal_interphalangeal_1"),
    THESPIS_LR("LeftIndexProximal", "RightIndexProximal", "metacarpophalangeal_2"),
    THESPIS_LR("LeftIndexIntermediate", "RightIndexIntermediate", "carpal_proximal_interphalangeal_2"),
    THESPIS_LR("LeftIndexDistal", "RightIndexDistal", "carpal_distal_interphalangeal_2"),
    THESPIS_LR("LeftMiddleProximal", "RightMiddleProximal", "metacarpophalangeal_3"),
    THESPIS_LR("LeftMiddleIntermediate", "RightMiddleIntermediate", "carpal_proximal_interphalangeal_3"),
    THESPIS_LR("LeftMiddleDistal", "RightMiddleDistal", "carpal_distal_interphalangeal_3"),
    THESPIS_LR("LeftRingProximal", "RightRingProximal", "metacarpophalangeal_4"),
    THESPIS_LR("LeftRingIntermediate", "RightRingIntermediate", "carpal_proximal_interphalangeal_4"),
    THESPIS_LR("LeftRingDistal", "RightRingDistal", "carpal_distal_interphalangeal_4"),
    THESPIS_LR("LeftLittleProximal", "RightLittleProximal", "metacarpophalangeal_5"),
    THESPIS_LR("LeftLittleIntermediate", "RightLittleIntermediate", "carpal_proximal_interphalangeal_5"),
    THESPIS_LR("LeftLittleDistal", "RightLittleDistal", "carpal_distal_interphalangeal_5"),
    THESPIS_LR("LeftUpperLeg", "RightUpperLeg", "hip"),
    THESPIS_LR("LeftLowerLeg", "RightLowerLeg", "knee"),
    THESPIS_LR("LeftFoot", "RightFoot", "talocrural"),
    THESPIS_LR("LeftToes", "RightToes", "metatarsophalangeal"),
};

// Hand-made Blender armatures (bone names with a .L / .R side).
constexpr NameEntry kBlender[] = {
    {"hips", "humanoid_root"},
    {"pelvis", "humanoid_root"},
    {"spine", "vl5"},
    {"chest", "vt10"},
    {"upper_chest", "vt1"},
    {"neck", "vc4"},
    {"head", "skullbase"},
    THESPIS_LR("shoulder.L", "shoulder.R", "sternoclavicular"),
    THESPIS_LR("clavicle.L", "clavicle.R", "sternoclavicular"),
    THESPIS_LR("upper_arm.L", "upper_arm.R", "shoulder"),
    THESPIS_LR("upperarm.L", "upperarm.R", "shoulder"),
    THESPIS_LR("forearm.L", "forearm.R", "elbow"),
    THESPIS_LR("lower_arm.L", "lower_arm.R", "elbow"),
    THESPIS_LR("lowerarm.L", "lowerarm.R", "elbow"),
    THESPIS_LR("hand.L", "hand.R", "radiocarpal"),
    THESPIS_LR("thigh.L", "thigh.R", "hip"),
    THESPIS_LR("upper_leg.L", "upper_leg.R", "hip"),
    THESPIS_LR("upperleg.L", "upperleg.R", "hip"),
    THESPIS_LR("shin.L", "shin.R", "knee"),
    THESPIS_LR("calf.L", "calf.R", "knee"),
    THESPIS_LR("lower_leg.L", "lower_leg.R", "knee"),
    THESPIS_LR("lowerleg.L", "lowerleg.R", "knee"),
    THESPIS_LR("foot.L", "foot.R", "talocrural"),
    THESPIS_LR("toe.L", "toe.R", "metatarsophalangeal"),
    THESPIS_LR("toes.L", "toes.R", "metatarsophalangeal"),
};

// Blender's Rigify human metarig and its deform bones ("DEF-" is stripped): "spine" is the
// pelvis, spine.001 … spine.006 go up to the head; ".001" bones of limbs are twist bones.
constexpr NameEntry kRigify[] = {
    {"spine", "humanoid_root"},
    {"spine.001", "vl1"},
    {"spine.002", "vt10"},
    {"spine.003", "vt6"},
    {"spine.004", "vc4"},
    {"spine.005", "vc2"},
    {"spine.006", "skullbase"},
    THESPIS_LR_NONE("breast.L", "breast.R"),
    THESPIS_LR_NONE("pelvis.L", "pelvis.R"),
    THESPIS_LR_NONE("heel.02.L", "heel.02.R"),
    THESPIS_LR("shoulder.L", "shoulder.R", "sternoclavicular"),
    THESPIS_LR("upper_arm.L", "upper_arm.R", "shoulder"),
    THESPIS_LR_NONE("upper_arm.L.001", "upper_arm.R.001"),
    THESPIS_LR("forearm.L", "forearm.R", "elbow"),
    THESPIS_LR_NONE("forearm.L.001", "forearm.R.001"),
    THESPIS_LR("hand.L", "hand.R", "radiocarpal"),
    THESPIS_LR("thumb.01.L", "thumb.01.R", "carpometacarpal_1"),
    THESPIS_LR("thumb.02.L", "thumb.02.R", "metacarpophalangeal_1"),
    THESPIS_LR("thumb.03.L", "thumb.03.R", "carpal_interphalangeal_1"),
    THESPIS_LR("palm.01.L", "palm.01.R", "carpometacarpal_2"),
    THESPIS_LR("f_index.01.L", "f_index.01.R", "metacarpophalangeal_2"),
    THESPIS_LR("f_index.02.L", "f_index.02.R", "carpal_proximal_interphalangeal_2"),
    THESPIS_LR("f_index.03.L", "f_index.03.R", "carpal_distal_interphalangeal_2"),
    THESPIS_LR("palm.02.L", "palm.02.R", "carpometacarpal_3"),
    THESPIS_LR("f_middle.01.L", "f_middle.01.R", "metacarpophalangeal_3"),
    THESPIS_LR("f_middle.02.L", "f_middle.02.R", "carpal_proximal_interphalangeal_3"),
    THESPIS_LR("f_middle.03.L", "f_middle.03.R", "carpal_distal_interphalangeal_3"),
    THESPIS_LR("palm.03.L", "palm.03.R", "carpometacarpal_4"),
    THESPIS_LR("f_ring.01.L", "f_ring.01.R", "metacarpophalangeal_4"),
    THESPIS_LR("f_ring.02.L", "f_ring.02.R", "carpal_proximal_interphalangeal_4"),
    THESPIS_LR("f_ring.03.L", "f_ring.03.R", "carpal_distal_interphalangeal_4"),
    THESPIS_LR("palm.04.L", "palm.04.R", "carpometacarpal_5"),
    THESPIS_LR("f_pinky.01.L", "f_pinky.01.R", "metacarpophalangeal_5"),
    THESPIS_LR("f_pinky.02.L", "f_pinky.02.R", "carpal_proximal_interphalangeal_5"),
    THESPIS_LR("f_pinky.03.L", "f_pinky.03.R", "carpal_distal_interphalangeal_5"),
    THESPIS_LR("thigh.L", "thigh.R", "hip"),
    THESPIS_LR_NONE("thigh.L.001", "thigh.R.001"),
    THESPIS_LR("shin.L", "shin.R", "knee"),
    THESPIS_LR_NONE("shin.L.001", "shin.R.001"),
    THESPIS_LR("foot.L", "foot.R", "talocrural"),
    THESPIS_LR("toe.L", "toe.R", "metatarsophalangeal"),
};

// Quaternius' robot rig (three.js' RobotExpressive, through FBX2glTF). "Bone" is the armature
// root on the floor; "Body" carries the legs and the spine; the feet are IK controls under
// "Bone" (the hierarchy check drops their names); the hands have no wrist joint.
constexpr NameEntry kQuaternius[] = {
    {"Bone", ""},
    {"Body", "humanoid_root"},
    {"Hips", "vl5"},
    {"Abdomen", "vl1"},
    {"Torso", "vt6"},
    {"Neck", "vc4"},
    {"Head", "skullbase"},
    THESPIS_LR("Shoulder.L", "Shoulder.R", "sternoclavicular"),
    THESPIS_LR("UpperArm.L", "UpperArm.R", "shoulder"),
    THESPIS_LR("LowerArm.L", "LowerArm.R", "elbow"),
    THESPIS_LR("Thumb.L", "Thumb.R", "carpometacarpal_1"),
    THESPIS_LR("Thumb2.L", "Thumb2.R", "metacarpophalangeal_1"),
    THESPIS_LR("Palm1.L", "Palm1.R", "carpometacarpal_2"),
    THESPIS_LR("Index.L", "Index.R", "metacarpophalangeal_2"),
    THESPIS_LR("Index2.L", "Index2.R", "carpal_proximal_interphalangeal_2"),
    THESPIS_LR("Palm2.L", "Palm2.R", "carpometacarpal_3"),
    THESPIS_LR("Middle1.L", "Middle1.R", "metacarpophalangeal_3"),
    THESPIS_LR("Middle2.L", "Middle2.R", "carpal_proximal_interphalangeal_3"),
    THESPIS_LR("Palm3.L", "Palm3.R", "carpometacarpal_4"),
    THESPIS_LR("Ring1.L", "Ring1.R", "metacarpophalangeal_4"),
    THESPIS_LR("Ring2.L", "Ring2.R", "carpal_proximal_interphalangeal_4"),
    THESPIS_LR("UpperLeg.L", "UpperLeg.R", "hip"),
    THESPIS_LR("LowerLeg.L", "LowerLeg.R", "knee"),
    THESPIS_LR("Foot.L", "Foot.R", "talocrural"),
    THESPIS_LR_NONE("PoleTarget.L", "PoleTarget.R"),
};

/// The comparison key of a name: lower case, with '.', '-', ' ' and '|' read as '_'.
std::string nameKey(std::string_view name)
{
    std::string key(name);
    for (char& c : key) {
        c = char(std::tolower(static_cast<unsigned char>(c)));
        if (c == '.' || c == '-' || c == ' ' || c == '|')
            c = '_';
    }
    return key;
}

/// The name without namespace ("mixamorig:") and exporter prefixes ("mixamorig_", "Armature_",
/// "DEF-").
std::string_view strippedName(std::string_view name)
{
    name = anim::bvh::naming::stripNamespace(name);
    for (std::string_view prefix : {"mixamorig_", "armature_", "def_"})
        if (name.size() > prefix.size() && nameKey(name.substr(0, prefix.size())) == prefix)
            return name.substr(prefix.size());
    return name;
}

/// The H-Anim 2.0 name when `name` is an H-Anim 1.1 or 2.0 joint name, else "".
std::string hanimNameOf(std::string_view name)
{
    for (const std::string& candidate : {std::string(name), nameKey(name)}) {
        const std::string_view current = anim::hanim::fromHAnim11(candidate);
        if (anim::hanim::isJointName(current))
            return std::string(current);
    }
    return {};
}

/// A naming convention as a table from name key to H-Anim name ("" for names it knows but
/// leaves unmapped).
struct KeyedConvention {
    std::string id;
    std::map<std::string, std::string> names;
};

/// Every convention, in the order a name on its own asks them (and ties are broken).
const std::vector<KeyedConvention>& conventions()
{
    static const std::vector<KeyedConvention> all = [] {
        std::vector<std::pair<std::string, std::span<const NameEntry>>> ordered;
        const auto motionCapture = anim::bvh::naming::conventions();
        auto add = [&](std::string_view id, std::span<const NameEntry> entries) {
            ordered.emplace_back(std::string(id), entries);
        };
        for (const auto& convention : motionCapture)
            if (convention.id == "mixamo")
                add(convention.id, convention.entries);
        add("unity", kUnity);
        add("blender", kBlender);
        add("rigify", kRigify);
        add("quaternius", kQuaternius);
        for (const auto& convention : motionCapture)
            if (convention.id != "mixamo")
                add(convention.id, convention.entries);
        std::vector<KeyedConvention> keyed;
        for (const auto& [id, entries] : ordered) {
            KeyedConvention convention{id, {}};
            for (const NameEntry& entry : entries)
                convention.names.emplace(nameKey(entry.file), std::string(entry.hanim)); // first spelling wins
            keyed.push_back(std::move(convention));
        }
        return keyed;
    }();
    return all;
}

/// The names one convention gives a rig, when it knows enough of them (at least 4 and a quarter,
/// as for BVH files): the one that knows most wins. Empty when none does.
std::vector<std::string> namesByConvention(const std::vector<std::string>& sources)
{
    const int minimum = std::max(4, int((sources.size() + 3) / 4));
    std::vector<std::string> best;
    int bestKnown = 0;
    auto consider = [&](int known, std::vector<std::string> names) {
        if (known > bestKnown && known >= minimum) {
            bestKnown = known;
            best = std::move(names);
        }
    };
    {
        std::vector<std::string> names;
        int known = 0;
        for (const std::string& source : sources) {
            names.push_back(hanimNameOf(strippedName(source)));
            known += names.back().empty() ? 0 : 1;
        }
        consider(known, std::move(names));
    }
    for (const KeyedConvention& convention : conventions()) {
        std::vector<std::string> names;
        int known = 0;
        for (const std::string& source : sources) {
            const auto found = convention.names.find(nameKey(strippedName(source)));
            names.push_back(found == convention.names.end() ? std::string() : found->second);
            known += found == convention.names.end() ? 0 : 1;
        }
        consider(known, std::move(names));
    }
    return best;
}

// ---- naming a humanoid by its shape ------------------------------------------------------------

/// A skeleton's rest pose seen from above: children, and per joint the lowest and highest point
/// and the centre of the joints below it (itself included). +Y is up.
class RestShape {
public:
    RestShape(const std::vector<int>& parents, const std::vector<Vec3d>& positions)
        : m_positions(positions), m_children(parents.size()), m_low(parents.size()), m_high(parents.size()),
          m_centre(parents.size()), m_count(parents.size(), 1)
    {
        for (std::size_t j = 0; j < parents.size(); ++j) {
            m_low[j] = m_high[j] = positions[j].y;
            m_centre[j] = positions[j];
            if (parents[j] >= 0)
                m_children[std::size_t(parents[j])].push_back(int(j));
        }
        for (std::size_t j = parents.size(); j-- > 1;) { // parents come first: children are done
            const auto p = std::size_t(parents[j]);
            m_low[p] = std::min(m_low[p], m_low[j]);
            m_high[p] = std::max(m_high[p], m_high[j]);
            m_centre[p] = m_centre[p] + m_centre[j];
            m_count[p] += m_count[j];
        }
        for (std::size_t j = 0; j < parents.size(); ++j)
            m_centre[j] = m_centre[j] * (1.0 / m_count[j]);
    }

    const Vec3d& position(int j) const { return m_positions[std::size_t(j)]; }
    const std::vector<int>& children(int j) const { return m_children[std::size_t(j)]; }
    double low(int j) const { return m_low[std::size_t(j)]; }
    double high(int j) const { return m_high[std::size_t(j)]; }
    const Vec3d& centre(int j) const { return m_centre[std::size_t(j)]; }

    /// From `j` down the child that reaches lowest, `length` joints at most.
    std::vector<int> chainDown(int j, std::size_t length) const
    {
        std::vector<int> chain{j};
        while (chain.size() < length && !children(chain.back()).empty()) {
            const auto& next = children(chain.back());
            chain.push_back(*std::min_element(next.begin(), next.end(), [&](int a, int b) { return low(a) < low(b); }));
        }
        return chain;
    }
    /// From `j` down through single children, up to the first joint that branches (a hand into
    /// fingers) or ends.
    std::vector<int> limb(int j) const
    {
        std::vector<int> chain{j};
        while (children(chain.back()).size() == 1)
            chain.push_back(children(chain.back()).front());
        return chain;
    }

private:
    const std::vector<Vec3d>& m_positions;
    std::vector<std::vector<int>> m_children;
    std::vector<double> m_low, m_high;
    std::vector<Vec3d> m_centre;
    std::vector<int> m_count;
};

double dot3(const Vec3d& a, const Vec3d& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }

/// H-Anim names for a humanoid rig whose joint names say nothing, from its rest shape (see the
/// header). Joints it cannot place keep "" ; all "" when there is no pelvis with two legs and a
/// spine.
std::vector<std::string> namesByShape(const std::vector<int>& parents, const std::vector<Vec3d>& positions)
{
    std::vector<std::string> names(parents.size());
    if (parents.empty())
        return names;
    const RestShape shape(parents, positions);
    const double height = shape.high(0) - shape.low(0);
    if (!(height > 0))
        return names;

    // The pelvis: the first joint with two children reaching well down (legs) and one reaching
    // well up (spine).
    int pelvis = -1;
    std::vector<int> legs, spines;
    for (int j = 0; j < int(parents.size()) && pelvis < 0; ++j) {
        const double y = shape.position(j).y;
        legs.clear();
        spines.clear();
        for (int c : shape.children(j)) {
            if (y - shape.low(c) > 0.2 * height && shape.high(c) - y < 0.1 * height)
                legs.push_back(c);
            else if (shape.high(c) - y > 0.2 * height && y - shape.low(c) < 0.1 * height)
                spines.push_back(c);
        }
        if (legs.size() >= 2 && !spines.empty())
            pelvis = j;
    }
    if (pelvis < 0)
        return names;
    std::sort(legs.begin(), legs.end(), [&](int a, int b) { return shape.low(a) < shape.low(b); });
    legs.resize(2);
    const int spineStart =
        *std::max_element(spines.begin(), spines.end(), [&](int a, int b) { return shape.high(a) < shape.high(b); });

    // Facing: where the toes point (glTF's +Z when the legs end at the ankles); left = up × forward.
    std::vector<int> legChains[2] = {shape.chainDown(legs[0], 4), shape.chainDown(legs[1], 4)};
    Vec3d forward{0, 0, 0};
    for (const auto& chain : legChains)
        if (chain.size() == 4)
            forward = forward + (shape.position(chain[3]) - shape.position(chain[2]));
    forward.y = 0;
    if (std::hypot(forward.x, forward.z) < 1e-3 * height)
        forward = {0, 0, 1};
    const Vec3d left{forward.z, 0, -forward.x};
    auto sideOf = [&](int first, int second, int from) {
        const Vec3d origin = shape.position(from);
        const bool firstIsLeft = dot3(shape.centre(first) - origin, left) >= dot3(shape.centre(second) - origin, left);
        return firstIsLeft ? std::pair{first, second} : std::pair{second, first};
    };

    names[std::size_t(pelvis)] = "humanoid_root";
    const auto [leftLeg, rightLeg] = sideOf(legs[0], legs[1], pelvis);
    for (const auto& [leg, side] : {std::pair{leftLeg, "l_"}, std::pair{rightLeg, "r_"}}) {
        const char* const kLeg[] = {"hip", "knee", "talocrural", "metatarsophalangeal"};
        const std::vector<int> chain = shape.chainDown(leg, 4);
        for (std::size_t i = 0; i < chain.size(); ++i)
            names[std::size_t(chain[i])] = std::string(side) + kLeg[i];
    }

    // The spine up to the joint where the arms and the neck branch.
    std::vector<int> spine{spineStart};
    while (shape.children(spine.back()).size() < 3) {
        const auto& next = shape.children(spine.back());
        if (next.empty())
            return names; // no arms: legs only
        spine.push_back(
            *std::max_element(next.begin(), next.end(), [&](int a, int b) { return shape.high(a) < shape.high(b); }));
    }
    const int chest = spine.back();
    std::vector<int> branches = shape.children(chest);
    auto lateral = [&](int c) { return std::abs(dot3(shape.centre(c) - shape.position(chest), left)); };
    std::sort(branches.begin(), branches.end(), [&](int a, int b) { return lateral(a) > lateral(b); });
    const auto [leftArm, rightArm] = sideOf(branches[0], branches[1], chest);
    const int neck = *std::max_element(branches.begin() + 2, branches.end(),
                                       [&](int a, int b) { return shape.high(a) < shape.high(b); });

    // Vertebrae of the paper's joint set, chosen by height between the root and the neck as in
    // the H-Anim rest pose, in order.
    const anim::Skeleton& standard = anim::hanim::skeleton(anim::hanim::Level::Subset25);
    const std::vector<Vec3d> standardPositions = standard.worldPositions(standard.restFrame());
    auto standardHeight = [&](const char* joint) { return standardPositions[std::size_t(standard.find(joint))].y; };
    const double rootY = standardHeight("humanoid_root"), neckY = standardHeight("vc4");
    const char* const kVertebrae[] = {"vl5", "vl1", "vt10", "vt6", "vt1"};
    const double pelvisY = shape.position(pelvis).y, spineTop = shape.position(neck).y - pelvisY;
    auto standardFraction = [&](std::size_t v) { return (standardHeight(kVertebrae[v]) - rootY) / (neckY - rootY); };
    std::size_t nextVertebra = 0;
    for (std::size_t i = 0; i < spine.size() && spineTop > 0 && nextVertebra < std::size(kVertebrae); ++i) {
        const double fraction = (shape.position(spine[i]).y - pelvisY) / spineTop;
        std::size_t best = nextVertebra;
        for (std::size_t v = nextVertebra; v < std::size(kVertebrae); ++v)
            if (std::abs(standardFraction(v) - fraction) < std::abs(standardFraction(best) - fraction))
                best = v;
        names[std::size_t(spine[i])] = kVertebrae[best];
        nextVertebra = best + 1;
    }

    const std::vector<int> neckChain = shape.limb(neck);
    if (neckChain.size() == 1)
        names[std::size_t(neckChain[0])] = "skullbase";
    else if (neckChain.size() >= 2) {
        names[std::size_t(neckChain[0])] = "vc4";
        names[std::size_t(neckChain[1])] = "skullbase";
    }
    for (const auto& [arm, side] : {std::pair{leftArm, "l_"}, std::pair{rightArm, "r_"}}) {
        const std::vector<int> chain = shape.limb(arm);
        const bool clavicle = chain.size() >= 4;
        const char* const kArm[] = {"sternoclavicular", "shoulder", "elbow", "radiocarpal"};
        for (std::size_t i = 0; i < chain.size() && i + (clavicle ? 0 : 1) < 4; ++i)
            names[std::size_t(chain[i])] = std::string(side) + kArm[i + (clavicle ? 0 : 1)];
    }
    return names;
}

std::string joinedList(const std::vector<std::string>& items)
{
    std::string list;
    for (const std::string& item : items)
        list += (list.empty() ? "" : ", ") + item;
    return list;
}

/// True when H-Anim joint `ancestor` is above `joint` in the H-Anim hierarchy.
bool isHAnimAncestor(std::string_view ancestor, std::string_view joint)
{
    for (std::string_view p = anim::hanim::parentName(joint); !p.empty(); p = anim::hanim::parentName(p))
        if (p == ancestor)
            return true;
    return false;
}

/// Drops automatic names that break the H-Anim hierarchy: a joint's nearest named ancestor must
/// be an H-Anim ancestor of its name (a joint with none must be the root, unless no joint is).
void dropMisplacedNames(const std::vector<int>& parents, const std::vector<std::string>& sources,
                        std::vector<std::string>& names, std::vector<std::string>& warnings)
{
    const bool hasRoot = std::find(names.begin(), names.end(), "humanoid_root") != names.end();
    std::vector<std::string> dropped;
    for (std::size_t j = 0; j < names.size(); ++j) {
        if (names[j].empty())
            continue;
        int ancestor = parents[j];
        while (ancestor >= 0 && names[std::size_t(ancestor)].empty())
            ancestor = parents[std::size_t(ancestor)];
        const bool placed = ancestor >= 0 ? isHAnimAncestor(names[std::size_t(ancestor)], names[j])
                                          : names[j] == "humanoid_root" || !hasRoot;
        if (!placed) {
            dropped.push_back(sources[j] + " (" + names[j] + ")");
            names[j].clear();
        }
    }
    if (!dropped.empty())
        warnings.push_back("These joints are not where their H-Anim name belongs in the hierarchy and keep their own "
                           "names: " + joinedList(dropped) + ".");
}

/// Final joint names: the user's table, else the automatic names; unique; the rest keep their
/// source names. Warns about what did not map.
std::vector<std::string> jointNames(const std::vector<std::string>& sources, const std::vector<int>& parents,
                                    const std::vector<Vec3d>& positions, const GltfCharacterOptions& options,
                                    std::vector<std::string>& warnings)
{
    std::vector<std::string> automatic(sources.size());
    if (options.automaticMapping) {
        automatic = namesByConvention(sources);
        if (automatic.empty())
            automatic = namesByShape(parents, positions);
        if (std::all_of(automatic.begin(), automatic.end(), [](const std::string& n) { return n.empty(); }))
            for (std::size_t j = 0; j < sources.size(); ++j)
                automatic[j] = automaticHAnimName(sources[j]);
        dropMisplacedNames(parents, sources, automatic, warnings);
    }

    std::vector<std::string> unknown;
    for (const auto& [source, target] : options.jointMapping)
        if (std::find(sources.begin(), sources.end(), source) == sources.end())
            unknown.push_back(source);
    if (!unknown.empty())
        warnings.push_back("The joint mapping names joints the file does not have: " + joinedList(unknown) + ".");

    // The user's names first, then the automatic ones, each in joint order: the first keeps a name.
    std::vector<std::string> names(sources.size());
    std::set<std::string> used;
    std::vector<std::string> duplicates;
    for (bool fromUser : {true, false})
        for (std::size_t j = 0; j < sources.size(); ++j) {
            const auto user = options.jointMapping.find(sources[j]);
            if ((user != options.jointMapping.end()) != fromUser)
                continue;
            const std::string& wanted = fromUser ? user->second : automatic[j];
            if (wanted.empty())
                continue;
            if (used.insert(wanted).second)
                names[j] = wanted;
            else
                duplicates.push_back(sources[j] + " (" + wanted + ")");
        }
    if (!duplicates.empty())
        warnings.push_back("These joints map to an H-Anim name another joint already has and keep their own names: " +
                           joinedList(duplicates) + ".");

    std::vector<std::string> unmapped;
    for (std::size_t j = 0; j < sources.size(); ++j) {
        if (!names[j].empty())
            continue;
        unmapped.push_back(sources[j]);
        std::string name = sources[j];
        for (int suffix = 2; used.count(name) > 0; ++suffix)
            name = sources[j] + "#" + std::to_string(suffix);
        used.insert(name);
        names[j] = name;
    }
    if (!unmapped.empty())
        warnings.push_back(std::to_string(unmapped.size()) + " of " + std::to_string(sources.size()) +
                           " joints have no H-Anim name and keep their own: " + joinedList(unmapped) + ".");
    return names;
}

// ==== the skeleton =================================================================================

/// The glTF nodes that become joints, parents first, and the way back.
struct SkeletonNodes {
    std::vector<int> nodes;       ///< joint → node
    std::vector<int> jointOfNode; ///< node → joint, -1 for other nodes
};

/// Every skin joint, the nodes between them and their nearest common node (the root).
Result<SkeletonNodes> skeletonNodes(const tinygltf::Model& model, const gltf::NodeTree& tree,
                                    const gltf::AccessorReader& reader)
{
    SkeletonNodes skeleton;
    skeleton.jointOfNode.assign(model.nodes.size(), -1);
    std::vector<bool> member(model.nodes.size(), false);
    std::vector<int> joints;
    for (std::size_t s = 0; s < model.skins.size(); ++s)
        for (int joint : model.skins[s].joints) {
            if (joint < 0 || std::size_t(joint) >= model.nodes.size())
                return reader.broken("skin " + std::to_string(s) + " names joint node " + std::to_string(joint) +
                                     ", which does not exist");
            if (!member[std::size_t(joint)])
                joints.push_back(joint);
            member[std::size_t(joint)] = true;
        }
    if (joints.empty())
        return skeleton;

    auto depth = [&](int n) {
        int d = 0;
        for (; tree.parent[std::size_t(n)] >= 0; n = tree.parent[std::size_t(n)])
            ++d;
        return d;
    };
    auto commonAncestor = [&](int a, int b) {
        int da = depth(a), db = depth(b);
        for (; da > db; --da)
            a = tree.parent[std::size_t(a)];
        for (; db > da; --db)
            b = tree.parent[std::size_t(b)];
        while (a != b && a >= 0) {
            a = tree.parent[std::size_t(a)];
            b = tree.parent[std::size_t(b)];
        }
        return a;
    };
    int root = joints.front();
    for (int joint : joints)
        if ((root = commonAncestor(root, joint)) < 0)
            return reader.broken("the joints of its skins are not under one common node");
    for (int joint : joints)
        for (int n = joint; n != root; n = tree.parent[std::size_t(n)])
            member[std::size_t(n)] = true;
    member[std::size_t(root)] = true;

    // Depth first from the root, children in file order: parents come first.
    std::vector<int> stack{root};
    while (!stack.empty()) {
        const int n = stack.back();
        stack.pop_back();
        skeleton.jointOfNode[std::size_t(n)] = int(skeleton.nodes.size());
        skeleton.nodes.push_back(n);
        const std::vector<int>& children = model.nodes[std::size_t(n)].children;
        for (auto c = children.rbegin(); c != children.rend(); ++c)
            if (member[std::size_t(*c)])
                stack.push_back(*c);
    }
    return skeleton;
}

/// The rest world transform of a node's parent (identity for a scene root).
Mat4 parentWorld(const gltf::NodeTree& tree, int node)
{
    const int parent = tree.parent[std::size_t(node)];
    return parent < 0 ? gltf::kIdentity : tree.world[std::size_t(parent)];
}

Vec3d translationOf(const Mat4& m) { return {m[12], m[13], m[14]}; }

/// A node's rest rotation in its parent.
Quatd restRotation(const tinygltf::Node& node)
{
    if (node.matrix.size() == 16)
        return gltf::rotationOf(gltf::localMatrix(node));
    if (node.rotation.size() == 4)
        return anim::normalize(Quatd{node.rotation[0], node.rotation[1], node.rotation[2], node.rotation[3]});
    return {};
}

Vec3d restTranslation(const tinygltf::Node& node)
{
    if (node.matrix.size() == 16)
        return {node.matrix[12], node.matrix[13], node.matrix[14]};
    if (node.translation.size() == 3)
        return {node.translation[0], node.translation[1], node.translation[2]};
    return {};
}

// ==== animations =================================================================================

enum class Interpolation { Linear, Step, CubicSpline };
enum class Path { Translation, Rotation };

/// One imported channel: a joint's translation or rotation keys.
struct Track {
    int joint = 0;
    Path path = Path::Rotation;
    Interpolation interpolation = Interpolation::Linear;
    std::vector<double> times;
    gltf::AccessorData values; ///< per key (×3 for CUBICSPLINE: in-tangent, value, out-tangent)

    int components() const { return values.components; }
    /// The value of key k (its middle element for CUBICSPLINE), component c.
    double key(std::size_t k, int c) const
    {
        return interpolation == Interpolation::CubicSpline ? values(3 * k + 1, c) : values(k, c);
    }

    /// The channel's value at time t (glTF's interpolation; held before the first and after the
    /// last key).
    std::array<double, 4> sample(double t) const
    {
        std::array<double, 4> out{};
        const std::size_t n = times.size();
        auto keyValue = [&](std::size_t k) {
            std::array<double, 4> v{};
            for (int c = 0; c < components(); ++c)
                v[std::size_t(c)] = key(k, c);
            return v;
        };
        if (t <= times.front())
            return keyValue(0);
        if (t >= times.back())
            return keyValue(n - 1);
        const std::size_t k = std::size_t(std::upper_bound(times.begin(), times.end(), t) - times.begin()) - 1;
        const double span = times[k + 1] - times[k];
        if (!(span > 0))
            return keyValue(k + 1);
        const double u = (t - times[k]) / span;
        switch (interpolation) {
        case Interpolation::Step: return keyValue(k);
        case Interpolation::Linear: {
            const std::array<double, 4> a = keyValue(k), b = keyValue(k + 1);
            if (path == Path::Rotation) {
                const Quatd q = anim::slerp(anim::normalize(Quatd{a[0], a[1], a[2], a[3]}),
                                            anim::normalize(Quatd{b[0], b[1], b[2], b[3]}), u);
                return {q.x, q.y, q.z, q.w};
            }
            for (std::size_t c = 0; c < 4; ++c)
                out[c] = a[c] + (b[c] - a[c]) * u;
            return out;
        }
        case Interpolation::CubicSpline: {
            // Hermite: p(u) = h00·v_k + h10·Δ·b_k + h01·v_k+1 + h11·Δ·a_k+1 (glTF 2.0, Appendix C).
            const double u2 = u * u, u3 = u2 * u;
            const double h00 = 2 * u3 - 3 * u2 + 1, h10 = u3 - 2 * u2 + u, h01 = -2 * u3 + 3 * u2, h11 = u3 - u2;
            for (int c = 0; c < components(); ++c)
                out[std::size_t(c)] = h00 * values(3 * k + 1, c) + h10 * span * values(3 * k + 2, c) +
                                      h01 * values(3 * k + 4, c) + h11 * span * values(3 * k + 3, c);
            if (path == Path::Rotation) {
                const Quatd q = anim::normalize(Quatd{out[0], out[1], out[2], out[3]});
                return {q.x, q.y, q.z, q.w};
            }
            return out;
        }
        }
        return out;
    }
};

struct Animation {
    std::string name;
    double duration = 0;
    std::vector<Track> tracks;
};

/// Nodes whose channels are not imported, by reason, for one warning each.
struct IgnoredChannels {
    std::set<std::string> scale, weights, outsideSkeleton;
};

/// Reads every animation's channels on skeleton joints. Structural errors (missing samplers,
/// accessors of the wrong shape, times out of order) refuse the file.
Result<std::vector<Animation>> readAnimations(const tinygltf::Model& model, const gltf::AccessorReader& reader,
                                              const SkeletonNodes& skeleton, IgnoredChannels& ignored)
{
    std::vector<Animation> animations;
    for (std::size_t a = 0; a < model.animations.size(); ++a) {
        const tinygltf::Animation& source = model.animations[a];
        Animation animation;
        animation.name = source.name.empty() ? "animation" + std::to_string(a) : source.name;
        const std::string use = "animation \"" + animation.name + "\"";
        for (std::size_t c = 0; c < source.channels.size(); ++c) {
            const tinygltf::AnimationChannel& channel = source.channels[c];
            const std::string channelUse = use + " channel " + std::to_string(c);
            if (channel.sampler < 0 || std::size_t(channel.sampler) >= source.samplers.size())
                return reader.broken(channelUse + " names a sampler that does not exist");
            if (channel.target_node < 0 || std::size_t(channel.target_node) >= model.nodes.size())
                continue; // no target node: the channel animates something outside the nodes (an extension)
            const std::string nodeLabel = gltf::nodeName(model, channel.target_node);
            const tinygltf::AnimationSampler& sampler = source.samplers[std::size_t(channel.sampler)];
            Result<gltf::AccessorData> input = reader.read(sampler.input, channelUse + " times");
            if (!input)
                return input.error();
            if (input->components != 1 || input->count == 0)
                return reader.broken(channelUse + " times are not a non-empty list of scalars");
            for (std::size_t k = 0; k < input->count; ++k)
                if (!std::isfinite(input->values[k]) || input->values[k] < 0 ||
                    (k > 0 && input->values[k] < input->values[k - 1]))
                    return reader.broken(channelUse + " has key times that are negative, not finite or out of order");
            animation.duration = std::max(animation.duration, input->values.back());

            Track track;
            if (channel.target_path == "rotation")
                track.path = Path::Rotation;
            else if (channel.target_path == "translation")
                track.path = Path::Translation;
            else {
                if (channel.target_path == "weights")
                    ignored.weights.insert(nodeLabel);
                else if (channel.target_path == "scale") {
                    // Files often key a constant scale (COLLADA2GLTF keys every channel): only a
                    // scale that changes the node is worth a warning.
                    Result<gltf::AccessorData> output = reader.read(sampler.output, channelUse + " values");
                    if (!output)
                        return output.error();
                    const std::vector<double>& rest = model.nodes[std::size_t(channel.target_node)].scale;
                    const bool cubic = sampler.interpolation == "CUBICSPLINE"; // keys between their tangents
                    for (std::size_t i = cubic ? 3 : 0; i < output->values.size(); i += cubic ? 9 : 3)
                        for (std::size_t axis = 0; axis < 3 && i + axis < output->values.size(); ++axis) {
                            const double expected = rest.size() == 3 ? rest[axis] : 1.0;
                            if (std::abs(output->values[i + axis] - expected) > 1e-4 * std::max(1.0, std::abs(expected)))
                                ignored.scale.insert(nodeLabel);
                        }
                }
                continue;
            }
            const int joint = skeleton.jointOfNode[std::size_t(channel.target_node)];
            if (joint < 0) {
                ignored.outsideSkeleton.insert(nodeLabel);
                continue;
            }
            track.joint = joint;
            if (sampler.interpolation == "STEP")
                track.interpolation = Interpolation::Step;
            else if (sampler.interpolation == "CUBICSPLINE")
                track.interpolation = Interpolation::CubicSpline;
            else if (sampler.interpolation.empty() || sampler.interpolation == "LINEAR")
                track.interpolation = Interpolation::Linear;
            else
                return reader.broken(channelUse + " has an unknown interpolation \"" + sampler.interpolation + "\"");
            Result<gltf::AccessorData> output = reader.read(sampler.output, channelUse + " values");
            if (!output)
                return output.error();
            const int components = track.path == Path::Rotation ? 4 : 3;
            const std::size_t perKey = track.interpolation == Interpolation::CubicSpline ? 3 : 1;
            if (output->components != components || output->count != input->count * perKey)
                return reader.broken(channelUse + " values do not hold one " +
                                     (track.path == Path::Rotation ? std::string("quaternion") : "3D vector") +
                                     (perKey == 3 ? " and two tangents" : "") + " per key");
            for (double v : output->values)
                if (!std::isfinite(v))
                    return reader.broken(channelUse + " has a value that is not finite");
            track.times = std::move(input->values);
            track.values = std::move(*output);
            animation.tracks.push_back(std::move(track));
        }
        animations.push_back(std::move(animation));
    }

    // COLLADA2GLTF writes one unnamed animation per node: they are parts of one motion.
    const bool allUnnamed = std::all_of(model.animations.begin(), model.animations.end(),
                                        [](const tinygltf::Animation& a) { return a.name.empty(); });
    std::set<std::pair<int, std::string>> targets;
    bool disjoint = true;
    for (const tinygltf::Animation& animation : model.animations)
        for (const tinygltf::AnimationChannel& channel : animation.channels)
            disjoint = disjoint && targets.emplace(channel.target_node, channel.target_path).second;
    if (animations.size() > 1 && allUnnamed && disjoint) {
        Animation merged;
        merged.name = "animation";
        for (Animation& part : animations) {
            merged.duration = std::max(merged.duration, part.duration);
            std::move(part.tracks.begin(), part.tracks.end(), std::back_inserter(merged.tracks));
        }
        animations.assign(1, std::move(merged));
    }
    return animations;
}

/// True when a translation track moves its joint off the rest offset by more than `tolerance`
/// (in world units, through the parent's rest transform).
bool movesJoint(const Track& track, const Vec3d& rest, const Mat4& parent, double tolerance)
{
    if (track.interpolation == Interpolation::CubicSpline)
        return true; // tangents may move it between keys
    for (std::size_t k = 0; k < track.times.size(); ++k) {
        const Vec3d key{track.key(k, 0), track.key(k, 1), track.key(k, 2)};
        const Vec3d offset = gltf::transformVector(parent, key - rest);
        if (std::sqrt(dot3(offset, offset)) > tolerance)
            return true;
    }
    return false;
}

// ==== materials and textures =====================================================================

/// A decoded glTF image as RGBA8, or nullopt when it holds no pixels we can read.
std::optional<TextureImage> textureOf(const tinygltf::Image& image, int index)
{
    const int channels = image.component;
    const int bytes = image.bits / 8;
    if (image.width <= 0 || image.height <= 0 || channels < 1 || channels > 4 || (bytes != 1 && bytes != 2))
        return std::nullopt;
    const std::size_t pixels = std::size_t(image.width) * std::size_t(image.height);
    if (image.image.size() != pixels * std::size_t(channels * bytes))
        return std::nullopt;
    TextureImage texture;
    texture.name = !image.name.empty() ? image.name : !image.uri.empty() ? image.uri : "image" + std::to_string(index);
    texture.width = image.width;
    texture.height = image.height;
    texture.rgba.resize(pixels * 4);
    for (std::size_t p = 0; p < pixels; ++p) {
        std::uint8_t value[4] = {0, 0, 0, 255};
        for (int c = 0; c < channels; ++c) // 16-bit samples are little endian: keep the high byte
            value[c] = image.image[(p * std::size_t(channels) + std::size_t(c)) * std::size_t(bytes) +
                                   std::size_t(bytes - 1)];
        if (channels <= 2) { // grey, grey + alpha
            value[3] = channels == 2 ? value[1] : 255;
            value[1] = value[2] = value[0];
        }
        std::copy(value, value + 4, texture.rgba.begin() + std::ptrdiff_t(p * 4));
    }
    return texture;
}

/// Every glTF material (same indices), with the base colour textures decoded into `character`.
void readMaterials(const tinygltf::Model& model, bool loadTextures, Character& character)
{
    std::map<int, int> textureOfImage;
    for (std::size_t m = 0; m < model.materials.size(); ++m) {
        const tinygltf::Material& source = model.materials[m];
        Material material;
        material.name = source.name.empty() ? "material" + std::to_string(m) : source.name;
        const std::vector<double>& factor = source.pbrMetallicRoughness.baseColorFactor;
        material.baseColor = {1, 1, 1, 1}; // glTF's default factor
        if (factor.size() == 4)
            for (std::size_t c = 0; c < 4; ++c)
                material.baseColor[c] = float(factor[c]);
        const int texture = source.pbrMetallicRoughness.baseColorTexture.index;
        if (loadTextures && texture >= 0) {
            const int image =
                std::size_t(texture) < model.textures.size() ? model.textures[std::size_t(texture)].source : -1;
            if (const auto found = textureOfImage.find(image); found != textureOfImage.end())
                material.baseColorTexture = found->second;
            else if (std::optional<TextureImage> decoded =
                         image >= 0 && std::size_t(image) < model.images.size()
                             ? textureOf(model.images[std::size_t(image)], image)
                             : std::nullopt) {
                material.baseColorTexture = int(character.textures.size());
                textureOfImage.emplace(image, material.baseColorTexture);
                character.textures.push_back(std::move(*decoded));
            } else
                character.warnings.push_back("Material \"" + material.name +
                                             "\" goes without its base colour texture, whose image could not be read.");
        }
        character.materials.push_back(std::move(material));
    }
}

// ==== assembling the character ===================================================================

/// What the import has read of the file, shared by the steps below.
struct Import {
    const gltf::File& file;
    const gltf::AccessorReader& reader;
    const gltf::NodeTree& tree;
    const SkeletonNodes& nodes;
    const GltfCharacterOptions& options;
    const tinygltf::Model& model() const { return file.model; }
};

/// The skeleton of the skin joints (named, see jointNames), with `translates` set for joints
/// whose animation moves them off their rest offsets.
Result<anim::Skeleton> buildSkeleton(const Import& import, const std::vector<Animation>& animations,
                                     std::vector<std::string>& warnings)
{
    const std::vector<int>& nodes = import.nodes.nodes;
    std::vector<std::string> sources;
    std::vector<int> parents;
    std::vector<Vec3d> positions;
    for (int node : nodes) {
        sources.push_back(gltf::nodeName(import.model(), node));
        const int parentNode = import.tree.parent[std::size_t(node)];
        parents.push_back(parentNode < 0 ? -1 : import.nodes.jointOfNode[std::size_t(parentNode)]);
        positions.push_back(translationOf(import.tree.world[std::size_t(node)]));
        const Vec3d& p = positions.back();
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
            return import.reader.broken("joint " + sources.back() + " has a rest position that is not finite");
    }
    const std::vector<std::string> names = jointNames(sources, parents, positions, import.options, warnings);

    // Translation channels that keep a joint at its rest offset (COLLADA2GLTF keys every joint's
    // translation) leave it a fixed bone: they may differ from the rest by rounding only.
    double extent = 0;
    for (const Vec3d& p : positions)
        extent = std::max(extent, std::sqrt(dot3(p - positions[0], p - positions[0])));
    const double tolerance = 1e-5 * std::max(1.0, extent);
    std::vector<bool> translates(nodes.size(), false);
    for (const Animation& animation : animations)
        for (const Track& track : animation.tracks) {
            const int node = nodes[std::size_t(track.joint)];
            if (track.path == Path::Translation &&
                movesJoint(track, restTranslation(import.model().nodes[std::size_t(node)]),
                           parentWorld(import.tree, node), tolerance))
                translates[std::size_t(track.joint)] = true;
        }

    std::vector<anim::Joint> joints;
    for (std::size_t j = 0; j < nodes.size(); ++j) {
        anim::Joint joint;
        joint.name = names[j];
        joint.sourceName = sources[j];
        joint.parent = parents[j];
        joint.offset = parents[j] < 0 ? positions[j] : positions[j] - positions[std::size_t(parents[j])];
        joint.translates = translates[j];
        joints.push_back(std::move(joint));
    }
    Result<anim::Skeleton> skeleton = anim::Skeleton::create(std::move(joints));
    if (!skeleton)
        return makeError(ErrorCode::Internal, "The skeleton read from " + import.file.name + " is inconsistent.",
                         skeleton.error().message);
    return skeleton;
}

/// Points every segment at the skeleton joint at or above the node it follows (the root when
/// none is), with that joint's default posture; returns the joint of each segment.
std::vector<int> followJoints(const Import& import, const std::vector<gltf::SegmentSource>& sources,
                              Character& character)
{
    std::vector<int> segmentJoint(character.mesh.segments.size(), 0);
    std::vector<std::string> mixed;
    for (std::size_t s = 0; s < character.mesh.segments.size(); ++s) {
        for (int n = sources[s].jointNode; n >= 0; n = import.tree.parent[std::size_t(n)])
            if (const int joint = import.nodes.jointOfNode[std::size_t(n)]; joint >= 0) {
                segmentJoint[s] = joint;
                break;
            }
        Segment& segment = character.mesh.segments[s];
        segment.joint = character.skeleton.joint(segmentJoint[s]).name;
        segment.posture = defaultPosture(segment.joint);
        if (sources[s].mixedMaterials)
            mixed.push_back(segment.name);
    }
    if (!mixed.empty())
        character.warnings.push_back("These segments mix several materials and show the first one only: " +
                                     joinedList(mixed) + ".");
    return segmentJoint;
}

/// The Skin: the file's normalized weights for skinned vertices (a joint named twice counts once),
/// weight 1 on the segment's joint for the vertices of rigid mesh nodes. Empty when nothing is
/// skinned.
Skin buildSkin(const Import& import, const gltf::MeshData& data, const std::vector<int>& segmentJoint,
               const CharacterMesh& mesh)
{
    Skin skin;
    if (std::none_of(data.jointNodes.begin(), data.jointNodes.end(),
                     [](const std::array<int, 8>& slots) { return slots[0] >= 0; }))
        return skin;
    const std::size_t vertexCount = mesh.vertexCount();
    std::vector<std::array<std::uint16_t, kMaxInfluences>> vertexJoints(vertexCount);
    std::vector<std::array<double, kMaxInfluences>> vertexWeights(vertexCount);
    std::vector<int> influenceCount(vertexCount, 0);
    int influences = 1;
    for (std::size_t s = 0; s < mesh.segments.size(); ++s) {
        const Segment& segment = mesh.segments[s];
        for (std::size_t v = segment.firstVertex; v < segment.firstVertex + segment.vertexCount; ++v) {
            auto& joints = vertexJoints[v];
            int& count = influenceCount[v];
            for (std::size_t k = 0; k < 8; ++k) {
                const int node = data.jointNodes[v][k];
                if (node < 0 || !(data.weights[v][k] > 0))
                    continue;
                const auto joint = std::uint16_t(import.nodes.jointOfNode[std::size_t(node)]);
                const auto same = std::find(joints.begin(), joints.begin() + count, joint);
                if (same == joints.begin() + count)
                    joints[std::size_t(count++)] = joint;
                vertexWeights[v][std::size_t(same - joints.begin())] += data.weights[v][k];
            }
            if (count == 0) { // a rigid mesh node's vertex
                joints[0] = std::uint16_t(segmentJoint[s]);
                vertexWeights[v][0] = 1;
                count = 1;
            }
            influences = std::max(influences, count);
        }
    }
    skin.influences = influences <= 4 ? 4 : kMaxInfluences;
    const auto stride = std::size_t(skin.influences);
    skin.joints.assign(vertexCount * stride, 0);
    skin.weights.assign(vertexCount * stride, 0.0f);
    for (std::size_t v = 0; v < vertexCount; ++v) {
        const auto count = std::size_t(influenceCount[v]);
        double total = 0;
        for (std::size_t k = 0; k < count; ++k)
            total += vertexWeights[v][k];
        for (std::size_t k = 0; k < count; ++k) {
            skin.joints[v * stride + k] = vertexJoints[v][k];
            skin.weights[v * stride + k] = float(vertexWeights[v][k] / total);
        }
    }
    return skin;
}

/// One clip per animation, sampled at the options' rate on the skeleton's frame layout.
Result<void> buildClips(const Import& import, const std::vector<Animation>& animations, Character& character)
{
    const anim::Skeleton& skeleton = character.skeleton;
    const anim::FrameLayout& layout = *skeleton.frameLayout();
    const std::vector<float> rest = skeleton.restFrame();
    const double rate = import.options.clipFrameRate;
    // Per joint: the rest world transform and rotation of its glTF parent, its own rest rotation.
    std::vector<Mat4> parentTransform;
    std::vector<Quatd> parentRotation, inverseRestRotation;
    for (int node : import.nodes.nodes) {
        parentTransform.push_back(parentWorld(import.tree, node));
        parentRotation.push_back(gltf::rotationOf(parentTransform.back()));
        inverseRestRotation.push_back(anim::conjugate(restRotation(import.model().nodes[std::size_t(node)])));
    }
    constexpr double kMaxClipFloats = double(std::size_t(1) << 26);
    for (const Animation& animation : animations) {
        if (animation.tracks.empty()) {
            character.warnings.push_back("Animation \"" + animation.name + "\" moves no joint and is left out.");
            continue;
        }
        const double frames = std::ceil(animation.duration * rate - 1e-9) + 1;
        if (frames * double(layout.floatCount()) > kMaxClipFloats) {
            character.warnings.push_back("Animation \"" + animation.name + "\" is too long (" +
                                         std::to_string(animation.duration) + " s) and is left out.");
            continue;
        }
        const auto frameCount = std::size_t(frames);
        std::vector<float> data;
        data.reserve(frameCount * layout.floatCount());
        for (std::size_t f = 0; f < frameCount; ++f) {
            const double t = double(f) / rate;
            const std::size_t base = data.size();
            data.insert(data.end(), rest.begin(), rest.end());
            for (const Track& track : animation.tracks) {
                const std::array<double, 4> v = track.sample(t);
                const auto j = std::size_t(track.joint);
                if (track.path == Path::Rotation) {
                    // Rw · r(t) · rrest⁻¹ · Rw⁻¹: the change from rest, in the world-aligned frame.
                    const Quatd r = anim::normalize(Quatd{v[0], v[1], v[2], v[3]});
                    const Quatd q = parentRotation[j] * r * inverseRestRotation[j] * anim::conjugate(parentRotation[j]);
                    float* out = data.data() + base + 4 * j;
                    out[0] = float(q.x);
                    out[1] = float(q.y);
                    out[2] = float(q.z);
                    out[3] = float(q.w);
                    continue;
                }
                const int element = skeleton.translationElement(track.joint);
                if (element < 0)
                    continue; // the channel holds the rest translation
                // The root's translation is its world position; another joint's, its offset in the world.
                const Vec3d local{v[0], v[1], v[2]};
                const Vec3d offset = j == 0 ? gltf::transformPoint(parentTransform[j], local)
                                            : gltf::transformVector(parentTransform[j], local);
                float* out = data.data() + base + layout.floatOffset(element);
                out[0] = float(offset.x);
                out[1] = float(offset.y);
                out[2] = float(offset.z);
            }
        }
        Result<std::shared_ptr<anim::KeyframeClip>> clip =
            anim::KeyframeClip::create(skeleton.frameLayout(), rate, std::move(data), animation.name);
        if (!clip)
            return makeError(ErrorCode::CorruptData,
                             "The glTF file " + import.file.name + " has an animation that cannot be imported: \"" +
                                 animation.name + "\".",
                             clip.error().message);
        character.clips.push_back(std::move(*clip));
    }
    return {};
}

void warnAboutIgnoredChannels(const IgnoredChannels& ignored, std::vector<std::string>& warnings)
{
    auto warn = [&](const std::set<std::string>& nodes, const std::string& what) {
        if (!nodes.empty())
            warnings.push_back(what + ": " + joinedList(std::vector<std::string>(nodes.begin(), nodes.end())) + ".");
    };
    warn(ignored.scale, "Scale animation is not imported (clips rotate and translate joints)");
    warn(ignored.weights, "Morph target animation is not imported");
    warn(ignored.outsideSkeleton, "Animation of nodes that are not joints of the skin is not imported");
}

} // namespace

// ==== the public functions =========================================================================

std::string automaticHAnimName(const std::string& sourceName)
{
    const std::string_view stripped = strippedName(sourceName);
    if (std::string hanim = hanimNameOf(stripped); !hanim.empty())
        return hanim;
    const std::string key = nameKey(stripped);
    for (const KeyedConvention& convention : conventions())
        if (const auto found = convention.names.find(key); found != convention.names.end())
            return found->second;
    return {};
}

Result<Character> loadGltfCharacter(const std::filesystem::path& path, const GltfCharacterOptions& options)
{
    if (!(options.clipFrameRate > 0) || !std::isfinite(options.clipFrameRate))
        return makeError(ErrorCode::InvalidArgument,
                         "The clip frame rate must be a positive number of frames per second.");
    Result<gltf::File> file = gltf::readFile(path, options.loadTextures);
    if (!file)
        return file.error();
    const gltf::AccessorReader reader(*file);
    Result<gltf::NodeTree> tree = gltf::nodeTree(file->model, reader);
    if (!tree)
        return tree.error();
    Result<SkeletonNodes> nodes = skeletonNodes(file->model, *tree, reader);
    if (!nodes)
        return nodes.error();
    const Import import{*file, reader, *tree, *nodes, options};

    Character character;
    character.name = path.stem().string();
    character.warnings = file->imageWarnings;

    IgnoredChannels ignored;
    std::vector<Animation> animations;
    Result<anim::Skeleton> skeleton = anim::Skeleton{};
    if (nodes->nodes.empty()) {
        // No skin: one joint that every segment follows rigidly.
        anim::Joint root;
        root.name = "humanoid_root";
        skeleton = anim::Skeleton::create({root});
        if (!file->model.animations.empty())
            character.warnings.push_back("The file has no skin: its " + std::to_string(file->model.animations.size()) +
                                         " animations are not imported.");
    } else {
        if (nodes->nodes.size() > std::numeric_limits<std::uint16_t>::max())
            return makeError(ErrorCode::CorruptData, "The glTF file " + file->name + " has too many joints.");
        Result<std::vector<Animation>> read = readAnimations(file->model, reader, *nodes, ignored);
        if (!read)
            return read.error();
        animations = std::move(*read);
        skeleton = buildSkeleton(import, animations, character.warnings);
    }
    if (!skeleton)
        return skeleton.error();
    character.skeleton = std::move(*skeleton);

    // The mesh: split segments take their joint's name.
    std::vector<std::string> names;
    for (std::size_t n = 0; n < file->model.nodes.size(); ++n) {
        const int joint = nodes->jointOfNode[n];
        names.push_back(joint >= 0 ? character.skeleton.joint(joint).name : gltf::nodeName(file->model, int(n)));
    }
    Result<gltf::MeshData> data = gltf::readMesh(*file, *tree, options.mesh, names);
    if (!data)
        return data.error();
    character.mesh = std::move(data->mesh);
    const std::vector<int> segmentJoint = followJoints(import, data->sources, character);
    character.skin = buildSkin(import, *data, segmentJoint, character.mesh);
    if (data->hasTexcoords)
        character.texcoords = std::move(data->texcoords);

    readMaterials(file->model, options.loadTextures, character);
    if (!character.materials.empty())
        for (const gltf::SegmentSource& source : data->sources)
            character.segmentMaterials.push_back(source.material < int(character.materials.size()) ? source.material
                                                                                                   : -1);

    if (Result<void> built = buildClips(import, animations, character); !built)
        return built.error();
    warnAboutIgnoredChannels(ignored, character.warnings);
    if (options.standardRig) {
        for (const std::string& foot : attachIkFeet(character, &automaticHAnimName))
            character.warnings.push_back("The IK foot " + foot + " now hangs from its knee, so that motion made for other bodies moves it.");
        if (const std::string was = turnToFaceForward(character); !was.empty())
            character.warnings.push_back("The model stood " + was + "; it is turned to stand +Y up facing +Z, as H-Anim does.");
    }

    if (Result<void> valid = character.validate(); !valid)
        return makeError(ErrorCode::Internal, "The character read from " + file->name + " is inconsistent.",
                         valid.error().message);
    return character;
}

} // namespace thespis::core::scene
