// BVH import onto H-Anim and export, on the real motion capture of ../shared/data/mocap (CMU in
// its MotionBuilder and 3ds Max namings, DAZ/Poser, MakeHuman, Biovision-style boxing, a
// MakeHuman face rig) and on small project-made fixtures.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <numbers>
#include <random>
#include <set>
#include <sstream>

#include "anim/bvh.h"
#include "anim/hanim.h"
#include "anim/modifiers.h"
#include "test_support.h"
#include "util/file_io.h"

using namespace thespis::core;
using namespace thespis::core::anim;
namespace fs = std::filesystem;

namespace {

// ---------------------------------------------------------------------------------------------
// A tiny independent reading of a BVH file (not through the parser under test): joint names
// with their parents, offsets and channels, the header's frame count and frame time, and the
// raw values of every frame. Only for the well-formed files of the shared data.
struct RawJoint {
    std::string name;
    int parent = -1;
    std::array<double, 3> offset{};
    std::vector<std::string> channels;
};

struct RawBvh {
    std::vector<RawJoint> joints;
    int channelCount = 0;
    int frames = 0;
    double frameTime = 0;
    std::vector<std::vector<double>> values;
};

RawBvh scanRaw(const fs::path& path)
{
    std::ifstream in(path, std::ios::binary);
    std::string line;
    RawBvh raw;
    std::vector<int> stack;
    bool inEndSite = false, motion = false;
    while (std::getline(in, line)) {
        if (!line.empty() && line.back() == '\r')
            line.pop_back();
        std::istringstream words(line);
        std::string first;
        if (!(words >> first))
            continue;
        if (!motion) {
            if (first == "ROOT" || first == "JOINT") {
                RawJoint joint;
                words >> joint.name;
                joint.parent = stack.empty() ? -1 : stack.back();
                raw.joints.push_back(joint);
                stack.push_back(int(raw.joints.size()) - 1);
            } else if (first == "End") {
                inEndSite = true;
            } else if (first == "OFFSET" && !inEndSite) {
                auto& o = raw.joints.back().offset;
                words >> o[0] >> o[1] >> o[2];
            } else if (first == "CHANNELS") {
                int n = 0;
                words >> n;
                raw.channelCount += n;
                for (std::string c; words >> c;)
                    raw.joints.back().channels.push_back(c);
            } else if (first == "}") {
                if (inEndSite)
                    inEndSite = false;
                else
                    stack.pop_back();
            } else if (first == "MOTION") {
                motion = true;
            }
        } else if (first == "Frames:") {
            words >> raw.frames;
        } else if (first == "Frame") {
            std::string time;
            words >> time >> raw.frameTime;
        } else {
            std::vector<double> v{std::stod(first)};
            for (double x; words >> x;)
                v.push_back(x);
            raw.values.push_back(std::move(v));
        }
    }
    return raw;
}

std::vector<fs::path> mocapFiles()
{
    std::vector<fs::path> files;
    for (const auto& entry : fs::recursive_directory_iterator(thespis::test::sharedData("mocap")))
        if (entry.is_regular_file() && entry.path().extension() == ".bvh")
            files.push_back(entry.path());
    std::sort(files.begin(), files.end());
    return files;
}

bool isFaceFile(const fs::path& path) { return path.filename() == "face-poseunits.bvh"; }

std::string relativeName(const fs::path& path)
{
    return fs::relative(path, thespis::test::sharedData("mocap")).generic_string();
}

// One import per file for the whole test program: the files are large, the tests many. The
// file's axes are kept (not stood upright), so that what is read can be compared with the text.
const bvh::ImportedClip& imported(const fs::path& path)
{
    static std::map<fs::path, bvh::ImportedClip> cache;
    auto it = cache.find(path);
    if (it == cache.end()) {
        auto result = bvh::load(path, {.upright = false});
        if (!result) {
            ADD_FAILURE() << path << ": " << describe(result.error());
            std::abort();
        }
        it = cache.emplace(path, std::move(*result)).first;
    }
    return it->second;
}

/// Rotation angle between two rotations, accurate for small angles too (acos of a float dot
/// product would lose half of the digits there): 2·atan2(|v|, |w|) of a⁻¹·b, in double.
double angleOf(const Quat& a, const Quat& b)
{
    const Quatd d = conjugate(normalize(Quatd{a.x, a.y, a.z, a.w})) * normalize(Quatd{b.x, b.y, b.z, b.w});
    return 2.0 * std::atan2(std::sqrt(d.x * d.x + d.y * d.y + d.z * d.z), std::abs(d.w));
}

/// |a − b| within 1e-5 for rotations (angle, sign-independent) and 1e-5 relative to the value's
/// magnitude (at least 1) for translations, at every key.
void expectSameMotion(const bvh::ImportedClip& a, const bvh::ImportedClip& b, const std::string& where)
{
    ASSERT_EQ(a.clip->frameCount(), b.clip->frameCount()) << where;
    const FrameLayout& la = *a.clip->layout();
    const FrameLayout& lb = *b.clip->layout();
    ASSERT_EQ(la, lb) << where;
    double worstRotation = 0, worstTranslation = 0;
    for (int f = 0; f < a.clip->frameCount(); ++f) {
        const auto fa = a.clip->frame(f), fb = b.clip->frame(f);
        for (int r = 0; r < la.rotationCount(); ++r) {
            // Sign-aligned component comparison (q and −q are the same rotation).
            const Quat& qa = rotationAt(fa, r);
            Quat qb = rotationAt(fb, r);
            if (dot(qa, qb) < 0)
                qb = negate(qb);
            const double d = std::max({std::abs(qa.x - qb.x), std::abs(qa.y - qb.y), std::abs(qa.z - qb.z),
                                       std::abs(qa.w - qb.w)});
            worstRotation = std::max(worstRotation, d);
            ASSERT_LE(d, 1e-5) << where << " frame " << f << " joint " << la.name(r);
        }
        for (std::size_t k = la.translationOffset(); k < la.scalarOffset(); ++k) {
            const double d = std::abs(fa[k] - fb[k]) / std::max(1.0, double(std::abs(fa[k])));
            worstTranslation = std::max(worstTranslation, d);
            ASSERT_LE(d, 1e-5) << where << " frame " << f << " float " << k;
        }
    }
    ::testing::Test::RecordProperty(where + "_worst_rotation", std::to_string(worstRotation));
    ::testing::Test::RecordProperty(where + "_worst_translation", std::to_string(worstTranslation));
}

std::string namesOf(const Skeleton& skeleton)
{
    std::string s;
    for (const Joint& j : skeleton.joints())
        s += j.sourceName + "→" + j.name + " ";
    return s;
}

/// The H-Anim name given to file joint `source`, or "" when it has none.
std::string mappedName(const Skeleton& skeleton, const std::string& source)
{
    for (const Joint& j : skeleton.joints())
        if (j.sourceName == source)
            return j.name;
    return "";
}

// Independent forward kinematics from the raw file values, with rotation matrices built from
// each channel in file order (R = R_first · R_second · R_third).
using Mat3 = std::array<std::array<double, 3>, 3>;

Mat3 matMul(const Mat3& a, const Mat3& b)
{
    Mat3 m{};
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c)
            for (int k = 0; k < 3; ++k)
                m[r][c] += a[r][k] * b[k][c];
    return m;
}

Mat3 axisMat(char axis, double degrees)
{
    const double a = degrees * std::numbers::pi / 180, c = std::cos(a), s = std::sin(a);
    if (axis == 'X')
        return {{{1, 0, 0}, {0, c, -s}, {0, s, c}}};
    if (axis == 'Y')
        return {{{c, 0, s}, {0, 1, 0}, {-s, 0, c}}};
    return {{{c, -s, 0}, {s, c, 0}, {0, 0, 1}}};
}

std::vector<std::array<double, 3>> rawWorldPositions(const RawBvh& raw, int frame)
{
    std::vector<std::array<double, 3>> positions(raw.joints.size());
    std::vector<Mat3> orientations(raw.joints.size());
    std::size_t k = 0;
    for (std::size_t j = 0; j < raw.joints.size(); ++j) {
        const RawJoint& joint = raw.joints[j];
        Mat3 local{{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};
        std::array<double, 3> t = joint.offset;
        for (const std::string& c : joint.channels) {
            const double v = raw.values[std::size_t(frame)][k++];
            if (c.find("rotation") != std::string::npos)
                local = matMul(local, axisMat(c[0], v));
            else
                t[std::size_t(c[0] - 'X')] = v;
        }
        if (joint.parent < 0) {
            positions[j] = t;
            orientations[j] = local;
        } else {
            const Mat3& p = orientations[std::size_t(joint.parent)];
            for (int r = 0; r < 3; ++r)
                positions[j][std::size_t(r)] = positions[std::size_t(joint.parent)][std::size_t(r)]
                                               + p[r][0] * t[0] + p[r][1] * t[1] + p[r][2] * t[2];
            orientations[j] = matMul(p, local);
        }
    }
    return positions;
}

// ---------------------------------------------------------------------------------------------
// A small well-formed file for the malformed-input tests; each test breaks one line of it.
const char* const kGood = "HIERARCHY\n"                                                    // 1
                          "ROOT Hips\n"                                                    // 2
                          "{\n"                                                            // 3
                          "\tOFFSET 0 0 0\n"                                               // 4
                          "\tCHANNELS 6 Xposition Yposition Zposition Zrotation Xrotation Yrotation\n" // 5
                          "\tJOINT Chest\n"                                                // 6
                          "\t{\n"                                                          // 7
                          "\t\tOFFSET 0 10 0\n"                                            // 8
                          "\t\tCHANNELS 3 Zrotation Xrotation Yrotation\n"                 // 9
                          "\t\tEnd Site\n"                                                 // 10
                          "\t\t{\n"                                                        // 11
                          "\t\t\tOFFSET 0 5 0\n"                                           // 12
                          "\t\t}\n"                                                        // 13
                          "\t}\n"                                                          // 14
                          "}\n"                                                            // 15
                          "MOTION\n"                                                       // 16
                          "Frames: 3\n"                                                    // 17
                          "Frame Time: 0.04\n"                                             // 18
                          "0 90 0 0 0 0 10 20 30\n"                                        // 19
                          "1 90 0 5 0 0 11 21 31\n"                                        // 20
                          "2 90 0 10 0 0 12 22 32\n";                                      // 21

/// kGood with some lines (1-based) replaced (a replacement may hold several lines).
std::string withLines(const std::map<int, std::string>& replacements)
{
    std::istringstream in(kGood);
    std::string out, line;
    for (int n = 1; std::getline(in, line); ++n) {
        const auto it = replacements.find(n);
        out += (it != replacements.end() ? it->second : line) + "\n";
    }
    return out;
}

std::string withLine(int number, const std::string& replacement) { return withLines({{number, replacement}}); }

void expectCorruptAt(const std::string& text, int line, const std::string& mentions = {})
{
    auto result = bvh::parse(text);
    ASSERT_FALSE(result) << "accepted:\n" << text;
    EXPECT_EQ(result.error().code, ErrorCode::CorruptData) << result.error().message;
    const std::string prefix = "line " + std::to_string(line) + ": ";
    EXPECT_EQ(result.error().message.rfind(prefix, 0), 0u) << "expected '" << prefix << "…', got: " << result.error().message;
    if (!mentions.empty()) {
        EXPECT_NE(result.error().message.find(mentions), std::string::npos) << result.error().message;
    }
}

fs::path scratchDir()
{
    const fs::path dir = fs::temp_directory_path()
                         / ("thespis_bvh_test_" + std::to_string(std::random_device{}()));
    fs::create_directories(dir);
    return dir;
}

} // namespace

