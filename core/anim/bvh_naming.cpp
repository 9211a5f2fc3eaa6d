#include "anim/bvh_naming.h"

#include <algorithm>
#include <array>
#include <numbers>
#include <set>

#include "anim/bvh_text.h"
#include "anim/hanim.h"
#include "util/file_io.h"
#include "util/text.h"

// The H-Anim name of each joint is chosen by what the joint moves, not only by where it sits:
// BVH joint J's rotation turns the bone from J to its children, which is what H-Anim joint J
// does too. So "LeftUpLeg" (CMU), "LeftHip" (3ds Max, Biovision), "lThigh" (DAZ), "UpLeg_L"
// (MakeHuman) are all l_hip. Spines are mapped onto the joints of the paper's 25-joint subset
// where possible (vl5, vl1, vt10, vt6, vt1, vc4, skullbase); the joint that carries both
// clavicles and the neck becomes vt1 when it sits at the base of the neck (CMU), else the
// thoracic joint nearest to where it sits. Facial joints (eyes, jaw, tongue) keep their names:
// their H-Anim names are beyond LOA 2, which the rest of the engine knows.

namespace thespis::core::anim::bvh {
namespace naming {
namespace {

// CMU as converted by cgspeed for MotionBuilder (most CMU BVH files in circulation).
constexpr NameEntry kCmu[] = {
    {"Hips", "humanoid_root"},
    THESPIS_LR_NONE("LHipJoint", "RHipJoint"), // pelvis side bones: no H-Anim joint
    THESPIS_LR("LeftUpLeg", "RightUpLeg", "hip"),
    THESPIS_LR("LeftLeg", "RightLeg", "knee"),
    THESPIS_LR("LeftFoot", "RightFoot", "talocrural"),
    THESPIS_LR("LeftToeBase", "RightToeBase", "metatarsophalangeal"),
    {"LowerBack", "vl5"},
    {"Spine", "vl1"},
    {"Spine1", "vt1"}, // carries the neck and both clavicles, at the base of the neck
    {"Neck", "vc4"},
    {"Neck1", "vc2"},
    {"Head", "skullbase"},
    THESPIS_LR("LeftShoulder", "RightShoulder", "sternoclavicular"), // the clavicle here
    THESPIS_LR("LeftArm", "RightArm", "shoulder"),
    THESPIS_LR("LeftForeArm", "RightForeArm", "elbow"),
    THESPIS_LR("LeftHand", "RightHand", "radiocarpal"),
    THESPIS_LR("LeftFingerBase", "RightFingerBase", "carpometacarpal_2"), // the palm, at the wrist
    THESPIS_LR("LeftHandIndex1", "RightHandIndex1", "metacarpophalangeal_2"),
    THESPIS_LR("LFingers", "RFingers", "metacarpophalangeal_2"), // 01_01's name for the same joint
    THESPIS_LR("LThumb", "RThumb", "carpometacarpal_1"),
};

// CMU as converted by cgspeed for 3ds Max (e.g. subject 131): other names, same skeleton.
// Here "LeftShoulder" is the upper arm and "LeftCollar" the clavicle.
constexpr NameEntry kCmu3dsMax[] = {
    {"Hips", "humanoid_root"},
    THESPIS_LR_NONE("LHipJoint", "RHipJoint"),
    THESPIS_LR("LeftHip", "RightHip", "hip"),
    THESPIS_LR("LeftKnee", "RightKnee", "knee"),
    THESPIS_LR("LeftAnkle", "RightAnkle", "talocrural"),
    THESPIS_LR("LeftToe", "RightToe", "metatarsophalangeal"),
    {"lowerback", "vl5"},
    {"Chest", "vl1"},
    {"Chest2", "vt1"},
    {"lowerneck", "vc4"},
    {"Neck", "vc2"},
    {"Head", "skullbase"},
    THESPIS_LR("LeftCollar", "RightCollar", "sternoclavicular"),
    THESPIS_LR("LeftShoulder", "RightShoulder", "shoulder"),
    THESPIS_LR("LeftElbow", "RightElbow", "elbow"),
    THESPIS_LR("LeftWrist", "RightWrist", "radiocarpal"),
    THESPIS_LR("lhand", "rhand", "carpometacarpal_2"),
    THESPIS_LR("LFingers", "RFingers", "metacarpophalangeal_2"),
    THESPIS_LR("LThumb", "RThumb", "carpometacarpal_1"),
};

// The classic Biovision / Motion Analysis names (Boxing_Toes.bvh and the BVH format's own
// examples): Hips, Chest, Neck, Head, LeftCollar, LeftShoulder or LeftUpArm, LeftHip or LeftUpLeg.
constexpr NameEntry kBiovision[] = {
    {"Hips", "humanoid_root"},
    {"Ab", "vl5"},
    {"Chest", "vl1"},
    {"Neck", "vc4"},
    {"Head", "skullbase"},
    THESPIS_LR("LeftCollar", "RightCollar", "sternoclavicular"),
    THESPIS_LR("LeftShoulder", "RightShoulder", "shoulder"),
    THESPIS_LR("LeftUpArm", "RightUpArm", "shoulder"),
    THESPIS_LR("LeftElbow", "RightElbow", "elbow"),
    THESPIS_LR("LeftLowArm", "RightLowArm", "elbow"),
    THESPIS_LR("LeftWrist", "RightWrist", "radiocarpal"),
    THESPIS_LR("LeftHand", "RightHand", "radiocarpal"),
    THESPIS_LR("LeftHip", "RightHip", "hip"),
    THESPIS_LR("LeftUpLeg", "RightUpLeg", "hip"),
    THESPIS_LR("LeftKnee", "RightKnee", "knee"),
    THESPIS_LR("LeftLowLeg", "RightLowLeg", "knee"),
    THESPIS_LR("LeftAnkle", "RightAnkle", "talocrural"),
    THESPIS_LR("LeftFoot", "RightFoot", "talocrural"),
    THESPIS_LR("LeftToes", "RightToes", "metatarsophalangeal"),
    THESPIS_LR("LeftToe", "RightToe", "metatarsophalangeal"),
};

// DAZ / Poser (cgspeed's DAZ-friendly CMU release, three.js pirouette.bvh).
constexpr NameEntry kDaz[] = {
    {"hip", "humanoid_root"},
    {"abdomen", "vl1"},
    {"chest", "vt6"},
    {"neck", "vc4"},
    {"head", "skullbase"},
    {"leftEye", ""},
    {"rightEye", ""},
    THESPIS_LR("lCollar", "rCollar", "sternoclavicular"),
    THESPIS_LR("lShldr", "rShldr", "shoulder"),
    THESPIS_LR("lForeArm", "rForeArm", "elbow"),
    THESPIS_LR("lHand", "rHand", "radiocarpal"),
    THESPIS_LR("lThumb1", "rThumb1", "carpometacarpal_1"),
    THESPIS_LR("lThumb2", "rThumb2", "metacarpophalangeal_1"),
    THESPIS_LR("lThumb3", "rThumb3", "carpal_interphalangeal_1"),
    THESPIS_LR("lIndex1", "rIndex1", "metacarpophalangeal_2"),
    THESPIS_LR("lIndex2", "rIndex2", "carpal_proximal_interphalangeal_2"),
    THESPIS_LR("lIndex3", "rIndex3", "carpal_distal_interphalangeal_2"),
    THESPIS_LR("lMid1", "rMid1", "metacarpophalangeal_3"),
    THESPIS_LR("lMid2", "rMid2", "carpal_proximal_interphalangeal_3"),
    THESPIS_LR("lMid3", "rMid3", "carpal_distal_interphalangeal_3"),
    THESPIS_LR("lRing1", "rRing1", "metacarpophalangeal_4"),
    THESPIS_LR("lRing2", "rRing2", "carpal_proximal_interphalangeal_4"),
    THESPIS_LR("lRing3", "rRing3", "carpal_distal_interphalangeal_4"),
    THESPIS_LR("lPinky1", "rPinky1", "metacarpophalangeal_5"),
    THESPIS_LR("lPinky2", "rPinky2", "carpal_proximal_interphalangeal_5"),
    THESPIS_LR("lPinky3", "rPinky3", "carpal_distal_interphalangeal_5"),
    THESPIS_LR_NONE("lButtock", "rButtock"), // pelvis side bones
    THESPIS_LR("lThigh", "rThigh", "hip"),
    THESPIS_LR("lShin", "rShin", "knee"),
    THESPIS_LR("lFoot", "rFoot", "talocrural"),
    THESPIS_LR("lToe", "rToe", "metatarsophalangeal"),
};

// MakeHuman's default rig of its BVH animations (walk1.bvh): "Root" is the root, "Hips" the
// pelvis; "__X" joints are helpers that carry a bone's offset and keep their own names.
constexpr NameEntry kMakeHuman[] = {
    {"Root", "humanoid_root"},
    {"Hips", "sacroiliac"},
    {"Spine1", "vl5"},
    {"Spine2", "vl1"},
    {"Spine3", "vt6"},
    {"Neck", "vc4"},
    {"Head", "skullbase"},
    {"__Jaw", ""}, {"Jaw", ""}, {"__Tongue1", ""}, {"Tongue1", ""}, {"Tongue2", ""}, {"Tongue3", ""},
    THESPIS_LR_NONE("__Eye_L", "__Eye_R"),
    THESPIS_LR_NONE("Eye_L", "Eye_R"),
    THESPIS_LR_NONE("__Clavicle_L", "__Clavicle_R"),
    THESPIS_LR("Clavicle_L", "Clavicle_R", "sternoclavicular"),
    THESPIS_LR("UpArm_L", "UpArm_R", "shoulder"),
    THESPIS_LR("LoArm_L", "LoArm_R", "elbow"),
    THESPIS_LR("Hand_L", "Hand_R", "radiocarpal"),
    THESPIS_LR_NONE("__Thumb1_L", "__Thumb1_R"),
    THESPIS_LR("Thumb1_L", "Thumb1_R", "carpometacarpal_1"),
    THESPIS_LR("Thumb2_L", "Thumb2_R", "metacarpophalangeal_1"),
    THESPIS_LR("Thumb3_L", "Thumb3_R", "carpal_interphalangeal_1"),
    THESPIS_LR_NONE("__Index1_L", "__Index1_R"),
    THESPIS_LR("Index1_L", "Index1_R", "metacarpophalangeal_2"),
    THESPIS_LR("Index2_L", "Index2_R", "carpal_proximal_interphalangeal_2"),
    THESPIS_LR("Index3_L", "Index3_R", "carpal_distal_interphalangeal_2"),
    THESPIS_LR("Middle1_L", "Middle1_R", "metacarpophalangeal_3"),
    THESPIS_LR("Middle2_L", "Middle2_R", "carpal_proximal_interphalangeal_3"),
    THESPIS_LR("Middle3_L", "Middle3_R", "carpal_distal_interphalangeal_3"),
    THESPIS_LR_NONE("__Ring1_L", "__Ring1_R"),
    THESPIS_LR("Ring1_L", "Ring1_R", "metacarpophalangeal_4"),
    THESPIS_LR("Ring2_L", "Ring2_R", "carpal_proximal_interphalangeal_4"),
    THESPIS_LR("Ring3_L", "Ring3_R", "carpal_distal_interphalangeal_4"),
    THESPIS_LR_NONE("__Pinky1_L", "__Pinky1_R"),
    THESPIS_LR("Pinky1_L", "Pinky1_R", "metacarpophalangeal_5"),
    THESPIS_LR("Pinky2_L", "Pinky2_R", "carpal_proximal_interphalangeal_5"),
    THESPIS_LR("Pinky3_L", "Pinky3_R", "carpal_distal_interphalangeal_5"),
    THESPIS_LR_NONE("__UpLeg_L", "__UpLeg_R"),
    THESPIS_LR("UpLeg_L", "UpLeg_R", "hip"),
    THESPIS_LR("LoLeg_L", "LoLeg_R", "knee"),
    THESPIS_LR("Foot_L", "Foot_R", "talocrural"),
    THESPIS_LR("Toe_L", "Toe_R", "metatarsophalangeal"),
};

// MakeHuman 1.1's "default" skeleton (163 bones with a face rig; face-poseunits.bvh). Twist
// bones (upperarm02, lowerarm02, upperleg02, lowerleg02), pelvis side bones, breasts, the lesser
// toes and every face bone keep their names.
constexpr NameEntry kMakeHumanDefault[] = {
    {"root", "humanoid_root"},
    {"spine05", "vl5"},
    {"spine04", "vl3"},
    {"spine03", "vl1"},
    {"spine02", "vt6"},
    {"spine01", "vt1"},
    {"neck01", "vc4"},
    {"neck02", "vc2"},
    {"neck03", ""},
    {"head", "skullbase"},
    THESPIS_LR_NONE("breast.L", "breast.R"),
    THESPIS_LR("clavicle.L", "clavicle.R", "sternoclavicular"),
    THESPIS_LR("shoulder01.L", "shoulder01.R", "acromioclavicular"),
    THESPIS_LR("upperarm01.L", "upperarm01.R", "shoulder"),
    THESPIS_LR_NONE("upperarm02.L", "upperarm02.R"),
    THESPIS_LR("lowerarm01.L", "lowerarm01.R", "elbow"),
    THESPIS_LR_NONE("lowerarm02.L", "lowerarm02.R"),
    THESPIS_LR("wrist.L", "wrist.R", "radiocarpal"),
    THESPIS_LR("metacarpal1.L", "metacarpal1.R", "carpometacarpal_2"),
    THESPIS_LR("metacarpal2.L", "metacarpal2.R", "carpometacarpal_3"),
    THESPIS_LR("metacarpal3.L", "metacarpal3.R", "carpometacarpal_4"),
    THESPIS_LR("metacarpal4.L", "metacarpal4.R", "carpometacarpal_5"),
    THESPIS_LR("finger1-1.L", "finger1-1.R", "carpometacarpal_1"),
    THESPIS_LR("finger1-2.L", "finger1-2.R", "metacarpophalangeal_1"),
    THESPIS_LR("finger1-3.L", "finger1-3.R", "carpal_interphalangeal_1"),
    THESPIS_LR("finger2-1.L", "finger2-1.R", "metacarpophalangeal_2"),
    THESPIS_LR("finger2-2.L", "finger2-2.R", "carpal_proximal_interphalangeal_2"),
    THESPIS_LR("finger2-3.L", "finger2-3.R", "carpal_distal_interphalangeal_2"),
    THESPIS_LR("finger3-1.L", "finger3-1.R", "metacarpophalangeal_3"),
    THESPIS_LR("finger3-2.L", "finger3-2.R", "carpal_proximal_interphalangeal_3"),
    THESPIS_LR("finger3-3.L", "finger3-3.R", "carpal_distal_interphalangeal_3"),
    THESPIS_LR("finger4-1.L", "finger4-1.R", "metacarpophalangeal_4"),
    THESPIS_LR("finger4-2.L", "finger4-2.R", "carpal_proximal_interphalangeal_4"),
    THESPIS_LR("finger4-3.L", "finger4-3.R", "carpal_distal_interphalangeal_4"),
    THESPIS_LR("finger5-1.L", "finger5-1.R", "metacarpophalangeal_5"),
    THESPIS_LR("finger5-2.L", "finger5-2.R", "carpal_proximal_interphalangeal_5"),
    THESPIS_LR("finger5-3.L", "finger5-3.R", "carpal_distal_interphalangeal_5"),
    THESPIS_LR_NONE("pelvis.L", "pelvis.R"),
    THESPIS_LR("upperleg01.L", "upperleg01.R", "hip"),
    THESPIS_LR_NONE("upperleg02.L", "upperleg02.R"),
    THESPIS_LR("lowerleg01.L", "lowerleg01.R", "knee"),
    THESPIS_LR_NONE("lowerleg02.L", "lowerleg02.R"),
    THESPIS_LR("foot.L", "foot.R", "talocrural"),
    THESPIS_LR("toe1-1.L", "toe1-1.R", "metatarsophalangeal"), // the big toe
    THESPIS_LR("toe1-2.L", "toe1-2.R", "tarsal_interphalangeal"),
    THESPIS_LR_NONE("toe2-1.L", "toe2-1.R"), THESPIS_LR_NONE("toe2-2.L", "toe2-2.R"),
    THESPIS_LR_NONE("toe2-3.L", "toe2-3.R"), THESPIS_LR_NONE("toe3-1.L", "toe3-1.R"),
    THESPIS_LR_NONE("toe3-2.L", "toe3-2.R"), THESPIS_LR_NONE("toe3-3.L", "toe3-3.R"),
    THESPIS_LR_NONE("toe4-1.L", "toe4-1.R"), THESPIS_LR_NONE("toe4-2.L", "toe4-2.R"),
    THESPIS_LR_NONE("toe4-3.L", "toe4-3.R"), THESPIS_LR_NONE("toe5-1.L", "toe5-1.R"),
    THESPIS_LR_NONE("toe5-2.L", "toe5-2.R"), THESPIS_LR_NONE("toe5-3.L", "toe5-3.R"),
};

// Mixamo / HumanIK (MotionBuilder's characterization names, usually behind "mixamorig:").
constexpr NameEntry kMixamo[] = {
    {"Hips", "humanoid_root"},
    {"Spine", "vl5"},
    {"Spine1", "vl1"},
    {"Spine2", "vt6"},
    {"Neck", "vc4"},
    {"Head", "skullbase"},
    {"HeadTop_End", ""},
    THESPIS_LR("LeftShoulder", "RightShoulder", "sternoclavicular"),
    THESPIS_LR("LeftArm", "RightArm", "shoulder"),
    THESPIS_LR("LeftForeArm", "RightForeArm", "elbow"),
    THESPIS_LR("LeftHand", "RightHand", "radiocarpal"),
    THESPIS_LR("LeftHandThumb1", "RightHandThumb1", "carpometacarpal_1"),
    THESPIS_LR("LeftHandThumb2", "RightHandThumb2", "metacarpophalangeal_1"),
    THESPIS_LR("LeftHandThumb3", "RightHandThumb3", "carpal_interphalangeal_1"),
    THESPIS_LR_NONE("LeftHandThumb4", "RightHandThumb4"),
    THESPIS_LR("LeftHandIndex1", "RightHandIndex1", "metacarpophalangeal_2"),
    THESPIS_LR("LeftHandIndex2", "RightHandIndex2", "carpal_proximal_interphalangeal_2"),
    THESPIS_LR("LeftHandIndex3", "RightHandIndex3", "carpal_distal_interphalangeal_2"),
    THESPIS_LR_NONE("LeftHandIndex4", "RightHandIndex4"),
    THESPIS_LR("LeftHandMiddle1", "RightHandMiddle1", "metacarpophalangeal_3"),
    THESPIS_LR("LeftHandMiddle2", "RightHandMiddle2", "carpal_proximal_interphalangeal_3"),
    THESPIS_LR("LeftHandMiddle3", "RightHandMiddle3", "carpal_distal_interphalangeal_3"),
    THESPIS_LR_NONE("LeftHandMiddle4", "RightHandMiddle4"),
    THESPIS_LR("LeftHandRing1", "RightHandRing1", "metacarpophalangeal_4"),
    THESPIS_LR("LeftHandRing2", "RightHandRing2", "carpal_proximal_interphalangeal_4"),
    THESPIS_LR("LeftHandRing3", "RightHandRing3", "carpal_distal_interphalangeal_4"),
    THESPIS_LR_NONE("LeftHandRing4", "RightHandRing4"),
    THESPIS_LR("LeftHandPinky1", "RightHandPinky1", "metacarpophalangeal_5"),
    THESPIS_LR("LeftHandPinky2", "RightHandPinky2", "carpal_proximal_interphalangeal_5"),
    THESPIS_LR("LeftHandPinky3", "RightHandPinky3", "carpal_distal_interphalangeal_5"),
    THESPIS_LR_NONE("LeftHandPinky4", "RightHandPinky4"),
    THESPIS_LR("LeftUpLeg", "RightUpLeg", "hip"),
    THESPIS_LR("LeftLeg", "RightLeg", "knee"),
    THESPIS_LR("LeftFoot", "RightFoot", "talocrural"),
    THESPIS_LR("LeftToeBase", "RightToeBase", "metatarsophalangeal"),
    THESPIS_LR_NONE("LeftToe_End", "RightToe_End"),
};

constexpr Convention kConventions[] = {
    {"cmu", kCmu},
    {"cmu-3dsmax", kCmu3dsMax},
    {"biovision", kBiovision},
    {"daz", kDaz},
    {"makehuman", kMakeHuman},
    {"makehuman-default", kMakeHumanDefault},
    {"mixamo", kMixamo},
};

const NameEntry* findEntry(const Convention& convention, std::string_view name)
{
    for (const NameEntry& entry : convention.entries)
        if (entry.file == name)
            return &entry;
    return nullptr;
}

// A joint moves when some frame turns it more than this away from its first frame: well above
// the rounding noise of 6-decimal files (1e-6°), well below any deliberate motion.
constexpr double kMovingAngle = 0.5 * std::numbers::pi / 180.0;

bool reachesBody(const std::set<std::string, std::less<>>& mapped)
{
    auto all = [&](std::initializer_list<std::string_view> names) {
        return std::all_of(names.begin(), names.end(), [&](std::string_view n) { return mapped.count(n) > 0; });
    };
    // The root plus both legs or both arms: whole bodies, and upper- or lower-body captures.
    return all({"humanoid_root"})
           && (all({"l_hip", "r_hip", "l_knee", "r_knee", "l_talocrural", "r_talocrural"})
               || all({"l_shoulder", "r_shoulder", "l_elbow", "r_elbow", "l_radiocarpal", "r_radiocarpal"}));
}

} // namespace

std::span<const Convention> conventions() { return kConventions; }

std::string_view stripNamespace(std::string_view name)
{
    const auto colon = name.rfind(':');
    return colon == std::string_view::npos || colon + 1 == name.size() ? name : name.substr(colon + 1);
}

std::string_view hanimJointName(std::string_view name)
{
    const std::string_view current = hanim::fromHAnim11(name);
    return hanim::isJointName(current) ? current : std::string_view();
}

int minimumKnown(std::size_t nameCount) { return std::max(4, int((nameCount + 3) / 4)); }

Detection detect(std::span<const std::string> names)
{
    Detection best;
    best.convention = "none";
    const int minimum = minimumKnown(names.size());

    for (const Convention& convention : kConventions) {
        int known = 0;
        for (const std::string& name : names)
            if (findEntry(convention, stripNamespace(name)))
                ++known;
        if (known > best.known && known >= minimum) {
            best.convention = std::string(convention.id);
            best.known = known;
            best.mapping.clear();
            for (const std::string& name : names)
                if (const NameEntry* entry = findEntry(convention, stripNamespace(name)); entry && !entry->hanim.empty())
                    best.mapping.emplace(name, std::string(entry->hanim));
        }
    }

    // A file already written with H-Anim names (1.1 names are brought to 2.0).
    int hanimKnown = 0;
    JointMapping hanimMapping;
    for (const std::string& name : names) {
        if (const std::string_view current = hanimJointName(stripNamespace(name)); !current.empty()) {
            ++hanimKnown;
            hanimMapping.emplace(name, std::string(current));
        }
    }
    if (hanimKnown > best.known && hanimKnown >= minimum) {
        best.convention = "hanim";
        best.known = hanimKnown;
        best.mapping = std::move(hanimMapping);
    }
    return best;
}

bool isFacialName(std::string_view name)
{
    // Substrings of face joint names across rigs: MakeHuman's face muscles (levator, oris,
    // orbicularis, oculi, risorius, temporalis, special01…06), eyes, jaw, tongue, lips, brows.
    static constexpr std::string_view kStems[] = {"eye", "jaw", "tongue", "brow", "lip", "cheek", "mouth",
                                                  "teeth", "levator", "oris", "orbicularis", "oculi",
                                                  "risorius", "temporalis", "special0"};
    const std::string s = lowercase(name);
    return std::any_of(std::begin(kStems), std::end(kStems),
                       [&](std::string_view stem) { return s.find(stem) != std::string::npos; });
}

Naming nameJoints(std::span<const std::string> fileNames, std::span<const double> rotationRange,
                  const ImportOptions& options)
{
    Naming result;

    JointMapping table;
    bool userTable = false;
    if (options.mapping) {
        table = *options.mapping;
        userTable = true;
        result.report.convention = "user";
    } else {
        Detection detection = detect(fileNames);
        result.report.convention = detection.convention;
        table = std::move(detection.mapping);
    }

    std::set<std::string, std::less<>> fileNameSet(fileNames.begin(), fileNames.end());
    std::set<std::string, std::less<>> used;
    std::vector<std::string> candidate(fileNames.size());
    for (std::size_t j = 0; j < fileNames.size(); ++j) {
        auto it = table.find(fileNames[j]);
        if (it == table.end() && userTable)
            it = table.find(std::string(stripNamespace(fileNames[j])));
        if (it == table.end() || it->second.empty())
            continue;
        const std::string& target = it->second;
        if (used.count(target) || (target != fileNames[j] && fileNameSet.count(target)))
            continue;
        used.insert(target);
        candidate[j] = target;
    }

    // A face clip: only facial joints move (MakeHuman's face pose units sit on a full body rig
    // whose body joints stay still). It imports with its own names, as any non-body file.
    bool faceMoves = false, bodyMoves = false;
    for (std::size_t j = 0; j < fileNames.size(); ++j) {
        if (rotationRange[j] <= kMovingAngle)
            continue;
        (isFacialName(fileNames[j]) ? faceMoves : bodyMoves) = true;
    }
    const bool faceClip = faceMoves && !bodyMoves;

    const bool body = !faceClip && reachesBody(used);
    const bool rename = options.mapToHAnim && (userTable || body);
    result.report.isBody = body && rename;
    for (std::size_t j = 0; j < fileNames.size(); ++j) {
        if (rename && !candidate[j].empty()) {
            result.names.push_back(candidate[j]);
        } else {
            result.names.push_back(fileNames[j]);
            result.report.unmapped.push_back(fileNames[j]);
        }
    }
    return result;
}

} // namespace naming

Result<JointMapping> parseMapping(std::string_view text)
{
    JointMapping mapping;
    std::map<std::string, int> sourceLine, targetLine;
    std::map<std::string, std::string> targetSource;
    Scanner scanner(text);
    std::string_view line;
    int number = 0;
    while (scanner.nextLine(line, number)) {
        if (const auto hash = line.find('#'); hash != std::string_view::npos)
            line = line.substr(0, hash);
        std::vector<std::string_view> words;
        std::size_t pos = 0;
        for (std::string_view word = nextWord(line, pos); !word.empty(); word = nextWord(line, pos))
            words.push_back(word);
        if (words.empty())
            continue;
        // "file_joint hanim_joint", also written "file_joint = hanim_joint" or "… -> …".
        if (words.size() == 3 && (words[1] == "=" || words[1] == "->"))
            words.erase(words.begin() + 1);
        if (words.size() != 2)
            return corrupt(number, "expected 'file_joint_name hanim_joint_name', found " + quote(line));
        const std::string source(words[0]);
        const std::string target(hanim::fromHAnim11(words[1]));
        if (!hanim::isJointName(target))
            return corrupt(number, quote(words[1]) + " is not an H-Anim 2.0 joint name (e.g. l_hip, vl5, skullbase)");
        if (const auto it = sourceLine.find(source); it != sourceLine.end())
            return corrupt(number, "joint " + quote(source) + " is mapped twice (first on line "
                                       + std::to_string(it->second) + ")");
        if (const auto it = targetLine.find(target); it != targetLine.end())
            return corrupt(number, quote(target) + " is already the target of " + quote(targetSource[target])
                                       + " (line " + std::to_string(it->second) + ")");
        sourceLine.emplace(source, number);
        targetLine.emplace(target, number);
        targetSource.emplace(target, source);
        mapping.emplace(source, target);
    }
    return mapping;
}

Result<JointMapping> loadMapping(const std::filesystem::path& path)
{
    auto text = readTextFile(path);
    if (!text)
        return text.error();
    auto mapping = parseMapping(*text);
    if (!mapping)
        return inFile(path, mapping.error());
    return mapping;
}

} // namespace thespis::core::anim::bvh
