// The face naming schemes of face_naming.h and the tables they give.

#include "scene/face_naming.h"

#include <algorithm>
#include <map>
#include <optional>
#include <set>
#include <span>
#include <string>
#include <string_view>

#include "scene/character.h"
#include "util/text.h"

namespace thespis::core::scene {

namespace {

using Side = MorphDrive::Side;

// ---- names ---------------------------------------------------------------------------------------

// A name without case, separators or anything up to the last of `namespaceEnds`.
std::string keyOf(std::string_view name, std::string_view namespaceEnds)
{
    if (const std::size_t end = name.find_last_of(namespaceEnds); end != std::string_view::npos && end + 1 < name.size())
        name.remove_prefix(end + 1);
    std::string key;
    for (const char c : lowercase(name))
        if (c != '_' && c != '-' && c != ' ' && c != '.')
            key += c;
    return key;
}

// Target names may carry a blend shape node's name ("blendShape1.jawOpen").
std::string targetKey(std::string_view name) { return keyOf(name, ":."); }
// Joint names keep their '.' ("eye.L"): only a namespace ("mixamorig:") goes.
std::string jointKey(std::string_view name) { return keyOf(name, ":"); }

// ---- ARKit -----------------------------------------------------------------------------------------

constexpr std::string_view kArkitShapes[] = {
    "eyeBlinkLeft",     "eyeLookDownLeft",     "eyeLookInLeft",     "eyeLookOutLeft",    "eyeLookUpLeft",
    "eyeSquintLeft",    "eyeWideLeft",         "eyeBlinkRight",     "eyeLookDownRight",  "eyeLookInRight",
    "eyeLookOutRight",  "eyeLookUpRight",      "eyeSquintRight",    "eyeWideRight",      "jawForward",
    "jawLeft",          "jawRight",            "jawOpen",           "mouthClose",        "mouthFunnel",
    "mouthPucker",      "mouthLeft",           "mouthRight",        "mouthSmileLeft",    "mouthSmileRight",
    "mouthFrownLeft",   "mouthFrownRight",     "mouthDimpleLeft",   "mouthDimpleRight",  "mouthStretchLeft",
    "mouthStretchRight", "mouthRollLower",     "mouthRollUpper",    "mouthShrugLower",   "mouthShrugUpper",
    "mouthPressLeft",   "mouthPressRight",     "mouthLowerDownLeft", "mouthLowerDownRight", "mouthUpperUpLeft",
    "mouthUpperUpRight", "browDownLeft",       "browDownRight",     "browInnerUp",       "browOuterUpLeft",
    "browOuterUpRight", "cheekPuff",           "cheekSquintLeft",   "cheekSquintRight",  "noseSneerLeft",
    "noseSneerRight",   "tongueOut"};
static_assert(std::size(kArkitShapes) == 52);

// An ARKit shape at weight 1 when FAP `fap` reaches `full` (in its unit), of that sign only:
// weight = value / full. Several rows for one shape add up (both lids closing halfway blink fully).
// The units: IRISD the eye's opening, ES the eyes' separation, ENS eyes to nose (about 3 cm), MNS
// mouth to nose (about 2 cm), MW the mouth's width (about 5 cm), each / 1024; AU 1e-5 rad.
struct ArkitFap {
    std::string_view shape;
    int fap;
    double full;
};
constexpr ArkitFap kArkitFaps[] = {
    // Eyes: a lid lowered by the whole opening closes the eye; a quarter opening raised is wide.
    {"eyeBlinkLeft", 19, 1024}, {"eyeBlinkLeft", 21, 1024}, {"eyeBlinkRight", 20, 1024}, {"eyeBlinkRight", 22, 1024},
    {"eyeWideLeft", 19, -256}, {"eyeWideRight", 20, -256},
    // Squinting lifts the cheek under the eye (a quarter ENS, about 8 mm).
    {"eyeSquintLeft", 41, 256}, {"eyeSquintRight", 42, 256},
    // Gaze: 30° sideways, 25° up or down. Yaw is positive to the face's left, pitch downwards.
    {"eyeLookOutLeft", 23, 52360}, {"eyeLookInLeft", 23, -52360},
    {"eyeLookInRight", 24, 52360}, {"eyeLookOutRight", 24, -52360},
    {"eyeLookDownLeft", 25, 43633}, {"eyeLookUpLeft", 25, -43633},
    {"eyeLookDownRight", 26, 43633}, {"eyeLookUpRight", 26, -43633},
    // Jaw: wide open is the chin 1.5 MNS down; forward half an MNS; sideways a quarter MW.
    {"jawOpen", 3, 1536}, {"jawForward", 14, 512}, {"jawLeft", 15, -256}, {"jawRight", 15, 256},
    // Lips. mouthClose closes lips the jaw has opened: both lips meeting over jawOpen's range.
    {"mouthClose", 4, 1536}, {"mouthClose", 5, 1536},
    {"mouthFunnel", 16, 1024}, {"mouthFunnel", 17, 1024},    // both lips half an MNS forward
    {"mouthRollLower", 16, -256}, {"mouthRollUpper", 17, -256}, // a lip drawn back rolls in
    {"mouthPucker", 6, -512}, {"mouthPucker", 7, -512},      // both corners a quarter MW inwards
    {"mouthStretchLeft", 6, 256}, {"mouthStretchRight", 7, 256},
    {"mouthSmileLeft", 12, 512}, {"mouthSmileRight", 13, 512}, // corners half an MNS up …
    {"mouthFrownLeft", 12, -512}, {"mouthFrownRight", 13, -512}, // … or down
    {"mouthShrugLower", 18, 256}, {"mouthShrugUpper", 18, 512}, // the chin pushing the lips up
    {"mouthPressLeft", 8, 1024}, {"mouthPressLeft", 10, 1024}, {"mouthPressRight", 9, 1024},
    {"mouthPressRight", 11, 1024},
    {"mouthUpperUpLeft", 8, -512}, {"mouthUpperUpRight", 9, -512},
    {"mouthLowerDownLeft", 10, -512}, {"mouthLowerDownRight", 11, -512},
    // Brows: inner and middle down a quarter ENS; inner up 3/8, outer up 3/8.
    {"browDownLeft", 31, -512}, {"browDownLeft", 33, -512}, {"browDownRight", 32, -512}, {"browDownRight", 34, -512},
    {"browInnerUp", 31, 768}, {"browInnerUp", 32, 768},
    {"browOuterUpLeft", 35, 384}, {"browOuterUpRight", 36, 384},
    // Cheeks puffed a quarter ES each, lifted a quarter ENS; the nose raised a quarter ENS; the
    // tongue's tip half an MW forward.
    {"cheekPuff", 39, 512}, {"cheekPuff", 40, 512},
    {"cheekSquintLeft", 41, 256}, {"cheekSquintRight", 42, 256},
    {"noseSneerLeft", 63, 256}, {"noseSneerRight", 63, 256},
    {"tongueOut", 45, 512},
};

bool isEyeLook(std::string_view shape) { return shape.starts_with("eyeLook"); }

// A viseme or expression as ARKit weights. A shape ending in '*' is a Left / Right pair.
struct ShapeWeight {
    std::string_view shape;
    double weight;
};
struct Recipe {
    ShapeWeight shapes[6];
};

// MPEG-4 visemes 1 … 14 (p_b_m, f_v, T_D, t_d, k_g, tS_dZ_S, s_z, n_l, r, A:, e, I, Q, U).
constexpr Recipe kVisemeRecipes[kVisemeCount] = {
    {{{"mouthPress*", 0.5}, {"mouthRollLower", 0.3}, {"mouthRollUpper", 0.2}}},
    {{{"mouthRollLower", 0.6}, {"mouthUpperUp*", 0.2}, {"jawOpen", 0.05}}},
    {{{"jawOpen", 0.15}, {"tongueOut", 0.4}}},
    {{{"jawOpen", 0.15}, {"mouthStretch*", 0.1}}},
    {{{"jawOpen", 0.2}, {"mouthStretch*", 0.15}}},
    {{{"jawOpen", 0.15}, {"mouthFunnel", 0.5}, {"mouthPucker", 0.2}}},
    {{{"jawOpen", 0.05}, {"mouthStretch*", 0.3}}},
    {{{"jawOpen", 0.15}, {"mouthLowerDown*", 0.1}}},
    {{{"jawOpen", 0.1}, {"mouthPucker", 0.4}, {"mouthFunnel", 0.2}}},
    {{{"jawOpen", 0.6}, {"mouthLowerDown*", 0.3}}},
    {{{"jawOpen", 0.3}, {"mouthStretch*", 0.4}}},
    {{{"jawOpen", 0.15}, {"mouthStretch*", 0.5}, {"mouthSmile*", 0.3}}},
    {{{"jawOpen", 0.4}, {"mouthFunnel", 0.6}, {"mouthPucker", 0.2}}},
    {{{"jawOpen", 0.1}, {"mouthPucker", 0.8}, {"mouthFunnel", 0.3}}},
};

// The 6 expressions (joy, sadness, anger, fear, disgust, surprise) from the action units Ekman
// and Friesen give them: joy AU6 + 12, sadness 1 + 4 + 15 + 17, anger 4 + 5 + 7 + 9 + 24,
// fear 1 + 2 + 4 + 5 + 20 + 26, disgust 4 + 6 + 9 + 10 + 15, surprise 1 + 2 + 5 + 26.
constexpr Recipe kExpressionRecipes[kExpressionCount] = {
    {{{"mouthSmile*", 0.8}, {"cheekSquint*", 0.6}, {"eyeSquint*", 0.4}}},
    {{{"browInnerUp", 0.8}, {"browDown*", 0.3}, {"mouthFrown*", 0.7}, {"mouthShrugLower", 0.3}}},
    {{{"browDown*", 0.9}, {"eyeWide*", 0.3}, {"eyeSquint*", 0.4}, {"noseSneer*", 0.3}, {"mouthPress*", 0.6}}},
    {{{"browInnerUp", 0.8}, {"browOuterUp*", 0.5}, {"browDown*", 0.2}, {"eyeWide*", 0.8}, {"mouthStretch*", 0.6},
      {"jawOpen", 0.2}}},
    {{{"noseSneer*", 0.8}, {"mouthUpperUp*", 0.6}, {"mouthFrown*", 0.3}, {"browDown*", 0.3}, {"cheekSquint*", 0.3}}},
    {{{"browInnerUp", 0.8}, {"browOuterUp*", 0.8}, {"eyeWide*", 0.8}, {"jawOpen", 0.4}}},
};

// ---- Oculus visemes and expression names -------------------------------------------------------------

// The OVR LipSync visemes in MPEG-4 order (viseme_sil, silence, has no MPEG-4 viseme).
constexpr std::string_view kOculusVisemes[kVisemeCount] = {"viseme_PP", "viseme_FF", "viseme_TH", "viseme_DD",
                                                           "viseme_kk", "viseme_CH", "viseme_SS", "viseme_nn",
                                                           "viseme_RR", "viseme_aa", "viseme_E",  "viseme_I",
                                                           "viseme_O",  "viseme_U"};
constexpr std::string_view kOculusSilence = "viseme_sil";

// Names of expression targets, by expression (first match wins), as keys.
constexpr std::string_view kExpressionNames[kExpressionCount][4] = {
    {"happy", "joy", "smile", "happiness"}, {"sad", "sadness", "", ""},  {"angry", "anger", "", ""},
    {"fear", "afraid", "scared", "fearful"}, {"disgust", "disgusted", "", ""}, {"surprised", "surprise", "", ""}};

// ---- bones ---------------------------------------------------------------------------------------------

// Eye and jaw bones of common rigs, as keys: Unity / VRM / Mixamo, H-Anim 1.1 / 2.0, Blender,
// Rigify (DEF- / ORG-), Character Creator (CC_Base_), VRoid (J_Adj_).
constexpr std::string_view kLeftEyes[] = {"lefteye", "eyeleft",      "eyel",      "leye",       "lefteyeball",
                                          "eyeballleft", "eyeballl", "leyeball", "leyeballjoint", "defeyel",
                                          "orgeyel", "ccbaseleye", "jadjlfaceeye"};
constexpr std::string_view kRightEyes[] = {"righteye", "eyeright",      "eyer",      "reye",       "righteyeball",
                                           "eyeballright", "eyeballr", "reyeball", "reyeballjoint", "defeyer",
                                           "orgeyer", "ccbasereye", "jadjrfaceeye"};
constexpr std::string_view kJaws[] = {"jaw",    "jawbone", "jawjoint", "lowerjaw",          "jawroot",
                                      "defjaw", "orgjaw",  "ccbasejawroot", "temporomandibular", "mandible"};

constexpr double kAngleUnit = 1e-5;       // AU
constexpr double kJawPerUnit = 0.22 / 1024; // see face_naming.h

// The first skeleton joint whose name or source name is one of `keys`.
const anim::Joint* findJoint(const anim::Skeleton& skeleton, std::span<const std::string_view> keys)
{
    for (int j = 0; j < skeleton.jointCount(); ++j) {
        const anim::Joint& joint = skeleton.joint(j);
        for (const std::string* name : {&joint.name, &joint.sourceName})
            if (std::find(keys.begin(), keys.end(), jointKey(*name)) != keys.end())
                return &joint;
    }
    return nullptr;
}

class Recogniser {
public:
    explicit Recogniser(const Character& character) : m_character(character)
    {
        for (const std::string& name : morphTargetNames(character))
            m_targetByKey.emplace(targetKey(name), name);
    }