// ---------------------------------------------------------------------------------------------
// Every real file imports, and matches its header.

TEST(BvhImport, EveryMocapFileMatchesItsHeader)
{
    const auto files = mocapFiles();
    ASSERT_GE(files.size(), 17u) << "the shared mocap folder is missing files";
    for (const fs::path& path : files) {
        SCOPED_TRACE(relativeName(path));
        const RawBvh raw = scanRaw(path);
        const bvh::ImportedClip& clip = imported(path);
        EXPECT_EQ(clip.report.jointCount, int(raw.joints.size()));
        EXPECT_EQ(clip.skeleton.jointCount(), int(raw.joints.size()));
        EXPECT_EQ(clip.report.channelCount, raw.channelCount);
        EXPECT_EQ(clip.report.frameCount, raw.frames);
        EXPECT_EQ(clip.clip->frameCount(), raw.frames);
        EXPECT_GE(int(raw.values.size()), raw.frames); // Boxing_Toes has one line more than its header
        EXPECT_EQ(clip.report.extraFrameLines, int(raw.values.size()) - raw.frames);
        EXPECT_DOUBLE_EQ(clip.report.frameTime, raw.frameTime);
        EXPECT_DOUBLE_EQ(clip.clip->frameRate(), 1.0 / raw.frameTime);
        EXPECT_EQ(clip.clip->name(), path.stem().string());
        // Joints keep the file's order, names, parents, offsets and rotation orders.
        for (std::size_t j = 0; j < raw.joints.size(); ++j) {
            const Joint& joint = clip.skeleton.joint(int(j));
            EXPECT_EQ(joint.sourceName, raw.joints[j].name);
            EXPECT_EQ(joint.parent, raw.joints[j].parent);
            EXPECT_EQ(joint.offset.x, raw.joints[j].offset[0]);
            EXPECT_EQ(joint.offset.y, raw.joints[j].offset[1]);
            EXPECT_EQ(joint.offset.z, raw.joints[j].offset[2]);
            std::string order;
            bool positions = false;
            for (const std::string& c : raw.joints[j].channels) {
                if (c.find("rotation") != std::string::npos)
                    order += c[0];
                else
                    positions = true;
            }
            EXPECT_EQ(joint.rotationOrder, order) << joint.sourceName;
            EXPECT_EQ(joint.translates, positions || j == 0) << joint.sourceName;
        }
        // Every leaf of these files has an End Site.
        for (int j = 0; j < clip.skeleton.jointCount(); ++j) {
            bool leaf = true;
            for (const Joint& other : clip.skeleton.joints())
                leaf = leaf && other.parent != j;
            if (leaf) {
                EXPECT_TRUE(clip.skeleton.joint(j).endSite.has_value()) << clip.skeleton.joint(j).sourceName;
            }
        }
    }
}

TEST(BvhImport, RotationsAndPositionsMatchIndependentForwardKinematics)
{
    // One file per rotation order and convention: ZYX (CMU), ZXY (DAZ, boxing), XYZ (MakeHuman).
    for (const char* name : {"cmu/02_01.bvh", "cmu/131_01.bvh", "threejs/pirouette.bvh", "makehuman/walk1.bvh",
                             "other/Boxing_Toes.bvh"}) {
        SCOPED_TRACE(name);
        const fs::path path = thespis::test::sharedData(std::string("mocap/") + name);
        const RawBvh raw = scanRaw(path);
        const bvh::ImportedClip& clip = imported(path);
        double extent = 0;
        for (const RawJoint& j : raw.joints)
            extent = std::max({extent, std::abs(j.offset[0]), std::abs(j.offset[1]), std::abs(j.offset[2])});
        for (int f : {0, raw.frames / 3, raw.frames - 1}) {
            const auto expected = rawWorldPositions(raw, f);
            const auto actual = clip.skeleton.worldPositions(clip.clip->frame(f));
            for (std::size_t j = 0; j < expected.size(); ++j) {
                const double error = std::hypot(actual[j].x - expected[j][0], actual[j].y - expected[j][1],
                                                actual[j].z - expected[j][2]);
                // Float storage of rotations (≈1e-7 rad per joint, summed along a chain of up to
                // 10 joints, times lever arms of a few skeleton extents) and of positions.
                EXPECT_LE(error, 2e-5 * std::max(1.0, extent))
                    << "frame " << f << " joint " << raw.joints[j].name;
            }
        }
    }
}

// ---------------------------------------------------------------------------------------------
// Naming conventions onto H-Anim.

TEST(BvhImport, EveryBodyConventionMapsItsCoreJoints)
{
    struct Expected {
        const char* file;
        const char* convention;
        std::vector<const char*> spine;                          // spine and neck joints it must have
        std::vector<std::pair<const char*, const char*>> pairs;  // file name → H-Anim name
    };
    const std::vector<Expected> expected = {
        {"cmu/02_01.bvh", "cmu", {"vl5", "vl1", "vt1", "vc4", "vc2"},
         {{"Hips", "humanoid_root"}, {"LeftShoulder", "l_sternoclavicular"}, {"LeftArm", "l_shoulder"},
          {"RightForeArm", "r_elbow"}, {"LeftUpLeg", "l_hip"}, {"RightFoot", "r_talocrural"},
          {"LeftToeBase", "l_metatarsophalangeal"}, {"Head", "skullbase"}, {"LThumb", "l_carpometacarpal_1"}}},
        {"cmu/01_01.bvh", "cmu", {"vl5", "vl1", "vt1", "vc4"}, {{"LFingers", "l_metacarpophalangeal_2"}}},
        {"cmu/131_01.bvh", "cmu-3dsmax", {"vl5", "vl1", "vt1", "vc4", "vc2"},
         {{"LeftCollar", "l_sternoclavicular"}, {"LeftShoulder", "l_shoulder"}, {"RightElbow", "r_elbow"},
          {"LeftWrist", "l_radiocarpal"}, {"LeftHip", "l_hip"}, {"RightAnkle", "r_talocrural"},
          {"lowerneck", "vc4"}, {"Chest2", "vt1"}}},
        {"threejs/pirouette.bvh", "daz", {"vl1", "vt6", "vc4"},
         {{"hip", "humanoid_root"}, {"lCollar", "l_sternoclavicular"}, {"lShldr", "l_shoulder"},
          {"rForeArm", "r_elbow"}, {"lHand", "l_radiocarpal"},
          {"lThigh", "l_hip"}, {"rShin", "r_knee"}, {"lFoot", "l_talocrural"},
          {"lIndex1", "l_metacarpophalangeal_2"}, {"rThumb1", "r_carpometacarpal_1"}}},
        {"makehuman/walk1.bvh", "makehuman", {"vl5", "vl1", "vt6", "vc4"},
         {{"Root", "humanoid_root"}, {"Hips", "sacroiliac"}, {"Clavicle_L", "l_sternoclavicular"},
          {"UpArm_L", "l_shoulder"}, {"LoArm_R", "r_elbow"}, {"Hand_L", "l_radiocarpal"}, {"UpLeg_R", "r_hip"},
          {"LoLeg_L", "l_knee"}, {"Foot_R", "r_talocrural"}, {"Middle2_L", "l_carpal_proximal_interphalangeal_3"}}},
        {"other/Boxing_Toes.bvh", "biovision", {"vl5", "vl1", "vc4"},
         {{"Hips", "humanoid_root"}, {"LeftCollar", "l_sternoclavicular"}, {"LeftShoulder", "l_shoulder"},
          {"RightElbow", "r_elbow"}, {"LeftWrist", "l_radiocarpal"}, {"RightHip", "r_hip"}, {"LeftKnee", "l_knee"},
          {"LeftAnkle", "l_talocrural"}, {"Ab", "vl5"}}},
    };
    const std::vector<const char*> core = {
        "humanoid_root", "l_hip", "r_hip", "l_knee", "r_knee", "l_talocrural", "r_talocrural", "skullbase",
        "l_sternoclavicular", "r_sternoclavicular", "l_shoulder", "r_shoulder", "l_elbow", "r_elbow",
        "l_radiocarpal", "r_radiocarpal"};

    std::set<std::string> conventionsSeen;
    for (const Expected& e : expected) {
        SCOPED_TRACE(e.file);
        const bvh::ImportedClip& clip = imported(thespis::test::sharedData(std::string("mocap/") + e.file));
        EXPECT_EQ(clip.report.convention, e.convention);
        EXPECT_TRUE(clip.report.isBody);
        conventionsSeen.insert(clip.report.convention);
        for (const char* name : core)
            EXPECT_GE(clip.skeleton.find(name), 0) << name << " missing: " << namesOf(clip.skeleton);
        for (const char* name : e.spine)
            EXPECT_GE(clip.skeleton.find(name), 0) << name << " missing: " << namesOf(clip.skeleton);
        for (const auto& [file, hanim] : e.pairs)
            EXPECT_EQ(mappedName(clip.skeleton, file), hanim) << file;
    }
    EXPECT_EQ(conventionsSeen.size(), 5u);
}

