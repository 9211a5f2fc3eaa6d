// The joint naming of glTF rigs (rig_naming.h): the glTF conventions' tables, picking the
// convention that knows a rig, the final unique names, and automaticHAnimName.

#include "scene/rig_naming.h"

#include <algorithm>
#include <cctype>
#include <map>
#include <set>
#include <span>
#include <string_view>

#include "anim/bvh_naming.h"
#include "anim/hanim.h"

namespace thespis::core::scene {
namespace {

using NameEntry = anim::bvh::naming::NameEntry;

// As in anim/bvh_naming.h, a joint is named after what it moves, and names with no H-Anim
// counterpart are listed with an empty name so that they count for detection. Mixamo's table
// there serves glTF files too.

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
    for (const std::string& candidate : {std::string(name), nameKey(name)})
        if (const std::string_view current = anim::bvh::naming::hanimJointName(candidate); !current.empty())
            return std::string(current);
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

/// The names one convention gives a rig, when it knows enough of them (as many as for BVH
/// files): the one that knows most wins. Empty when none does.
std::vector<std::string> namesByConvention(const std::vector<std::string>& sources)
{
    const int minimum = anim::bvh::naming::minimumKnown(sources.size());
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
                           "names: " + rig_naming::joinedList(dropped) + ".");
}

} // namespace

namespace rig_naming {

std::string joinedList(const std::vector<std::string>& items)
{
    std::string list;
    for (const std::string& item : items)
        list += (list.empty() ? "" : ", ") + item;
    return list;
}

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

} // namespace rig_naming

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

} // namespace thespis::core::scene
