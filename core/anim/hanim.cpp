#include "anim/hanim.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <map>
#include <utility>

namespace thespis::core::anim::hanim {
namespace {

struct StandardJoint {
    const char* name;
    const char* parent;
    double x, y, z; // rest position in the world, metres (left side; right side mirrors x)
};

// LOA 2, left side and mid-line, parents first. Right-side joints are made by mirroring.
constexpr StandardJoint kLoa2[] = {
    {"humanoid_root", "", 0.0, 0.98, 0.0},
    {"sacroiliac", "humanoid_root", 0.0, 0.96, 0.0},
    {"l_hip", "sacroiliac", 0.09, 0.92, 0.0},
    {"l_knee", "l_hip", 0.09, 0.50, 0.01},
    {"l_talocrural", "l_knee", 0.09, 0.08, -0.01},
    {"l_tarsometatarsal", "l_talocrural", 0.09, 0.04, 0.07},
    {"l_metatarsophalangeal", "l_tarsometatarsal", 0.09, 0.02, 0.13},
    {"l_tarsal_interphalangeal", "l_metatarsophalangeal", 0.09, 0.015, 0.17},
    {"vl5", "humanoid_root", 0.0, 1.03, -0.02},
    {"vl3", "vl5", 0.0, 1.09, -0.03},
    {"vl1", "vl3", 0.0, 1.15, -0.03},
    {"vt10", "vl1", 0.0, 1.24, -0.04},
    {"vt6", "vt10", 0.0, 1.33, -0.05},
    {"vt1", "vt6", 0.0, 1.44, -0.04},
    {"vc4", "vt1", 0.0, 1.50, -0.03},
    {"vc2", "vc4", 0.0, 1.55, -0.02},
    {"skullbase", "vc2", 0.0, 1.60, -0.01},
    {"l_sternoclavicular", "vt1", 0.03, 1.42, 0.05},
    {"l_acromioclavicular", "l_sternoclavicular", 0.15, 1.44, -0.02},
    {"l_shoulder", "l_acromioclavicular", 0.19, 1.41, -0.02},
    {"l_elbow", "l_shoulder", 0.20, 1.12, -0.03},
    {"l_radiocarpal", "l_elbow", 0.21, 0.86, 0.0},
    {"l_carpometacarpal_1", "l_radiocarpal", 0.20, 0.84, 0.03},
    {"l_metacarpophalangeal_1", "l_carpometacarpal_1", 0.20, 0.80, 0.05},
    {"l_carpal_interphalangeal_1", "l_metacarpophalangeal_1", 0.20, 0.77, 0.06},
    {"l_carpometacarpal_2", "l_radiocarpal", 0.215, 0.84, 0.02},
    {"l_metacarpophalangeal_2", "l_carpometacarpal_2", 0.215, 0.77, 0.03},
    {"l_carpal_proximal_interphalangeal_2", "l_metacarpophalangeal_2", 0.215, 0.73, 0.03},
    {"l_carpal_distal_interphalangeal_2", "l_carpal_proximal_interphalangeal_2", 0.215, 0.705, 0.03},
    {"l_carpometacarpal_3", "l_radiocarpal", 0.22, 0.84, 0.0},
    {"l_metacarpophalangeal_3", "l_carpometacarpal_3", 0.22, 0.765, 0.005},
    {"l_carpal_proximal_interphalangeal_3", "l_metacarpophalangeal_3", 0.22, 0.72, 0.005},
    {"l_carpal_distal_interphalangeal_3", "l_carpal_proximal_interphalangeal_3", 0.22, 0.69, 0.005},
    {"l_carpometacarpal_4", "l_radiocarpal", 0.22, 0.84, -0.015},
    {"l_metacarpophalangeal_4", "l_carpometacarpal_4", 0.22, 0.77, -0.015},
    {"l_carpal_proximal_interphalangeal_4", "l_metacarpophalangeal_4", 0.22, 0.73, -0.015},
    {"l_carpal_distal_interphalangeal_4", "l_carpal_proximal_interphalangeal_4", 0.22, 0.70, -0.015},
    {"l_carpometacarpal_5", "l_radiocarpal", 0.215, 0.84, -0.03},
    {"l_metacarpophalangeal_5", "l_carpometacarpal_5", 0.215, 0.78, -0.03},
    {"l_carpal_proximal_interphalangeal_5", "l_metacarpophalangeal_5", 0.215, 0.75, -0.03},
    {"l_carpal_distal_interphalangeal_5", "l_carpal_proximal_interphalangeal_5", 0.215, 0.73, -0.03},
};

constexpr std::string_view kLoa1[] = {
    "humanoid_root", "sacroiliac", "l_hip", "l_knee", "l_talocrural", "l_metatarsophalangeal",
    "r_hip", "r_knee", "r_talocrural", "r_metatarsophalangeal", "vl5", "skullbase",
    "l_shoulder", "l_elbow", "l_radiocarpal", "r_shoulder", "r_elbow", "r_radiocarpal"};

constexpr std::string_view kSubset25[] = {
    "humanoid_root", "sacroiliac", "l_hip", "l_knee", "l_talocrural", "l_metatarsophalangeal",
    "r_hip", "r_knee", "r_talocrural", "r_metatarsophalangeal", "vl5", "vl1", "vt10", "vt6",
    "vt1", "vc4", "skullbase", "l_sternoclavicular", "l_shoulder", "l_elbow", "l_radiocarpal",
    "r_sternoclavicular", "r_shoulder", "r_elbow", "r_radiocarpal"};

constexpr std::pair<std::string_view, std::string_view> kHAnim11[] = {
    {"HumanoidRoot", "humanoid_root"}, {"l_ankle", "l_talocrural"}, {"r_ankle", "r_talocrural"},
    {"l_metatarsal", "l_metatarsophalangeal"}, {"r_metatarsal", "r_metatarsophalangeal"},
    {"l_midtarsal", "l_tarsometatarsal"}, {"r_midtarsal", "r_tarsometatarsal"},
    {"l_wrist", "l_radiocarpal"}, {"r_wrist", "r_radiocarpal"},
    {"l_thumb1", "l_carpometacarpal_1"}, {"l_thumb2", "l_metacarpophalangeal_1"},
    {"l_thumb3", "l_carpal_interphalangeal_1"}, {"r_thumb1", "r_carpometacarpal_1"},
    {"r_thumb2", "r_metacarpophalangeal_1"}, {"r_thumb3", "r_carpal_interphalangeal_1"},
};

std::string mirroredSide(std::string_view name)
{
    std::string s(name);
    if (s.size() > 2 && s[1] == '_' && (s[0] == 'l' || s[0] == 'r'))
        s[0] = s[0] == 'l' ? 'r' : 'l';
    return s;
}

struct FullJoint {
    std::string name, parent;
    Vec3d position;
};

// Every LOA 2 joint with its world rest position, parents first, left before right.
const std::vector<FullJoint>& loa2Joints()
{
    static const std::vector<FullJoint> joints = [] {
        std::vector<FullJoint> all;
        for (const StandardJoint& j : kLoa2) {
            all.push_back({j.name, j.parent, {j.x, j.y, j.z}});
        }
        // Right side: mirror every left joint, keeping parents-first order by appending after.
        for (const StandardJoint& j : kLoa2) {
            const std::string_view name = j.name;
            if (name.starts_with("l_"))
                all.push_back({mirroredSide(name), mirroredSide(j.parent), {-j.x, j.y, j.z}});
        }
        return all;
    }();
    return joints;
}

Skeleton buildSkeleton(const std::vector<std::string>& names)
{
    const auto& all = loa2Joints();
    auto findFull = [&](std::string_view name) {
        return std::find_if(all.begin(), all.end(), [&](const FullJoint& j) { return j.name == name; });
    };
    std::vector<Joint> joints;
    for (const std::string& name : names) {
        const auto full = findFull(name);
        Joint joint;
        joint.name = name;
        // Parent: the nearest LOA 2 ancestor that this level includes.
        std::string ancestor = full->parent;
        int parent = -1;
        while (!ancestor.empty()) {
            const auto it = std::find(names.begin(), names.end(), ancestor);
            if (it != names.end()) {
                parent = int(it - names.begin());
                break;
            }
            ancestor = findFull(ancestor)->parent;
        }
        joint.parent = parent;
        joint.offset = parent < 0 ? full->position
                                  : full->position - findFull(names[std::size_t(parent)])->position;
        joints.push_back(std::move(joint));
    }
    return std::move(Skeleton::create(std::move(joints))).value();
}

} // namespace

std::vector<std::string> jointNames(Level level)
{
    std::vector<std::string> names;
    if (level == Level::Loa2) {
        for (const FullJoint& j : loa2Joints())
            names.push_back(j.name);
        return names;
    }
    const auto subset = level == Level::Loa1 ? std::span<const std::string_view>(kLoa1)
                                             : std::span<const std::string_view>(kSubset25);
    // Keep LOA 2 order so parents come first.
    for (const FullJoint& j : loa2Joints())
        if (std::find(subset.begin(), subset.end(), j.name) != subset.end())
            names.push_back(j.name);
    return names;
}

const Skeleton& skeleton(Level level)
{
    static const Skeleton loa1 = buildSkeleton(jointNames(Level::Loa1));
    static const Skeleton loa2 = buildSkeleton(jointNames(Level::Loa2));
    static const Skeleton subset = buildSkeleton(jointNames(Level::Subset25));
    return level == Level::Loa1 ? loa1 : level == Level::Loa2 ? loa2 : subset;
}

bool isJointName(std::string_view name)
{
    const auto& all = loa2Joints();
    return std::any_of(all.begin(), all.end(), [&](const FullJoint& j) { return j.name == name; });
}

std::string_view parentName(std::string_view name)
{
    for (const FullJoint& j : loa2Joints())
        if (j.name == name)
            return j.parent;
    return {};
}

std::string_view fromHAnim11(std::string_view name)
{
    for (const auto& [old, current] : kHAnim11)
        if (old == name)
            return current;
    return name;
}

std::string mirrorName(std::string_view name)
{
    if (isJointName(name))
        return mirroredSide(name);
    std::string s(name);
    auto swapWord = [&](std::string_view from, std::string_view to) {
        if (s.starts_with(from)) {
            s = std::string(to) + s.substr(from.size());
            return true;
        }
        return false;
    };
    // Left/Right words (CMU, Mixamo-like), L/R prefixes (DAZ lCollar, CMU LHipJoint), .L/.R and
    // _L/_R suffixes (MakeHuman, Blender).
    if (swapWord("Left", "Right") || swapWord("Right", "Left") || swapWord("left", "right")
        || swapWord("right", "left"))
        return s;
    if (s.size() > 1 && (s[0] == 'l' || s[0] == 'r' || s[0] == 'L' || s[0] == 'R')
        && std::isupper(static_cast<unsigned char>(s[1]))) {
        s[0] = s[0] == 'l' ? 'r' : s[0] == 'r' ? 'l' : s[0] == 'L' ? 'R' : 'L';
        return s;
    }
    if (s.size() > 2 && (s[s.size() - 2] == '.' || s[s.size() - 2] == '_')) {
        char& side = s.back();
        if (side == 'L' || side == 'R' || side == 'l' || side == 'r')
            side = side == 'L' ? 'R' : side == 'R' ? 'L' : side == 'l' ? 'r' : 'l';
    }
    return s;
}

} // namespace thespis::core::anim::hanim