TEST(BvhImport, MappingIsConsistentWithTheHAnimHierarchy)
{
    // For every body file: each joint is either renamed to a valid H-Anim 2.0 name or listed as
    // unmapped with its own name (never dropped), names are unique, and the nearest renamed
    // ancestor of a renamed joint is one of its H-Anim ancestors: the tables respect the body's
    // structure, not only its words.
    for (const fs::path& path : mocapFiles()) {
        if (isFaceFile(path))
            continue;
        SCOPED_TRACE(relativeName(path));
        const bvh::ImportedClip& clip = imported(path);
        const Skeleton& s = clip.skeleton;
        std::set<std::string> unmapped(clip.report.unmapped.begin(), clip.report.unmapped.end());
        EXPECT_EQ(unmapped.size(), clip.report.unmapped.size());
        int renamed = 0;
        for (int j = 0; j < s.jointCount(); ++j) {
            const Joint& joint = s.joint(j);
            if (unmapped.count(joint.sourceName)) {
                EXPECT_EQ(joint.name, joint.sourceName);
                continue;
            }
            ++renamed;
            EXPECT_TRUE(hanim::isJointName(joint.name)) << joint.sourceName << " → " << joint.name;
            int ancestor = joint.parent;
            while (ancestor >= 0 && unmapped.count(s.joint(ancestor).sourceName))
                ancestor = s.joint(ancestor).parent;
            if (ancestor < 0) {
                EXPECT_EQ(joint.name, "humanoid_root");
                continue;
            }
            bool found = false;
            for (std::string_view up = hanim::parentName(joint.name); !up.empty(); up = hanim::parentName(up))
                found = found || up == s.joint(ancestor).name;
            EXPECT_TRUE(found) << joint.name << " (" << joint.sourceName << ") under " << s.joint(ancestor).name;
        }
        EXPECT_EQ(renamed + int(clip.report.unmapped.size()), s.jointCount());
        EXPECT_GE(renamed, 16);
    }
}

TEST(BvhImport, FaceRigImportsWithItsOwnNames)
{
    const bvh::ImportedClip& face = imported(thespis::test::sharedData("mocap/makehuman/face-poseunits.bvh"));
    EXPECT_FALSE(face.report.isBody);
    EXPECT_EQ(face.report.convention, "makehuman-default");
    EXPECT_EQ(face.skeleton.jointCount(), 163);
    EXPECT_EQ(int(face.report.unmapped.size()), face.skeleton.jointCount());
    for (const Joint& joint : face.skeleton.joints())
        EXPECT_EQ(joint.name, joint.sourceName);
    EXPECT_GE(face.skeleton.find("jaw"), 0);
    EXPECT_GE(face.skeleton.find("levator02.L"), 0);
}

TEST(BvhImport, SameRigWithBodyMotionIsABody)
{
    // The face file's skeleton is MakeHuman's full default rig. What makes it a face clip is that
    // only face joints move: give it two frames in which the left thigh and right elbow bend,
    // and it is a body again, mapped onto H-Anim.
    const fs::path path = thespis::test::sharedData("mocap/makehuman/face-poseunits.bvh");
    const bvh::ImportedClip& face = imported(path);
    auto text = readTextFile(path);
    ASSERT_TRUE(text);
    std::string header = text->substr(0, text->find("MOTION"));
    std::vector<double> frame0(std::size_t(face.report.channelCount), 0.0), frame1 = frame0;
    std::size_t channel = 0;
    for (const Joint& joint : face.skeleton.joints()) {
        const std::size_t positions = joint.translates ? 3 : 0;
        if (joint.sourceName == "upperleg01.L" || joint.sourceName == "lowerarm01.R")
            frame1[channel + positions] = 30; // first rotation channel
        channel += positions + joint.rotationOrder.size();
    }
    ASSERT_EQ(channel, frame0.size());
    std::ostringstream body;
    body << header << "MOTION\nFrames: 2\nFrame Time: 0.041667\n";
    for (const auto* f : {&frame0, &frame1}) {
        for (double v : *f)
            body << v << ' ';
        body << '\n';
    }
    auto result = bvh::parse(body.str());
    ASSERT_TRUE(result) << describe(result.error());
    EXPECT_TRUE(result->report.isBody);
    EXPECT_EQ(result->report.convention, "makehuman-default");
    EXPECT_EQ(mappedName(result->skeleton, "root"), "humanoid_root");
    EXPECT_EQ(mappedName(result->skeleton, "upperleg01.L"), "l_hip");
    EXPECT_EQ(mappedName(result->skeleton, "upperarm01.R"), "r_shoulder");
    EXPECT_EQ(mappedName(result->skeleton, "clavicle.L"), "l_sternoclavicular");
    EXPECT_EQ(mappedName(result->skeleton, "spine01"), "vt1");
    EXPECT_EQ(mappedName(result->skeleton, "finger3-2.R"), "r_carpal_proximal_interphalangeal_3");
    EXPECT_EQ(mappedName(result->skeleton, "jaw"), "jaw"); // facial joints keep their names
    EXPECT_EQ(mappedName(result->skeleton, "upperarm02.L"), "upperarm02.L"); // twist bone
}

TEST(BvhImport, MixamoNamesBehindANamespace)
{
    auto result = bvh::load(thespis::test::testData("bvh/mixamo_pose.bvh"));
    ASSERT_TRUE(result) << describe(result.error());
    EXPECT_EQ(result->report.convention, "mixamo");
    EXPECT_TRUE(result->report.isBody);
    EXPECT_EQ(mappedName(result->skeleton, "mixamorig:Hips"), "humanoid_root");
    EXPECT_EQ(mappedName(result->skeleton, "mixamorig:LeftShoulder"), "l_sternoclavicular");
    EXPECT_EQ(mappedName(result->skeleton, "mixamorig:LeftArm"), "l_shoulder");
    EXPECT_EQ(mappedName(result->skeleton, "mixamorig:RightHandIndex2"), "r_carpal_proximal_interphalangeal_2");
    EXPECT_EQ(mappedName(result->skeleton, "mixamorig:HeadTop_End"), "mixamorig:HeadTop_End");
    EXPECT_EQ(mappedName(result->skeleton, "mixamorig:LeftToe_End"), "mixamorig:LeftToe_End");
}

TEST(BvhImport, HAnim11NamesAreBroughtTo20)
{
    auto result = bvh::load(thespis::test::testData("bvh/hanim11_pose.bvh"));
    ASSERT_TRUE(result) << describe(result.error());
    EXPECT_EQ(result->report.convention, "hanim");
    EXPECT_TRUE(result->report.isBody);
    EXPECT_TRUE(result->report.unmapped.empty());
    EXPECT_EQ(mappedName(result->skeleton, "HumanoidRoot"), "humanoid_root");
    EXPECT_EQ(mappedName(result->skeleton, "l_ankle"), "l_talocrural");
    EXPECT_EQ(mappedName(result->skeleton, "r_wrist"), "r_radiocarpal");
    EXPECT_EQ(mappedName(result->skeleton, "l_metatarsal"), "l_metatarsophalangeal");
    EXPECT_EQ(mappedName(result->skeleton, "vt10"), "vt10");
}

TEST(BvhImport, WithoutMappingEveryJointKeepsItsName)
{
    bvh::ImportOptions options;
    options.mapToHAnim = false;
    auto result = bvh::load(thespis::test::sharedData("mocap/cmu/02_01.bvh"), options);
    ASSERT_TRUE(result);
    EXPECT_FALSE(result->report.isBody);
    EXPECT_EQ(int(result->report.unmapped.size()), result->skeleton.jointCount());
    EXPECT_GE(result->skeleton.find("LeftArm"), 0);
    EXPECT_EQ(result->skeleton.find("l_shoulder"), -1);
}

TEST(BvhImport, UnknownNamesAreNotABody)
{
    const std::string text = "HIERARCHY\nROOT thing\n{\n OFFSET 0 0 0\n CHANNELS 3 Zrotation Xrotation Yrotation\n"
                             " JOINT arm\n {\n  OFFSET 1 0 0\n  CHANNELS 3 Zrotation Xrotation Yrotation\n"
                             "  End Site\n  {\n   OFFSET 1 0 0\n  }\n }\n}\nMOTION\nFrames: 1\nFrame Time: 0.1\n0 0 0 0 0 0\n";
    auto result = bvh::parse(text);
    ASSERT_TRUE(result) << describe(result.error());
    EXPECT_EQ(result->report.convention, "none");
    EXPECT_FALSE(result->report.isBody);
    EXPECT_EQ(result->report.unmapped, (std::vector<std::string>{"thing", "arm"}));
    // The root translates even without position channels: its offset, every frame.
    const int t = result->skeleton.translationElement(0);
    ASSERT_GE(t, 0);
    EXPECT_TRUE(result->skeleton.joint(0).translates);
}