    FaceMapping run();

private:
    const std::string* target(std::string_view name) const
    {
        const auto found = m_targetByKey.find(targetKey(name));
        return found == m_targetByKey.end() ? nullptr : &found->second;
    }
    void drive(const std::string& target, int channel, double coefficient, Side side = Side::Both)
    {
        m_mapping.drives.push_back({target, channel, coefficient, side});
        m_claimed.insert(target);
    }
    /// Drives the recipe's shapes the model has; whether it had any.
    bool driveRecipe(const Recipe& recipe, int channel);
    void scheme(const char* name) { m_schemes += (m_schemes.empty() ? "" : ", ") + std::string(name); }

    const Character& m_character;
    std::map<std::string, std::string> m_targetByKey; // key → the model's own name
    std::set<std::string> m_claimed;                  // targets some scheme drives
    FaceMapping m_mapping;
    std::string m_schemes;
};

bool Recogniser::driveRecipe(const Recipe& recipe, int channel)
{
    bool any = false;
    for (const ShapeWeight& entry : recipe.shapes) {
        if (entry.shape.empty())
            break;
        const bool pair = entry.shape.ends_with('*');
        const std::string stem(entry.shape.substr(0, entry.shape.size() - (pair ? 1 : 0)));
        for (const std::string& shape : pair ? std::vector<std::string>{stem + "Left", stem + "Right"}
                                             : std::vector<std::string>{stem})
            if (const std::string* name = target(shape)) {
                drive(*name, channel, entry.weight);
                any = true;
            }
    }
    return any;
}

FaceMapping Recogniser::run()
{
    const anim::Skeleton& skeleton = m_character.skeleton;
    const anim::Joint* leftEye = findJoint(skeleton, kLeftEyes);
    const anim::Joint* rightEye = findJoint(skeleton, kRightEyes);

    const bool arkit = std::any_of(std::begin(kArkitShapes), std::end(kArkitShapes),
                                   [&](std::string_view shape) { return target(shape) != nullptr; });
    if (arkit) {
        scheme("ARKit blendshapes");
        for (const ArkitFap& row : kArkitFaps)
            if (const std::string* name = target(row.shape); name && !(isEyeLook(row.shape) && (leftEye || rightEye)))
                drive(*name, fapChannel(row.fap), 1 / row.full, row.full > 0 ? Side::Positive : Side::Negative);
    }

    bool oculus = target(kOculusSilence) != nullptr;
    for (int v = 1; v <= kVisemeCount; ++v) {
        if (const std::string* name = target(kOculusVisemes[v - 1])) {
            drive(*name, visemeChannel(v), 1);
            oculus = true;
        } else if (arkit) {
            driveRecipe(kVisemeRecipes[v - 1], visemeChannel(v));
        }
    }
    if (oculus)
        scheme("Oculus visemes");
    if (const std::string* silence = target(kOculusSilence))
        m_claimed.insert(*silence);

    bool named = false;
    for (int e = 1; e <= kExpressionCount; ++e) {
        const std::string* name = nullptr;
        for (std::string_view synonym : kExpressionNames[e - 1])
            if (!synonym.empty() && !name)
                name = target(synonym);
        if (name) {
            drive(*name, expressionChannel(e), 1);
            named = true;
        } else if (arkit) {
            driveRecipe(kExpressionRecipes[e - 1], expressionChannel(e));
        }
    }
    if (named)
        scheme("expression targets");

    bool channels = false;
    for (const auto& [key, name] : m_targetByKey)
        if (!m_claimed.contains(name)) {
            const std::size_t colon = name.find_last_of(":.");
            const std::string own = colon == std::string::npos ? name : name.substr(colon + 1);
            if (const std::optional<int> channel = findFaceChannel(lowercase(own))) {
                drive(name, *channel, 1);
                channels = true;
            }
        }
    if (channels)
        scheme("face channel targets");

    if (leftEye || rightEye) {
        scheme("eye bones");
        const std::pair<const anim::Joint*, int> eyes[] = {{leftEye, 23}, {rightEye, 24}};
        for (const auto& [eye, yaw] : eyes)
            if (eye) {
                m_mapping.joints.push_back({eye->name, fapChannel(yaw), {0, 1, 0}, kAngleUnit});
                m_mapping.joints.push_back({eye->name, fapChannel(yaw + 2), {1, 0, 0}, kAngleUnit});
            }
    }
    const bool jawTarget = std::any_of(m_mapping.drives.begin(), m_mapping.drives.end(),
                                       [](const FaceMappingDrive& d) { return d.channel == fapChannel(3); });
    if (const anim::Joint* jaw = findJoint(skeleton, kJaws); jaw && !jawTarget) {
        scheme("jaw bone");
        m_mapping.joints.push_back({jaw->name, fapChannel(3), {1, 0, 0}, kJawPerUnit});
    }
    if (skeleton.find("skullbase") >= 0) {
        scheme("head");
        m_mapping.joints.push_back({"skullbase", fapChannel(48), {1, 0, 0}, kAngleUnit});
        m_mapping.joints.push_back({"skullbase", fapChannel(49), {0, 1, 0}, kAngleUnit});
        m_mapping.joints.push_back({"skullbase", fapChannel(50), {0, 0, 1}, kAngleUnit});
    }
    m_mapping.name = m_schemes;
    return std::move(m_mapping);
}

} // namespace

FaceMapping recogniseFaceMapping(const Character& character)
{
    return Recogniser(character).run();
}

} // namespace thespis::core::scene