// ---------------------------------------------------------------------------------------------
// User mappings.

TEST(BvhMapping, UserMappingFileRoundTrip)
{
    const fs::path dir = scratchDir();
    const fs::path mappingPath = dir / "boxing.map";
    // Boxing_Toes with a user table: H-Anim 1.1 names are accepted and brought to 2.0, comments
    // and blank lines are skipped, "=" is allowed between the names.
    const std::string mappingText = "# Boxing_Toes.bvh onto H-Anim\n"
                                    "Hips        humanoid_root\n"
                                    "\n"
                                    "LeftHip     l_hip   # thigh\n"
                                    "LeftKnee  = l_knee\n"
                                    "LeftAnkle   l_ankle\n"
                                    "RightHip    r_hip\n"
                                    "RightKnee   r_knee\n"
                                    "RightAnkle  r_ankle\n"
                                    "Chest       vt6\n"
                                    "LeftShoulder  l_shoulder\n"
                                    "RightShoulder r_shoulder\n"
                                    "LeftElbow     l_elbow\n"
                                    "RightElbow    r_elbow\n";
    ASSERT_TRUE(writeFileAtomically(mappingPath, mappingText));
    auto mapping = bvh::loadMapping(mappingPath);
    ASSERT_TRUE(mapping) << describe(mapping.error());
    EXPECT_EQ(mapping->size(), 12u);
    EXPECT_EQ(mapping->at("LeftAnkle"), "l_talocrural");
    EXPECT_EQ(mapping->at("LeftKnee"), "l_knee");

    bvh::ImportOptions options;
    options.mapping = *mapping;
    auto first = bvh::load(thespis::test::sharedData("mocap/other/Boxing_Toes.bvh"), options);
    ASSERT_TRUE(first) << describe(first.error());
    EXPECT_EQ(first->report.convention, "user");
    EXPECT_TRUE(first->report.isBody);
    EXPECT_EQ(mappedName(first->skeleton, "Chest"), "vt6"); // the user table replaces the built-in one
    EXPECT_EQ(mappedName(first->skeleton, "LeftAnkle"), "l_talocrural");
    EXPECT_EQ(mappedName(first->skeleton, "Ab"), "Ab"); // not in the user table
    EXPECT_EQ(mappedName(first->skeleton, "LeftCollar"), "LeftCollar");
    EXPECT_EQ(int(first->report.unmapped.size()), first->skeleton.jointCount() - 12);

    // Export writes the file's names; reading it back with the same table gives the same clip.
    const fs::path out = dir / "boxing_out.bvh";
    ASSERT_TRUE(bvh::save(out, first->skeleton, *first->clip));
    auto second = bvh::load(out, options);
    ASSERT_TRUE(second) << describe(second.error());
    for (int j = 0; j < first->skeleton.jointCount(); ++j)
        EXPECT_EQ(second->skeleton.joint(j).name, first->skeleton.joint(j).name);
    EXPECT_EQ(second->report.unmapped, first->report.unmapped);
    expectSameMotion(*first, *second, "boxing_user_mapping");
    fs::remove_all(dir);
}

TEST(BvhMapping, BadLinesAreNamed)
{
    auto check = [](const std::string& text, int line, const std::string& mentions) {
        auto result = bvh::parseMapping(text);
        ASSERT_FALSE(result) << text;
        EXPECT_EQ(result.error().code, ErrorCode::CorruptData);
        EXPECT_EQ(result.error().message.rfind("line " + std::to_string(line) + ": ", 0), 0u) << result.error().message;
        EXPECT_NE(result.error().message.find(mentions), std::string::npos) << result.error().message;
    };
    check("Hips humanoid_root\nLeftHip l_hip extra\n", 2, "expected 'file_joint_name hanim_joint_name'");
    check("# header\n\nHips humanoid_root\nLeftHip l_hipp\n", 4, "'l_hipp' is not an H-Anim 2.0 joint name");
    check("Hips humanoid_root\r\nLeftHip l_hip\r\nLeftHip r_hip\r\n", 3, "mapped twice (first on line 2)");
    check("LeftHip l_hip\nLeftUpLeg l_hip\n", 2, "already the target of 'LeftHip' (line 1)");
    check("lonely\n", 1, "expected");

    // The file name is in the message of loadMapping, and a missing file is FileNotFound.
    const fs::path dir = scratchDir();
    ASSERT_TRUE(writeFileAtomically(dir / "bad.map", "Hips humanoid_root\nnot a valid line\n"));
    auto loaded = bvh::loadMapping(dir / "bad.map");
    ASSERT_FALSE(loaded);
    EXPECT_NE(loaded.error().message.find("bad.map, line 2: "), std::string::npos) << loaded.error().message;
    auto missing = bvh::loadMapping(dir / "missing.map");
    ASSERT_FALSE(missing);
    EXPECT_EQ(missing.error().code, ErrorCode::FileNotFound);
    fs::remove_all(dir);
}

TEST(BvhMapping, DuplicateTargetsKeepTheFirstJoint)
{
    bvh::ImportOptions options;
    options.mapping = bvh::JointMapping{{"Hips", "humanoid_root"}, {"Chest", "vt1"}, {"Chest2", "vt1"},
                                        {"LeftShoulder", "LeftCollar"}};
    auto result = bvh::load(thespis::test::sharedData("mocap/cmu/131_01.bvh"), options);
    ASSERT_TRUE(result) << describe(result.error());
    EXPECT_EQ(mappedName(result->skeleton, "Chest"), "vt1");
    EXPECT_EQ(mappedName(result->skeleton, "Chest2"), "Chest2");
    // A target that is another joint's own name would make two joints of one name: refused.
    EXPECT_EQ(mappedName(result->skeleton, "LeftShoulder"), "LeftShoulder");
    const auto& unmapped = result->report.unmapped;
    EXPECT_NE(std::find(unmapped.begin(), unmapped.end(), "Chest2"), unmapped.end());
    EXPECT_EQ(std::find(unmapped.begin(), unmapped.end(), "Chest"), unmapped.end());
}

// ---------------------------------------------------------------------------------------------
// Export → import.

TEST(BvhExport, RoundTripOfEveryMocapFile)
{
    for (const fs::path& path : mocapFiles()) {
        SCOPED_TRACE(relativeName(path));
        const bvh::ImportedClip& original = imported(path);
        const std::string text = bvh::write(original.skeleton, *original.clip);
        auto back = bvh::parse(text, {.upright = false}, original.clip->name());
        ASSERT_TRUE(back) << describe(back.error());
        EXPECT_EQ(back->report.convention, original.report.convention);
        EXPECT_EQ(back->report.isBody, original.report.isBody);
        EXPECT_EQ(back->report.unmapped, original.report.unmapped);
        EXPECT_EQ(back->report.jointCount, original.report.jointCount);
        EXPECT_EQ(back->report.frameCount, original.report.frameCount);
        EXPECT_EQ(back->clip->frameRate(), original.clip->frameRate()); // exactly
        ASSERT_EQ(back->skeleton.jointCount(), original.skeleton.jointCount());
        for (int j = 0; j < original.skeleton.jointCount(); ++j) {
            const Joint& a = original.skeleton.joint(j);
            const Joint& b = back->skeleton.joint(j);
            EXPECT_EQ(b.name, a.name);
            EXPECT_EQ(b.sourceName, a.sourceName);
            EXPECT_EQ(b.parent, a.parent);
            EXPECT_EQ(b.rotationOrder, a.rotationOrder);
            EXPECT_EQ(b.translates, a.translates);
            EXPECT_NEAR(b.offset.x, a.offset.x, 1e-8 * std::max(1.0, std::abs(a.offset.x)));
            EXPECT_NEAR(b.offset.y, a.offset.y, 1e-8 * std::max(1.0, std::abs(a.offset.y)));
            EXPECT_NEAR(b.offset.z, a.offset.z, 1e-8 * std::max(1.0, std::abs(a.offset.z)));
            ASSERT_EQ(b.endSite.has_value(), a.endSite.has_value()) << a.sourceName;
            if (a.endSite) {
                EXPECT_NEAR(b.endSite->y, a.endSite->y, 1e-8 * std::max(1.0, std::abs(a.endSite->y)));
            }
        }
        expectSameMotion(original, *back, path.stem().string());
    }
}

TEST(BvhExport, WritesTheStandardLayout)
{
    const bvh::ImportedClip& walk = imported(thespis::test::sharedData("mocap/cmu/02_01.bvh"));
    const std::string text = bvh::write(walk.skeleton, *walk.clip);
    EXPECT_EQ(text.rfind("HIERARCHY\nROOT Hips\n{\n\tOFFSET 0 0 0\n"
                         "\tCHANNELS 6 Xposition Yposition Zposition Zrotation Yrotation Xrotation\n"
                         "\tJOINT LHipJoint\n\t{\n",
                         0),
              0u)
        << text.substr(0, 300);
    EXPECT_NE(text.find("\n\t\t\t\t\t\tEnd Site\n\t\t\t\t\t\t{\n"), std::string::npos);
    EXPECT_NE(text.find("\nMOTION\nFrames: 343\nFrame Time: 0.008333\n"), std::string::npos);
    EXPECT_EQ(text.find('\r'), std::string::npos);
    // Nine significant digits at most.
    const std::size_t start = text.find("Frame Time: 0.008333\n") + 21;
    std::istringstream values(text.substr(start, text.find('\n', start) - start));
    int count = 0;
    for (std::string v; values >> v; ++count) {
        std::string digits;
        for (char c : v.substr(0, v.find_first_of("eE")))
            if (std::isdigit(static_cast<unsigned char>(c)))
                digits += c;
        digits.erase(0, digits.find_first_not_of('0')); // leading zeros are not significant
        EXPECT_LE(digits.size(), 9u) << v;
    }
    EXPECT_EQ(count, walk.report.channelCount);
}

TEST(BvhExport, SaveIsAtomicAndLoadable)
{
    const fs::path dir = scratchDir();
    const bvh::ImportedClip& pirouette = imported(thespis::test::sharedData("mocap/threejs/pirouette.bvh"));
    const fs::path out = dir / "pirouette.bvh";
    ASSERT_TRUE(bvh::save(out, pirouette.skeleton, *pirouette.clip));
    for (const auto& entry : fs::directory_iterator(dir))
        EXPECT_EQ(entry.path().filename(), "pirouette.bvh"); // no temporary left behind
    auto back = bvh::load(out);
    ASSERT_TRUE(back);
    expectSameMotion(pirouette, *back, "pirouette_saved");
    EXPECT_FALSE(bvh::save(dir / "no_such_folder" / "x.bvh", pirouette.skeleton, *pirouette.clip));
    fs::remove_all(dir);
}

TEST(BvhExport, EveryRotationOrderAndGimbalLock)
{
    // One joint per Euler order, plus joints with one and two rotation channels; random
    // rotations and the gimbal-lock poses (middle angle ±90°) of each order.
    const std::vector<std::string> orders = {"XYZ", "XZY", "YXZ", "YZX", "ZXY", "ZYX", "Y", "ZX", ""};
    std::vector<Joint> joints;
    for (std::size_t i = 0; i < orders.size(); ++i) {
        Joint joint;
        joint.name = "j" + std::to_string(i) + "_" + orders[i];
        joint.parent = i == 0 ? -1 : 0;
        joint.offset = {double(i), 1, 0};
        joint.rotationOrder = orders[i];
        joint.endSite = Vec3d{0, 1, 0};
        joints.push_back(joint);
    }
    auto skeleton = Skeleton::create(joints);
    ASSERT_TRUE(skeleton);
    const FrameLayout& layout = *skeleton->frameLayout();

    std::mt19937 random(7);
    std::uniform_real_distribution<double> angle(-std::numbers::pi, std::numbers::pi);
    auto axisQuat = [](char axis, double a) {
        return Quatd::fromAxisAngle(axis == 'X' ? Vec3d{1, 0, 0} : axis == 'Y' ? Vec3d{0, 1, 0} : Vec3d{0, 0, 1}, a);
    };
    std::vector<float> frames;
    const int frameCount = 200;
    for (int f = 0; f < frameCount; ++f) {
        std::vector<float> frame = skeleton->restFrame();
        for (std::size_t i = 0; i < orders.size(); ++i) {
            const std::string& order = orders[i];
            Quatd q = Quatd::identity();
            for (std::size_t k = 0; k < order.size(); ++k) {
                double a = angle(random);
                if (order.size() == 3 && k == 1 && f % 4 == 0)
                    a = (f % 8 == 0 ? 0.5 : -0.5) * std::numbers::pi; // gimbal lock
                q = q * axisQuat(order[k], a);
            }
            rotationAt(std::span<float>(frame), int(i)) = Quat{float(q.x), float(q.y), float(q.z), float(q.w)};
        }
        const std::size_t t = layout.translationOffset();
        frame[t] = float(f) * 0.25f;
        frame[t + 1] = -3.5f;
        frame[t + 2] = 1e-3f * float(f);
        frames.insert(frames.end(), frame.begin(), frame.end());
    }
    auto clip = KeyframeClip::create(skeleton->frameLayout(), 30, frames, "orders");
    ASSERT_TRUE(clip) << describe(clip.error());

    const std::string text = bvh::write(*skeleton, **clip);
    auto back = bvh::parse(text);
    ASSERT_TRUE(back) << describe(back.error()) << "\n" << text.substr(0, 2000);
    for (std::size_t i = 0; i < orders.size(); ++i)
        EXPECT_EQ(back->skeleton.joint(int(i)).rotationOrder, orders[i]);
    // The joint without rotation channels stays the identity.
    const int none = int(orders.size()) - 1;
    for (int f = 0; f < frameCount; ++f) {
        const Quat& q = rotationAt(back->clip->frame(f), none);
        EXPECT_EQ(q, Quat::identity());
    }
    for (int f = 0; f < frameCount; ++f) {
        for (int r = 0; r < none; ++r) {
            const double d = angleOf(rotationAt((*clip)->frame(f), r), rotationAt(back->clip->frame(f), r));
            ASSERT_LE(d, 2e-6) << "order " << orders[std::size_t(r)] << " frame " << f;
        }
        const auto a = (*clip)->frame(f), b = back->clip->frame(f);
        for (std::size_t k = layout.translationOffset(); k < layout.floatCount(); ++k)
            EXPECT_EQ(a[k], b[k]); // float → 9 digits → float is exact
    }
}

TEST(BvhExport, EulerCurvesStayContinuous)
{
    // A joint turning steadily about Y through ±180° several times, and one passing through
    // gimbal lock: consecutive frames of the written channels differ by the motion, never by a
    // 360° wrap or a jump to the other Euler solution.
    std::vector<Joint> joints(2);
    joints[0].name = "root";
    joints[0].rotationOrder = "ZXY";
    joints[1].name = "arm";
    joints[1].parent = 0;
    joints[1].rotationOrder = "ZYX";
    auto skeleton = Skeleton::create(joints);
    ASSERT_TRUE(skeleton);
    std::vector<float> frames;
    const int frameCount = 400;
    for (int f = 0; f < frameCount; ++f) {
        std::vector<float> frame = skeleton->restFrame();
        const double a = 0.05 * f; // radians: about three full turns
        const Quatd spin = Quatd::fromAxisAngle({0, 1, 0}, a);
        // ZYX with the middle (Y) angle sweeping through ±90°: Rz(0.3)·Ry(b)·Rx(0.2).
        const double b = -2.0 + 4.0 * f / frameCount;
        const Quatd lock = Quatd::fromAxisAngle({0, 0, 1}, 0.3) * Quatd::fromAxisAngle({0, 1, 0}, b)
                           * Quatd::fromAxisAngle({1, 0, 0}, 0.2);
        rotationAt(std::span<float>(frame), 0) = Quat{float(spin.x), float(spin.y), float(spin.z), float(spin.w)};
        rotationAt(std::span<float>(frame), 1) = Quat{float(lock.x), float(lock.y), float(lock.z), float(lock.w)};
        frames.insert(frames.end(), frame.begin(), frame.end());
    }
    auto clip = KeyframeClip::create(skeleton->frameLayout(), 60, frames);
    ASSERT_TRUE(clip);
    const std::string text = bvh::write(*skeleton, **clip);
    std::istringstream in(text.substr(text.find("Frame Time:")));
    std::string line;
    std::getline(in, line);
    std::vector<double> previous;
    int lines = 0;
    while (std::getline(in, line)) {
        std::istringstream values(line);
        std::vector<double> v;
        for (double x; values >> x;)
            v.push_back(x);
        ASSERT_EQ(v.size(), 9u);
        if (!previous.empty()) {
            // 0.05 rad = 2.9° per frame for the spin; the locked joint's angles move by at most
            // a few degrees per frame away from the lock.
            for (std::size_t k = 3; k < 6; ++k)
                EXPECT_LE(std::abs(v[k] - previous[k]), 3.0) << "frame " << lines << " channel " << k << "\n" << line;
            for (std::size_t k = 6; k < 9; ++k)
                EXPECT_LE(std::abs(v[k] - previous[k]), 20.0) << "frame " << lines << " channel " << k << "\n" << line;
        }
        previous = v;
        ++lines;
    }
    EXPECT_EQ(lines, frameCount);
    auto back = bvh::parse(text);
    ASSERT_TRUE(back);
    for (int f = 0; f < frameCount; ++f)
        for (int r = 0; r < 2; ++r)
            ASSERT_LE(angleOf(rotationAt((*clip)->frame(f), r), rotationAt(back->clip->frame(f), r)), 2e-6) << f;
}

TEST(BvhExport, ClipOnAnotherLayoutIsWrittenByName)
{
    // A clip whose layout lacks some joints of the skeleton (e.g. a schedule's output on the
    // 25-joint subset): the missing joints are written at rest.
    const Skeleton& subset = hanim::skeleton(hanim::Level::Subset25);
    std::vector<float> frame = subset.restFrame();
    const int elbow = subset.find("l_elbow");
    const Quatd bend = Quatd::fromAxisAngle({1, 0, 0}, 1.0);
    rotationAt(std::span<float>(frame), elbow) = Quat{float(bend.x), float(bend.y), float(bend.z), float(bend.w)};
    auto clip = KeyframeClip::create(subset.frameLayout(), 30, frame);
    ASSERT_TRUE(clip);
    const Skeleton& full = hanim::skeleton(hanim::Level::Loa2);
    auto back = bvh::parse(bvh::write(full, **clip));
    ASSERT_TRUE(back) << describe(back.error());
    EXPECT_EQ(back->skeleton.jointCount(), full.jointCount());
    EXPECT_EQ(back->report.convention, "hanim");
    const int backElbow = back->skeleton.find("l_elbow");
    ASSERT_GE(backElbow, 0);
    EXPECT_LE(angleOf(rotationAt(back->clip->frame(0), backElbow), rotationAt((*clip)->frame(0), elbow)), 2e-6);
    const int finger = back->skeleton.find("l_metacarpophalangeal_3");
    ASSERT_GE(finger, 0);
    EXPECT_EQ(rotationAt(back->clip->frame(0), finger), Quat::identity());
}

// ---------------------------------------------------------------------------------------------
// Mirror, frame rate.

TEST(BvhMirror, MirrorTwiceGivesTheClipBack)
{
    for (const fs::path& path : mocapFiles()) {
        SCOPED_TRACE(relativeName(path));
        const bvh::ImportedClip& clip = imported(path);
        auto once = Mirror::create(clip.clip);
        ASSERT_TRUE(once);
        auto twice = Mirror::create(*once);
        ASSERT_TRUE(twice);
        std::vector<float> a(clip.clip->layout()->floatCount()), b(a.size());
        for (int f = 0; f < clip.clip->frameCount(); ++f) {
            const double t = f / clip.clip->frameRate();
            clip.clip->evaluate(t, a);
            (*twice)->evaluate(t, b);
            for (std::size_t k = 0; k < a.size(); ++k)
                ASSERT_NEAR(a[k], b[k], 1e-6) << "frame " << f << " float " << k;
        }
    }
}

TEST(BvhMirror, MirrorSwapsTheMappedSides)
{
    // Mirroring is only meaningful when left and right joints find each other: on a mapped CMU
    // walk, the mirrored left hip is the reflected right hip.
    const bvh::ImportedClip& walk = imported(thespis::test::sharedData("mocap/cmu/02_01.bvh"));
    auto mirrored = Mirror::create(walk.clip);
    ASSERT_TRUE(mirrored);
    const FrameLayout& layout = *walk.clip->layout();
    for (const Joint& joint : walk.skeleton.joints())
        EXPECT_GE(layout.find(hanim::mirrorName(joint.name), ElementKind::Rotation), 0) << joint.name;
    std::vector<float> a(layout.floatCount()), m(a.size());
    const int left = walk.skeleton.find("l_hip"), right = walk.skeleton.find("r_hip");
    for (double t : {0.0, 0.5, 1.0, 2.0}) {
        walk.clip->evaluate(t, a);
        (*mirrored)->evaluate(t, m);
        const Quat& r = rotationAt(std::span<const float>(a), right);
        const Quat reflected{r.x, -r.y, -r.z, r.w};
        EXPECT_LE(angleOf(rotationAt(std::span<const float>(m), left), reflected), 1e-6);
        EXPECT_GT(angleOf(rotationAt(std::span<const float>(m), left), rotationAt(std::span<const float>(a), left)), 1e-3);
    }
}

// MakeHuman's walk is Z-up (Blender's axes): it is stood up, exactly, and says so; the files
// already in H-Anim's axes are left exactly as they are.
TEST(BvhImport, ABodyLyingDownIsStoodUp)
{
    const fs::path walk = thespis::test::sharedData("mocap/makehuman/walk1.bvh");
    auto upright = bvh::load(walk);
    ASSERT_TRUE(upright.ok()) << describe(upright.error());
    EXPECT_EQ(upright->report.turnedFrom, "+Z up, facing −Y");
    const bvh::ImportedClip& raw = imported(walk);
    for (int j = 0; j < raw.skeleton.jointCount(); ++j) {
        const Vec3d a = raw.skeleton.joint(j).offset, b = upright->skeleton.joint(j).offset;
        EXPECT_EQ(b.x, a.x);
        EXPECT_EQ(b.y, a.z);
        EXPECT_EQ(b.z, -a.y);
    }
    const std::vector<Vec3d> rest = upright->skeleton.worldPositions(upright->skeleton.restFrame());
    const auto at = [&](const char* name) { return rest[std::size_t(upright->skeleton.find(name))]; };
    EXPECT_GT(at("skullbase").y, at("humanoid_root").y + 3.0); // decimetres: the head is above the hips
    EXPECT_GT(at("l_hip").x, at("r_hip").x);                   // its left is +X: it faces +Z
    // Poses stay the same body: the head stays as far from the toes in every frame.
    std::vector<Vec3d> rawPositions(std::size_t(raw.skeleton.jointCount())), positions(rawPositions.size());
    std::vector<Quatd> rawOrientations(rawPositions.size()), orientations(rawPositions.size());
    for (int f = 0; f < raw.clip->frameCount(); ++f) {
        raw.skeleton.worldTransforms(raw.clip->frame(f), rawPositions, rawOrientations);
        upright->skeleton.worldTransforms(upright->clip->frame(f), positions, orientations);
        for (std::size_t j = 0; j < positions.size(); ++j) {
            EXPECT_NEAR(positions[j].y, rawPositions[j].z, 1e-4);
            EXPECT_NEAR(positions[j].z, -rawPositions[j].y, 1e-4);
        }
    }
    for (const fs::path& path : mocapFiles()) {
        if (path == walk || isFaceFile(path))
            continue;
        auto stood = bvh::load(path);
        ASSERT_TRUE(stood.ok());
        EXPECT_EQ(stood->report.turnedFrom, "") << path;
        EXPECT_EQ(stood->clip->data(), imported(path).clip->data()) << path;
    }
}

// CMU's MB2 releases open with a T-pose frame; the motion starts on the next one.
TEST(BvhImport, ACalibrationFirstFrameIsFoundAndCanBeLeftOut)
{
    const std::set<std::string> calibrated = {"cmu/01_01.bvh",  "cmu/77_02.bvh",  "cmu/111_28.bvh", "cmu/113_21.bvh",
                                              "cmu/140_06.bvh", "cmu/140_07.bvh", "cmu/141_20.bvh"};
    for (const fs::path& path : mocapFiles()) {
        SCOPED_TRACE(relativeName(path));
        const bvh::ImportedClip& whole = imported(path);
        EXPECT_EQ(whole.report.calibrationFrame, calibrated.count(relativeName(path)) > 0);
        if (!whole.report.calibrationFrame)
            continue;
        auto dropped = bvh::load(path, {.upright = false, .dropCalibrationFrame = true});
        ASSERT_TRUE(dropped.ok());
        EXPECT_EQ(dropped->report.frameCount, whole.report.frameCount); // the header's count
        ASSERT_EQ(dropped->clip->frameCount(), whole.clip->frameCount() - 1);
        // The same frames from the second on (keys are stored in one hemisphere along the clip, so
        // a rotation may come back with the other sign).
        const FrameLayout& layout = *whole.skeleton.frameLayout();
        for (int f = 0; f < dropped->clip->frameCount(); ++f) {
            const auto a = dropped->clip->frame(f), b = whole.clip->frame(f + 1);
            for (int r = 0; r < layout.rotationCount(); ++r)
                EXPECT_NEAR(std::abs(dot(rotationAt(a, r), rotationAt(b, r))), 1.0f, 1e-6f);
            EXPECT_TRUE(std::equal(a.begin() + std::ptrdiff_t(layout.translationOffset()), a.end(),
                                   b.begin() + std::ptrdiff_t(layout.translationOffset())));
        }
    }
}

TEST(BvhImport, FrameRateOverride)
{
    // CMU 77_02's header says 120 fps; the CMU index says it was captured at 60.
    bvh::ImportOptions options;
    options.frameRate = 60.0;
    auto clip = bvh::load(thespis::test::sharedData("mocap/cmu/77_02.bvh"), options);
    ASSERT_TRUE(clip) << describe(clip.error());
    EXPECT_EQ(clip->clip->frameRate(), 60.0);
    EXPECT_EQ(clip->clip->frameCount(), 938);
    EXPECT_DOUBLE_EQ(clip->clip->domain().end, 937.0 / 60.0);
    EXPECT_DOUBLE_EQ(clip->report.frameTime, 0.0083333); // the header, as it is
    // Same keys, only slower: key 100 is at 100/60 s now.
    const bvh::ImportedClip& header = imported(thespis::test::sharedData("mocap/cmu/77_02.bvh"));
    std::vector<float> a(header.clip->layout()->floatCount()), b(a.size());
    header.clip->evaluate(100 / header.clip->frameRate(), a);
    clip->clip->evaluate(100 / 60.0, b);
    for (std::size_t k = 0; k < a.size(); ++k)
        EXPECT_NEAR(a[k], b[k], 1e-6);

    for (double bad : {0.0, -30.0, std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()}) {
        options.frameRate = bad;
        auto refused = bvh::parse(kGood, options);
        ASSERT_FALSE(refused);
        EXPECT_EQ(refused.error().code, ErrorCode::InvalidArgument);
    }
}

// ---------------------------------------------------------------------------------------------
// Malformed input: every error is CorruptData naming its line.

TEST(BvhErrors, TheGoodFileParses)
{
    auto result = bvh::parse(kGood);
    ASSERT_TRUE(result) << describe(result.error());
    EXPECT_EQ(result->report.frameCount, 3);
    EXPECT_EQ(result->report.channelCount, 9);
    // ZXY: R = Rz(10°) at frame 3 for the root, and Chest = Rz(12)·Rx(22)·Ry(32).
    const Quatd expected = Quatd::fromAxisAngle({0, 0, 1}, 12 * std::numbers::pi / 180)
                           * Quatd::fromAxisAngle({1, 0, 0}, 22 * std::numbers::pi / 180)
                           * Quatd::fromAxisAngle({0, 1, 0}, 32 * std::numbers::pi / 180);
    const Quat e{float(expected.x), float(expected.y), float(expected.z), float(expected.w)};
    EXPECT_LE(angleOf(rotationAt(result->clip->frame(2), 1), e), 1e-6);
}

TEST(BvhErrors, NotBvh)
{
    for (const char* text : {"", "   \n", "{ \"json\": true }", "hierarchy_of_needs\nROOT", "MOTION\nFrames: 1\n"}) {
        auto result = bvh::parse(text);
        ASSERT_FALSE(result);
        EXPECT_EQ(result.error().code, ErrorCode::NotOurFormat) << text;
    }
}

// Blank replacement lines ("\t") keep the line numbers of the rest of the file.
TEST(BvhErrors, Hierarchy)
{
    expectCorruptAt(withLine(2, "JOINT Hips"), 2, "expected ROOT");
    expectCorruptAt(withLine(2, "ROOT"), 2, "expected a joint name after ROOT");
    expectCorruptAt(withLine(3, "\t"), 4, "expected '{' after ROOT Hips, found 'OFFSET'");
    expectCorruptAt(withLine(4, "\tOFFSET 0 0"), 4, "expected OFFSET x y z for joint 'Hips', found the end of the line");
    expectCorruptAt(withLine(8, "\t\tOFFSET 0 foo 0"), 8, "expected OFFSET x y z for joint 'Chest', found 'foo'");
    expectCorruptAt(withLine(8, "\t\tOFFSET 0 nan 0"), 8, "found 'nan'");
    expectCorruptAt(withLine(8, "\t\tOFFSET 0 1e999 0"), 8, "found '1e999'");
    expectCorruptAt(withLine(8, "\t\tOFFSET 0 1e300 0"), 8, "the OFFSET of joint 'Chest' is out of range: '1e300'");
    expectCorruptAt(withLine(8, "\t\tOFFSET 1 2 3\n\t\tOFFSET 1 2 3"), 9, "second OFFSET");
    expectCorruptAt(withLine(8, "\t"), 14, "joint 'Chest' (line 6) has no OFFSET");
    expectCorruptAt(withLine(9, "\t\tCHANNELS 3 Zrotation Xrotation Wrotation"), 9, "found 'Wrotation'");
    expectCorruptAt(withLine(9, "\t\tCHANNELS 7 Zrotation Xrotation Yrotation"), 9, "channel count from 0 to 6");
    expectCorruptAt(withLine(9, "\t\tCHANNELS 3 Zrotation Xrotation"), 9, "expected 3 channel names");
    expectCorruptAt(withLine(9, "\t\tCHANNELS 2 Zrotation Zrotation"), 9, "lists channel 'Zrotation' twice");
    expectCorruptAt(withLine(9, "\t\tCHANNELS three Zrotation"), 9, "found 'three'");
    expectCorruptAt(withLine(9, "\t\tCHANNEL 3 Zrotation Xrotation Yrotation"), 9,
                    "expected OFFSET, CHANNELS, JOINT, End Site or '}' in joint 'Chest', found 'CHANNEL'");
    expectCorruptAt(withLine(9, "\t"), 14, "joint 'Chest' (line 6) has no CHANNELS");
    expectCorruptAt(withLine(5, "\t"), 6, "needs its OFFSET and CHANNELS before JOINT");
    expectCorruptAt(withLine(6, "\tJOINT Hips"), 6, "a second joint named 'Hips' (the first is on line 2)");
    expectCorruptAt(withLine(7, "\t"), 8, "expected '{' after JOINT Chest");
    expectCorruptAt(withLine(10, "\t\tEnd Sight"), 10, "expected 'End Site', found 'End Sight'");
    expectCorruptAt(withLine(11, "\t"), 12, "expected '{' after End Site");
    expectCorruptAt(withLine(12, "\t\t\tOFFSET 0 5"), 12, "End Site of 'Chest'");
    expectCorruptAt(withLine(12, "\t\t\tOFSET 0 5 0"), 12, "expected OFFSET x y z in the End Site of 'Chest'");
    expectCorruptAt(withLine(13, "\t\t}\n\t\tEnd Site\n\t\t{\n\t\t\tOFFSET 0 1 0"), 14, "second End Site");
    // A missing '}' shows where the parser meets what cannot be inside a joint.
    expectCorruptAt(withLine(14, "\t"), 16, "in joint 'Hips', found 'MOTION'");
    expectCorruptAt(withLine(15, "}\nROOT Other\n{\n}"), 16, "a second ROOT");
    expectCorruptAt(withLine(16, "MOTIONS"), 16, "expected MOTION after the hierarchy, found 'MOTIONS'");
    // The file ends inside a joint: the error names the last line there is.
    expectCorruptAt(std::string(kGood).substr(0, std::string(kGood).find("\t\tEnd Site")), 9, "the file ends inside joint 'Chest'");
    expectCorruptAt(std::string(kGood).substr(0, std::string(kGood).find("MOTION")), 15, "expected MOTION");
    // Control bytes are shown escaped.
    expectCorruptAt(withLine(9, std::string("\t\tCHANNELS 3 Zrot\x01tion Xrotation Yrotation")), 9, "'Zrot\\x01tion'");
}

TEST(BvhErrors, Motion)
{
    expectCorruptAt(withLine(17, "Frames: x"), 17, "expected a whole number of frames after 'Frames:', found 'x'");
    expectCorruptAt(withLine(17, "Frames: 2.5"), 17, "found '2.5'");
    expectCorruptAt(withLine(17, "Frames: 0"), 17, "a clip needs at least one frame");
    expectCorruptAt(withLine(17, "Frames: -3"), 17, "at least one frame");
    expectCorruptAt(withLine(17, "Frames: 2000000"), 17, "more than the 1000000 frames");
    expectCorruptAt(withLine(17, "Frames: 99999999999999999999"), 17, "expected a whole number");
    expectCorruptAt(withLine(17, "Frames: 999999"), 21, "the file ends after 3 frames, but 'Frames:' announces 999999");
    expectCorruptAt(withLines({{17, "Frames: 1000000"}, {5, std::string("\tCHANNELS 6 Xposition Yposition Zposition Zrotation Xrotation Yrotation")
                                                                 + std::string(9994, ' ')}}),
                    21, "ends after 3 frames");
    expectCorruptAt(withLine(17, "Frame: 3"), 17, "expected 'Frames:' after MOTION");
    expectCorruptAt(withLine(17, "Frames 3"), 17, "expected ':' after 'Frames'");
    expectCorruptAt(withLine(17, "Frames:"), 17, "expected a value after 'Frames:'");
    expectCorruptAt(withLine(17, "Frames: 3 frames"), 17, "unexpected 'frames' after the frame count");
    expectCorruptAt(withLine(18, "Frame Time: 0"), 18, "must be a positive number of seconds");
    expectCorruptAt(withLine(18, "Frame Time: -0.04"), 18, "must be a positive");
    expectCorruptAt(withLine(18, "Frame Time: 1e-320"), 18, "must be a positive"); // 1/t overflows
    expectCorruptAt(withLine(18, "Frame Time: fast"), 18, "expected a number of seconds after 'Frame Time:'");
    expectCorruptAt(withLine(18, "Frame Rate: 25"), 18, "expected 'Frame Time:'");
    expectCorruptAt(withLine(18, "Frame Time: 0.04 s"), 18, "unexpected 's' after the frame time");
    expectCorruptAt(withLine(20, "1 90 0 5 0 0 11 21"), 20, "frame 2 has 8 values; the hierarchy declares 9");
    expectCorruptAt(withLine(20, "1 90 0 5 0 0 11 21 31 41"), 20, "frame 2 has more than the 9 values");
    expectCorruptAt(withLine(20, "1 90 0 5 0 zero 11 21 31"), 20, "value 6 of frame 2 is not a finite number: 'zero'");
    expectCorruptAt(withLine(20, "1 90 0 5 0 inf 11 21 31"), 20, "'inf'");
    expectCorruptAt(withLine(20, "1 90 0 5 0 -nan 11 21 31"), 20, "'-nan'");
    expectCorruptAt(withLine(20, "1 90 0 5 0 1e400 11 21 31"), 20, "'1e400'");
    expectCorruptAt(withLine(20, "1 90 0 5 0 0x1p3 11 21 31"), 20, "'0x1p3'");
    expectCorruptAt(withLine(20, "1e39 90 0 5 0 0 11 21 31"), 20, "a position of joint 'Hips' in frame 2 is out of range");
    expectCorruptAt(withLine(21, "\t"), 21, "the file ends after 2 frames, but 'Frames:' announces 3");
    expectCorruptAt(std::string(kGood).substr(0, std::string(kGood).find("2 90 0 10")), 20, "ends after 2 frames");
    // Lines after the announced frames must still be frames (see ExtraFrameLinesFollowTheHeader).
    expectCorruptAt(withLine(21, "2 90 0 10 0 0 12 22 32\n3 90 0 0 0"), 22, "frame 4 has 5 values");
    expectCorruptAt(withLine(21, "2 90 0 10 0 0 12 22 32\n\n}"), 23, "value 1 of frame 4 is not a finite number: '}'");
    // Frames of a hierarchy without any channel cannot be told apart.
    expectCorruptAt(withLines({{5, "\tCHANNELS 0"}, {9, "\t\tCHANNELS 0"}}), 16, "declares no channels");
}

TEST(BvhImport, ExtraFrameLinesFollowTheHeader)
{
    // Some exporters write one frame line more than "Frames:" says (Boxing_Toes.bvh: 3070 lines,
    // "Frames: 3069"). The header is the contract: the clip has the announced frames.
    auto result = bvh::parse(withLine(21, "2 90 0 10 0 0 12 22 32\n3 90 0 99 0 0 0 0 0"));
    ASSERT_TRUE(result) << describe(result.error());
    EXPECT_EQ(result->report.frameCount, 3);
    EXPECT_EQ(result->clip->frameCount(), 3);
    const auto last = result->clip->frame(2);
    EXPECT_EQ(last[result->clip->layout()->floatOffset(result->skeleton.translationElement(0))], 2.0f);
}

TEST(BvhErrors, LimitsAreCheckedBeforeAllocating)
{
    // 10,001 joints: refused at the JOINT that is one too many.
    std::string many = "HIERARCHY\nROOT r\n{\nOFFSET 0 0 0\nCHANNELS 3 Zrotation Xrotation Yrotation\n";
    for (int k = 1; k <= 10000; ++k)
        many += "JOINT j" + std::to_string(k) + "\n{\nOFFSET 0 0 0\nCHANNELS 0\n}\n";
    many += "}\nMOTION\nFrames: 1\nFrame Time: 1\n0 0 0\n";
    expectCorruptAt(many, 6 + 5 * 9999, "more than 10000 joints");

    // 9,999 joints are allowed, but not a million frames of them: refused at "Frames:".
    std::string wide = "HIERARCHY\nROOT r\n{\nOFFSET 0 0 0\nCHANNELS 3 Zrotation Xrotation Yrotation\n";
    for (int k = 1; k < 9999; ++k)
        wide += "JOINT j" + std::to_string(k) + "\n{\nOFFSET 0 0 0\nCHANNELS 0\n}\n";
    const int framesLine = 5 + 5 * 9998 + 3;
    expectCorruptAt(wide + "}\nMOTION\nFrames: 1000000\nFrame Time: 1\n0 0 0\n", framesLine, "more than 1 GiB");
    auto fits = bvh::parse(wide + "}\nMOTION\nFrames: 2\nFrame Time: 1\n0 0 0\n1 2 3\n");
    ASSERT_TRUE(fits) << describe(fits.error());
    EXPECT_EQ(fits->skeleton.jointCount(), 9999);

    // Deep nesting is read without recursion.
    std::string deep = "HIERARCHY\nROOT r\n{\nOFFSET 0 0 0\nCHANNELS 3 Zrotation Xrotation Yrotation\n";
    const int depth = 9000;
    for (int k = 1; k <= depth; ++k)
        deep += "JOINT j" + std::to_string(k) + " {\nOFFSET 0 1 0\nCHANNELS 0\n";
    for (int k = 0; k <= depth; ++k)
        deep += "} ";
    deep += "\nMOTION\nFrames: 1\nFrame Time: 1\n0 0 45\n";
    auto result = bvh::parse(deep);
    ASSERT_TRUE(result) << describe(result.error());
    EXPECT_EQ(result->skeleton.jointCount(), depth + 1);
    EXPECT_EQ(result->skeleton.joint(depth).parent, depth - 1);
}

TEST(BvhErrors, LineEndingsDoNotChangeLineNumbers)
{
    const std::string bad = withLine(20, "1 90 0 5 0 0 11 21");
    for (const char* newline : {"\r\n", "\r"}) {
        std::string good(kGood), broken = bad;
        for (std::string* text : {&good, &broken}) {
            std::string converted;
            for (char c : *text)
                converted += c == '\n' ? std::string(newline) : std::string(1, c);
            *text = converted;
        }
        auto result = bvh::parse(good);
        ASSERT_TRUE(result) << describe(result.error());
        EXPECT_EQ(result->report.frameCount, 3);
        expectCorruptAt(broken, 20, "frame 2 has 8 values");
    }
}

TEST(BvhImport, TolerantSpellings)
{
    const std::vector<std::string> variants = {
        withLine(17, "Frames:    3"),
        withLine(17, "Frames:3"),
        withLine(17, "Frames :\t3"),
        withLine(18, "Frame Time:\t0.04"),
        withLine(18, "FrameTime: 0.04"),
        withLine(18, "Frame Time:0.04"),
        withLines({{2, "ROOT Hips {"}, {3, "\t"}}), // the brace on the name's line
        withLine(1, "\xEF\xBB\xBFHIERARCHY"),
        withLine(1, "hierarchy"),
        withLine(20, "\n+1 90.0 0e0 5 -0 .0 11 21 31\n\n"),
        withLine(9, "\t\tCHANNELS 3 zROTATION xrotation YRotation"),
        withLine(6, "\tJOINT Upper Chest"),
        std::string(kGood) + "\n\n   \n",
    };
    for (const std::string& text : variants) {
        auto result = bvh::parse(text);
        ASSERT_TRUE(result) << describe(result.error()) << "\n" << text;
        EXPECT_EQ(result->report.frameCount, 3);
        EXPECT_DOUBLE_EQ(result->report.frameTime, 0.04);
        EXPECT_EQ(result->report.channelCount, 9);
    }
    auto spaced = bvh::parse(withLine(6, "\tJOINT Upper Chest"));
    ASSERT_TRUE(spaced);
    EXPECT_EQ(spaced->skeleton.joint(1).sourceName, "Upper Chest");
}

TEST(BvhImport, PartialChannelSets)
{
    // Joints with position channels only, one or two rotation channels, none at all, and
    // positions after rotations: each joint's rotation is the product of its own channels,
    // position channels replace the offset's components, the rest keep the offset.
    const std::string text = "HIERARCHY\nROOT base\n{\n OFFSET 1 2 3\n CHANNELS 1 Yrotation\n"
                             " JOINT slider\n {\n  OFFSET 0 1 0\n  CHANNELS 1 Yposition\n"
                             "  JOINT hinge\n  {\n   OFFSET 0 1 0\n   CHANNELS 2 Xrotation Zrotation\n"
                             "   JOINT rigid\n   {\n    OFFSET 0 0.5 0\n    CHANNELS 0\n   }\n  }\n }\n"
                             " JOINT free\n {\n  OFFSET 1 0 0\n  CHANNELS 6 Zrotation Yrotation Xrotation Xposition Yposition Zposition\n }\n}\n"
                             "MOTION\nFrames: 1\nFrame Time: 0.5\n90 7 30 60 10 20 30 4 5 6\n";
    auto result = bvh::parse(text);
    ASSERT_TRUE(result) << describe(result.error());
    const Skeleton& s = result->skeleton;
    EXPECT_EQ(s.joint(0).rotationOrder, "Y");
    EXPECT_EQ(s.joint(1).rotationOrder, "");
    EXPECT_TRUE(s.joint(1).translates);
    EXPECT_EQ(s.joint(2).rotationOrder, "XZ");
    EXPECT_FALSE(s.joint(2).translates);
    EXPECT_EQ(s.joint(3).rotationOrder, "");
    EXPECT_EQ(s.joint(4).rotationOrder, "ZYX");
    const auto frame = result->clip->frame(0);
    const double deg = std::numbers::pi / 180;
    auto expectRotation = [&](int joint, Quatd q) {
        EXPECT_LE(angleOf(rotationAt(frame, joint), Quat{float(q.x), float(q.y), float(q.z), float(q.w)}), 1e-6) << joint;
    };
    expectRotation(0, Quatd::fromAxisAngle({0, 1, 0}, 90 * deg));
    expectRotation(1, Quatd::identity());
    expectRotation(2, Quatd::fromAxisAngle({1, 0, 0}, 30 * deg) * Quatd::fromAxisAngle({0, 0, 1}, 60 * deg));
    expectRotation(3, Quatd::identity());
    expectRotation(4, Quatd::fromAxisAngle({0, 0, 1}, 10 * deg) * Quatd::fromAxisAngle({0, 1, 0}, 20 * deg)
                          * Quatd::fromAxisAngle({1, 0, 0}, 30 * deg));
    auto translation = [&](int joint) {
        const std::size_t t = result->clip->layout()->floatOffset(s.translationElement(joint));
        return std::array<float, 3>{frame[t], frame[t + 1], frame[t + 2]};
    };
    EXPECT_EQ(translation(0), (std::array<float, 3>{1, 2, 3})); // root without positions: its offset
    EXPECT_EQ(translation(1), (std::array<float, 3>{0, 7, 0}));
    EXPECT_EQ(translation(4), (std::array<float, 3>{4, 5, 6}));
    // And back: the same channels are written, positions first.
    const std::string written = bvh::write(s, *result->clip);
    EXPECT_NE(written.find("CHANNELS 4 Xposition Yposition Zposition Yrotation\n"), std::string::npos) << written; // the root always translates
    EXPECT_NE(written.find("CHANNELS 3 Xposition Yposition Zposition\n"), std::string::npos) << written;
    EXPECT_NE(written.find("CHANNELS 2 Xrotation Zrotation\n"), std::string::npos) << written;
    EXPECT_NE(written.find("CHANNELS 0\n"), std::string::npos) << written;
    EXPECT_NE(written.find("CHANNELS 6 Xposition Yposition Zposition Zrotation Yrotation Xrotation\n"), std::string::npos);
    auto back = bvh::parse(written);
    ASSERT_TRUE(back) << describe(back.error()) << written;
    expectSameMotion(*result, *back, "partial");
}

// ---------------------------------------------------------------------------------------------
// The fuzz seed corpus, run through the parser on every CI build.

TEST(BvhFuzzCorpus, EverySeedIsHandled)
{
    const fs::path corpus = thespis::test::testData("../fuzz/corpus/bvh");
    int valid = 0, invalid = 0;
    for (const auto& entry : fs::directory_iterator(corpus)) {
        SCOPED_TRACE(entry.path().filename().string());
        auto text = readTextFile(entry.path());
        ASSERT_TRUE(text);
        auto result = bvh::parse(*text);
        if (entry.path().filename().string().starts_with("valid_")) {
            ++valid;
            ASSERT_TRUE(result) << describe(result.error());
            auto back = bvh::parse(bvh::write(result->skeleton, *result->clip));
            ASSERT_TRUE(back) << describe(back.error());
            expectSameMotion(*result, *back, entry.path().stem().string());
        } else {
            ++invalid;
            ASSERT_FALSE(result);
            EXPECT_EQ(result.error().code, ErrorCode::CorruptData);
            EXPECT_EQ(result.error().message.rfind("line ", 0), 0u) << result.error().message;
        }
    }
    EXPECT_GE(valid, 4);
    EXPECT_GE(invalid, 2);
}
