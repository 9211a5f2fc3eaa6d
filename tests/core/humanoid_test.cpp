// The procedural default humanoid (core/scene/default_humanoid.h): valid at every H-Anim level,
// H-Anim segment names with no role tags, closed outward-facing surfaces with seams that
// stay shut, smooth skin weights, a hair shell a few millimetres above the skull (paper Fig. 14),
// left/right symmetry, proportions, determinism.

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "anim/hanim.h"
#include "scene/default_humanoid.h"

namespace thespis::core::scene {
namespace {

namespace hanim = anim::hanim;
using hanim::Level;

constexpr Level kLevels[] = {Level::Loa1, Level::Subset25, Level::Loa2};

std::string levelName(Level level)
{
    return level == Level::Loa1 ? "LOA 1" : level == Level::Loa2 ? "LOA 2" : "25-joint subset";
}

Character makeHumanoid(Level level = Level::Subset25, double detail = 1.0)
{
    Result<Character> character = makeDefaultHumanoid({.level = level, .detail = detail});
    EXPECT_TRUE(character.ok()) << (character.ok() ? "" : character.error().message);
    return std::move(character).value();
}

Vec3d toDouble(const Vec3& v) { return {v.x, v.y, v.z}; }
double dot(Vec3d a, Vec3d b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
Vec3d cross(Vec3d a, Vec3d b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }
double length(Vec3d v) { return std::sqrt(dot(v, v)); }

const Segment& segment(const Character& character, std::string_view name)
{
    const Segment* found = character.mesh.findSegment(name);
    EXPECT_NE(found, nullptr) << name;
    return found ? *found : character.mesh.segments.front();
}

/// Closest point to p on triangle abc (Ericson, Real-Time Collision Detection 5.1.5).
Vec3d closestOnTriangle(Vec3d p, Vec3d a, Vec3d b, Vec3d c)
{
    const Vec3d ab = b - a, ac = c - a, ap = p - a;
    const double d1 = dot(ab, ap), d2 = dot(ac, ap);
    if (d1 <= 0 && d2 <= 0)
        return a;
    const Vec3d bp = p - b;
    const double d3 = dot(ab, bp), d4 = dot(ac, bp);
    if (d3 >= 0 && d4 <= d3)
        return b;
    const double vc = d1 * d4 - d3 * d2;
    if (vc <= 0 && d1 >= 0 && d3 <= 0)
        return a + ab * (d1 / (d1 - d3));
    const Vec3d cp = p - c;
    const double d5 = dot(ab, cp), d6 = dot(ac, cp);
    if (d6 >= 0 && d5 <= d6)
        return c;
    const double vb = d5 * d2 - d1 * d6;
    if (vb <= 0 && d2 >= 0 && d6 <= 0)
        return a + ac * (d2 / (d2 - d6));
    const double va = d3 * d6 - d5 * d4;
    if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0)
        return b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6)));
    const double denominator = 1 / (va + vb + vc);
    return a + ab * (vb * denominator) + ac * (vc * denominator);
}

using Key = std::array<float, 3>;
Key keyOf(const Vec3& p) { return {p.x, p.y, p.z}; }

TEST(DefaultHumanoid, IsValidAtEveryLevel)
{
    for (Level level : kLevels) {
        SCOPED_TRACE(levelName(level));
        const Character character = makeHumanoid(level);
        const Result<void> valid = character.validate();
        EXPECT_TRUE(valid.ok()) << (valid.ok() ? "" : valid.error().message);
        EXPECT_EQ(character.name, "Default humanoid");
        EXPECT_EQ(character.skeleton.jointCount(), hanim::skeleton(level).jointCount());
        EXPECT_EQ(character.skin.influences, 4);
        EXPECT_EQ(character.segmentMaterials.size(), character.mesh.segments.size());
        EXPECT_EQ(character.texcoords.size(), character.mesh.vertexCount()); // the face's picture
        EXPECT_TRUE(character.clips.empty());
        for (const Segment& s : character.mesh.segments) {
            EXPECT_GE(character.skeleton.find(s.joint), 0) << s.name << " follows " << s.joint;
            EXPECT_GT(s.triangleCount, 0u) << s.name;
        }
    }
}

// About 20 000 for the body and 13 000 for the face, whose lips and lids need 2–3 mm.
TEST(DefaultHumanoid, HasAboutThirtyThousandTrianglesAtDetailOne)
{
    for (Level level : kLevels) {
        SCOPED_TRACE(levelName(level));
        const std::size_t triangles = makeHumanoid(level).mesh.triangleCount();
        EXPECT_GE(triangles, 25000u);
        EXPECT_LE(triangles, 40000u);
        // Half the detail: about a quarter of the triangles.
        const double ratio = double(makeHumanoid(level, 0.5).mesh.triangleCount()) / double(triangles);
        EXPECT_GT(ratio, 0.15);
        EXPECT_LT(ratio, 0.45);
    }
}

TEST(DefaultHumanoid, RejectsADetailOutOfRange)
{
    for (double detail : {0.0, -1.0, std::numeric_limits<double>::quiet_NaN(), 100.0}) {
        const Result<Character> character = makeDefaultHumanoid({.detail = detail});
        ASSERT_FALSE(character.ok()) << detail;
        EXPECT_EQ(character.error().code, ErrorCode::InvalidArgument);
        EXPECT_NE(character.error().message.find("detail"), std::string::npos);
    }
}

TEST(DefaultHumanoid, NamesSegmentsAfterHAnimBodySegments)
{
    auto names = [](const Character& character) {
        std::map<std::string, std::string> jointOf;
        for (const Segment& s : character.mesh.segments)
            jointOf[s.name] = s.joint;
        return jointOf;
    };
    const std::map<std::string, std::string> subset = names(makeHumanoid(Level::Subset25));
    const std::map<std::string, std::string> expected = {
        {"sacrum", "humanoid_root"}, {"pelvis", "sacroiliac"}, {"l5", "vl5"}, {"l1", "vl1"}, {"t10", "vt10"},
        {"t6", "vt6"}, {"t1", "vt1"}, {"c4", "vc4"}, {"skull", "skullbase"}, {"hair", "skullbase"},
        {"l_thigh", "l_hip"}, {"l_calf", "l_knee"}, {"l_talus", "l_talocrural"},
        {"l_tarsal_proximal_phalanx", "l_metatarsophalangeal"}, {"l_clavicle", "l_sternoclavicular"},
        {"l_upperarm", "l_shoulder"}, {"l_forearm", "l_elbow"}, {"l_carpal", "l_radiocarpal"},
        {"r_thigh", "r_hip"}, {"r_calf", "r_knee"}, {"r_talus", "r_talocrural"},
        {"r_tarsal_proximal_phalanx", "r_metatarsophalangeal"}, {"r_clavicle", "r_sternoclavicular"},
        {"r_upperarm", "r_shoulder"}, {"r_forearm", "r_elbow"}, {"r_carpal", "r_radiocarpal"},
        // The face's parts, each with its own material, all on the skull.
        {"l_eyeball", "skullbase"}, {"r_eyeball", "skullbase"}, {"l_iris", "skullbase"}, {"r_iris", "skullbase"},
        {"l_pupil", "skullbase"}, {"r_pupil", "skullbase"}, {"l_eyelid", "skullbase"}, {"r_eyelid", "skullbase"},
        {"l_eyelash", "skullbase"}, {"r_eyelash", "skullbase"}, {"upper_teeth", "skullbase"},
        {"lower_teeth", "skullbase"}, {"tongue", "skullbase"}, {"mouth", "skullbase"}};
    EXPECT_EQ(subset, expected);

    // LOA 1 has one segment for the whole spine and neck; LOA 2 splits the spine, the foot and
    // the fingers.
    const std::map<std::string, std::string> loa1 = names(makeHumanoid(Level::Loa1));
    EXPECT_EQ(loa1.size(), 33u); // 18 joints + hair + the face's 14
    EXPECT_EQ(loa1.count("l5"), 1u);
    EXPECT_EQ(loa1.count("t6"), 0u);
    EXPECT_EQ(loa1.count("l_clavicle"), 0u);
    const std::map<std::string, std::string> loa2 = names(makeHumanoid(Level::Loa2));
    for (const auto& [name, joint] : std::map<std::string, std::string>{
             {"l3", "vl3"}, {"c2", "vc2"}, {"l_scapula", "l_acromioclavicular"}, {"l_metatarsal", "l_tarsometatarsal"},
             {"l_tarsal_distal_phalanx", "l_tarsal_interphalangeal"}, {"l_metacarpal_1", "l_carpometacarpal_1"},
             {"l_carpal_proximal_phalanx_1", "l_metacarpophalangeal_1"},
             {"l_carpal_distal_phalanx_1", "l_carpal_interphalangeal_1"},
             {"l_carpal_middle_phalanx_3", "l_carpal_proximal_interphalangeal_3"},
             {"r_carpal_distal_phalanx_5", "r_carpal_distal_interphalangeal_5"}}) {
        ASSERT_EQ(loa2.count(name), 1u) << name;
        EXPECT_EQ(loa2.at(name), joint) << name;
    }
}

TEST(DefaultHumanoid, SegmentsFollowTheirJointsUntagged)
{
    for (Level level : kLevels) {
        SCOPED_TRACE(levelName(level));
        const Character character = makeHumanoid(level);
        const std::vector<Vec3d> rest = character.skeleton.worldPositions(character.skeleton.restFrame());
        for (const Segment& s : character.mesh.segments) {
            EXPECT_EQ(s.role, SegmentRole::None) << s.name;
            EXPECT_EQ(s.bindRotation, Quatd::identity()) << s.name;
            const Vec3d joint = rest[std::size_t(character.skeleton.find(s.joint))];
            EXPECT_LT(length(s.bindTranslation - joint), 1e-9) << s.name;
        }
    }
}

TEST(DefaultHumanoid, DressesTheFigureAndPaintsItsFace)
{
    const Character character = makeHumanoid();
    std::set<std::string> names;
    for (const Material& material : character.materials) {
        names.insert(material.name);
        EXPECT_EQ(material.baseColorTexture, material.name == "face" ? 0 : -1) << material.name;
        for (float channel : material.baseColor) {
            EXPECT_GT(channel, 0.0f) << material.name;
            EXPECT_LE(channel, 1.0f) << material.name;
        }
    }
    EXPECT_EQ(names, (std::set<std::string>{"skin", "hair", "shirt", "trousers", "shoes", "face", "sclera", "iris",
                                            "pupil", "teeth", "tongue", "mouth"}));
    ASSERT_EQ(character.textures.size(), 1u); // the face's skin: lips and brows
    EXPECT_EQ(character.textures[0].name, "face");
    auto materialOf = [&](std::string_view name) {
        const std::size_t index = std::size_t(&segment(character, name) - character.mesh.segments.data());
        return character.materials[std::size_t(character.segmentMaterials[index])].name;
    };
    for (const auto& [segmentName, material] : std::map<std::string, std::string>{
             {"skull", "face"}, {"c4", "skin"}, {"hair", "hair"}, {"t6", "shirt"}, {"l_upperarm", "shirt"},
             {"l_forearm", "skin"}, {"r_carpal", "skin"}, {"pelvis", "trousers"}, {"l_thigh", "trousers"},
             {"r_calf", "trousers"}, {"l_talus", "shoes"}, {"l_eyeball", "sclera"}, {"r_iris", "iris"},
             {"l_pupil", "pupil"}, {"l_eyelid", "skin"}, {"r_eyelash", "hair"}, {"upper_teeth", "teeth"},
             {"tongue", "tongue"}, {"mouth", "mouth"}})
        EXPECT_EQ(materialOf(segmentName), material) << segmentName;
    // The skin's picture is skin where the face samples nothing else, lip-red on the lips.
    const TextureImage& face = character.textures[0];
    const auto texel = [&](std::array<float, 2> uv) {
        const int x = std::clamp(int(uv[0] * float(face.width)), 0, face.width - 1);
        const int y = std::clamp(int(uv[1] * float(face.height)), 0, face.height - 1);
        return std::array<int, 3>{face.rgba[std::size_t((y * face.width + x) * 4)],
                                  face.rgba[std::size_t((y * face.width + x) * 4 + 1)],
                                  face.rgba[std::size_t((y * face.width + x) * 4 + 2)]};
    };
    const FeaturePoint* upperLip = character.face.findFeaturePoint("2.2");
    const FeaturePoint* cheek = character.face.findFeaturePoint("5.1");
    ASSERT_TRUE(upperLip && cheek);
    const auto lip = texel(character.texcoords[upperLip->vertex]), skin = texel(character.texcoords[cheek->vertex]);
    EXPECT_GT(lip[0] - lip[1], skin[0] - skin[1] + 20) << "the lips are redder than the cheek";
}

TEST(DefaultHumanoid, HairLiesAFewMillimetresAboveTheSkull)
{
    const Character character = makeHumanoid();
    const CharacterMesh& mesh = character.mesh;
    const Segment& hair = segment(character, "hair");
    const Segment& skull = segment(character, "skull");
    EXPECT_EQ(hair.joint, "skullbase");

    // Skull triangles with a bounding sphere each, to skip the far ones quickly.
    struct Triangle {
        Vec3d a, b, c, centre;
        double radius;
    };
    std::vector<Triangle> triangles;
    for (std::uint32_t t = skull.firstTriangle; t < skull.firstTriangle + skull.triangleCount; ++t) {
        const Vec3d a = toDouble(mesh.positions[mesh.indices[3 * t]]), b = toDouble(mesh.positions[mesh.indices[3 * t + 1]]),
                    c = toDouble(mesh.positions[mesh.indices[3 * t + 2]]);
        const Vec3d centre = (a + b + c) * (1.0 / 3);
        triangles.push_back({a, b, c, centre, std::max({length(a - centre), length(b - centre), length(c - centre)})});
    }
    double nearest = 1, farthest = 0;
    for (std::uint32_t v = hair.firstVertex; v < hair.firstVertex + hair.vertexCount; ++v) {
        const Vec3d p = toDouble(mesh.positions[v]);
        double best = 1;
        const Triangle* closest = nullptr;
        Vec3d closestPoint;
        for (const Triangle& t : triangles) {
            if (length(p - t.centre) - t.radius >= best)
                continue;
            const Vec3d q = closestOnTriangle(p, t.a, t.b, t.c);
            if (const double d = length(p - q); d < best) {
                best = d;
                closest = &t;
                closestPoint = q;
            }
        }
        ASSERT_NE(closest, nullptr);
        // Outside: on the side the skull triangle faces.
        EXPECT_GT(dot(p - closestPoint, cross(closest->b - closest->a, closest->c - closest->a)), 0) << "hair vertex " << v;
        nearest = std::min(nearest, best);
        farthest = std::max(farthest, best);
    }
    EXPECT_GE(nearest, 0.002);
    EXPECT_LE(farthest, 0.010);

    // It covers the top and the back of the head, not the face.
    auto hairAlong = [&](const Vec3& from, int axis, double sign) { // a hair vertex within 1 cm of the line from `from` along ±axis
        for (std::uint32_t v = hair.firstVertex; v < hair.firstVertex + hair.vertexCount; ++v) {
            const Vec3& p = mesh.positions[v];
            const float delta[3] = {p.x - from.x, p.y - from.y, p.z - from.z};
            if (delta[axis] * sign > 0 && std::hypot(delta[(axis + 1) % 3], delta[(axis + 2) % 3]) < 0.01)
                return true;
        }
        return false;
    };
    const auto skullBegin = mesh.positions.begin() + skull.firstVertex;
    const auto skullEnd = skullBegin + skull.vertexCount;
    const Vec3& top = *std::max_element(skullBegin, skullEnd, [](const Vec3& a, const Vec3& b) { return a.y < b.y; });
    const Vec3& back = *std::min_element(skullBegin, skullEnd, [](const Vec3& a, const Vec3& b) { return a.z < b.z; });
    const Vec3& nose = *std::max_element(skullBegin, skullEnd, [](const Vec3& a, const Vec3& b) { return a.z < b.z; });
    EXPECT_TRUE(hairAlong(top, 1, 1)) << "no hair above the top of the skull";
    EXPECT_TRUE(hairAlong(back, 2, -1)) << "no hair behind the back of the skull";
    EXPECT_FALSE(hairAlong(nose, 2, 1)) << "hair in front of the face";
}

TEST(DefaultHumanoid, SurfacesAreClosedWithSeamsThatMatchAndFaceOutward)
{
    for (Level level : {Level::Subset25, Level::Loa2}) {
        SCOPED_TRACE(levelName(level));
        const Character character = makeHumanoid(level);
        const CharacterMesh& mesh = character.mesh;
        std::vector<std::size_t> segmentOf(mesh.vertexCount());
        for (std::size_t s = 0; s < mesh.segments.size(); ++s)
            for (std::uint32_t v = 0; v < mesh.segments[s].vertexCount; ++v)
                segmentOf[mesh.segments[s].firstVertex + v] = s;

        // Weld vertices at the same position: seams between segments repeat their vertices
        // with the same normal and the same weights, so the skinned surface stays shut and smooth.
        std::map<Key, std::uint32_t> first;
        std::vector<std::uint32_t> welded(mesh.vertexCount());
        std::size_t seamVertices = 0;
        for (std::uint32_t v = 0; v < mesh.vertexCount(); ++v) {
            const auto [it, inserted] = first.emplace(keyOf(mesh.positions[v]), v);
            welded[v] = it->second;
            const std::uint32_t w = it->second;
            if (inserted || segmentOf[v] == segmentOf[w])
                continue;
            ++seamVertices;
            EXPECT_EQ(keyOf(mesh.normals[v]), keyOf(mesh.normals[w])) << "seam vertex " << v;
            for (int i = 0; i < 4; ++i) {
                EXPECT_EQ(character.skin.joints[v * 4 + i], character.skin.joints[w * 4 + i]) << "seam vertex " << v;
                EXPECT_EQ(character.skin.weights[v * 4 + i], character.skin.weights[w * 4 + i]) << "seam vertex " << v;
            }
        }
        EXPECT_GT(seamVertices, 100u);

        // Closed and consistently wound: every welded edge is used once in each direction. The
        // face's lids, lashes, iris and pupil are shells over the eyeball, and the lips part along
        // a seam and turn into the mouth (the inside of the mouth closes the head behind them):
        // their edges are open, but only there.
        const std::set<std::string> shells{"l_eyelid", "r_eyelid", "l_eyelash", "r_eyelash",
                                           "l_iris",   "r_iris",   "l_pupil",   "r_pupil"};
        const Segment& mouth = segment(character, "mouth");
        Vec3d mouthMin{1e9, 1e9, 1e9}, mouthMax{-1e9, -1e9, -1e9};
        for (std::uint32_t v = mouth.firstVertex; v < mouth.firstVertex + mouth.vertexCount; ++v) {
            const Vec3d p = toDouble(mesh.positions[v]);
            mouthMin = {std::min(mouthMin.x, p.x - 0.002), std::min(mouthMin.y, p.y), std::min(mouthMin.z, p.z)};
            mouthMax = {std::max(mouthMax.x, p.x + 0.002), std::max(mouthMax.y, p.y), std::max(mouthMax.z, p.z + 0.012)};
        }
        const auto mayBeOpen = [&](std::uint32_t a, std::uint32_t b) {
            if (shells.count(mesh.segments[segmentOf[a]].name) || shells.count(mesh.segments[segmentOf[b]].name))
                return true;
            const Vec3d m = (toDouble(mesh.positions[a]) + toDouble(mesh.positions[b])) * 0.5;
            return m.x > mouthMin.x && m.x < mouthMax.x && m.y > mouthMin.y && m.y < mouthMax.y && m.z > mouthMin.z &&
                   m.z < mouthMax.z;
        };
        std::map<std::pair<std::uint32_t, std::uint32_t>, int> edges;
        for (std::size_t t = 0; t < mesh.triangleCount(); ++t)
            for (int e = 0; e < 3; ++e) {
                const std::uint32_t a = welded[mesh.indices[3 * t + e]], b = welded[mesh.indices[3 * t + (e + 1) % 3]];
                ASSERT_NE(a, b) << "degenerate triangle " << t;
                ++edges[{a, b}];
            }
        std::size_t open = 0, repeated = 0, openOnTheFace = 0;
        for (const auto& [edge, count] : edges) {
            const bool edgeOpen = count != 1 || edges.count({edge.second, edge.first}) == 0;
            if (edgeOpen && mayBeOpen(edge.first, edge.second)) {
                ++openOnTheFace;
                continue;
            }
            repeated += count != 1;
            open += edges.count({edge.second, edge.first}) == 0;
        }
        EXPECT_EQ(open, 0u);
        EXPECT_EQ(repeated, 0u);
        EXPECT_GT(openOnTheFace, 100u); // the lids' margins and the lips' edges are there

        // Counter-clockwise seen from outside: the winding agrees with the smooth normals …
        std::size_t disagreeing = 0;
        for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
            const std::uint32_t a = mesh.indices[3 * t], b = mesh.indices[3 * t + 1], c = mesh.indices[3 * t + 2];
            const Vec3d face = cross(toDouble(mesh.positions[b]) - toDouble(mesh.positions[a]),
                                     toDouble(mesh.positions[c]) - toDouble(mesh.positions[a]));
            const Vec3d normals = toDouble(mesh.normals[a]) + toDouble(mesh.normals[b]) + toDouble(mesh.normals[c]);
            disagreeing += dot(face, normals) <= 0;
        }
        EXPECT_EQ(disagreeing, 0u);
        // … and the normals point away from each segment's middle (the hand's fingers and the
        // hair's inner side face it in part: the hair is a closed shell of positive volume).
        for (const Segment& s : mesh.segments) {
            Vec3d centroid;
            for (std::uint32_t v = s.firstVertex; v < s.firstVertex + s.vertexCount; ++v)
                centroid = centroid + toDouble(mesh.positions[v]) * (1.0 / s.vertexCount);
            std::size_t outward = 0;
            for (std::uint32_t v = s.firstVertex; v < s.firstVertex + s.vertexCount; ++v)
                outward += dot(toDouble(mesh.normals[v]), toDouble(mesh.positions[v]) - centroid) > 0;
            // The hair, the lids and lashes (shells round the eye) and the inside of the mouth
            // (seen from within) face their middle in part or in whole.
            if (s.name != "hair" && s.name != "mouth" && !shells.count(s.name)) {
                EXPECT_GT(double(outward) / s.vertexCount, 0.7) << s.name;
            }
        }
        const Segment& hair = segment(character, "hair");
        double hairVolume = 0;
        for (std::uint32_t t = hair.firstTriangle; t < hair.firstTriangle + hair.triangleCount; ++t)
            hairVolume += dot(toDouble(mesh.positions[mesh.indices[3 * t]]),
                              cross(toDouble(mesh.positions[mesh.indices[3 * t + 1]]), toDouble(mesh.positions[mesh.indices[3 * t + 2]]))) / 6;
        EXPECT_GT(hairVolume, 1e-4); // about its area (600 cm²) times its thickness (3 to 6 mm)
        EXPECT_LT(hairVolume, 5e-4);
    }
}

TEST(DefaultHumanoid, SkinWeightsBlendSmoothlyAcrossJoints)
{
    for (Level level : kLevels) {
        SCOPED_TRACE(levelName(level));
        const Character character = makeHumanoid(level);
        const Skin& skin = character.skin;
        const std::vector<int> parents = character.skeleton.parents();
        for (const Segment& s : character.mesh.segments) {
            const int joint = character.skeleton.find(s.joint);
            for (std::uint32_t v = s.firstVertex; v < s.firstVertex + s.vertexCount; ++v) {
                double sum = 0;
                std::size_t largest = v * 4;
                for (std::size_t i = v * 4; i < v * 4 + 4; ++i) {
                    EXPECT_GE(skin.weights[i], 0.0f);
                    sum += skin.weights[i];
                    if (skin.weights[i] > skin.weights[largest])
                        largest = i;
                }
                EXPECT_NEAR(sum, 1.0, 1e-5) << "vertex " << v;
                // Its strongest joint is its segment's joint or a neighbour in the skeleton.
                const int strongest = skin.joints[largest];
                const bool neighbour = strongest == joint || strongest == parents[std::size_t(joint)] ||
                                       parents[std::size_t(strongest)] == joint;
                ASSERT_TRUE(neighbour) << s.name << " vertex " << v << " mostly follows "
                                       << character.skeleton.joint(strongest).name;
            }
        }
        // Knees and elbows blend with the bone above over a few centimetres on both sides of the joint.
        const std::vector<Vec3d> rest = character.skeleton.worldPositions(character.skeleton.restFrame());
        for (const char* name : {"l_knee", "r_elbow"}) {
            const int joint = character.skeleton.find(name);
            auto weightOf = [&](std::size_t v, int j) {
                float weight = 0;
                for (std::size_t i = v * 4; i < v * 4 + 4; ++i)
                    weight += skin.joints[i] == j ? skin.weights[i] : 0.0f;
                return weight;
            };
            double below = 0, above = 0;
            for (std::size_t v = 0; v < character.mesh.vertexCount(); ++v) {
                const float weight = weightOf(v, joint);
                if (weight > 0.05f && weight < 0.95f && weightOf(v, parents[std::size_t(joint)]) > 0.05f) {
                    const double y = character.mesh.positions[v].y - rest[std::size_t(joint)].y;
                    below = std::min(below, y);
                    above = std::max(above, y);
                }
            }
            EXPECT_LT(below, -0.015) << name;
            EXPECT_GT(above, 0.015) << name;
            EXPECT_GT(below, -0.06) << name;
            EXPECT_LT(above, 0.06) << name;
        }
    }
}

TEST(DefaultHumanoid, RightSideMirrorsTheLeft)
{
    const Character character = makeHumanoid(Level::Loa2);
    const CharacterMesh& mesh = character.mesh;
    std::size_t pairs = 0;
    for (const Segment& left : mesh.segments) {
        if (!left.name.starts_with("l_"))
            continue;
        const Segment& right = segment(character, "r_" + left.name.substr(2));
        ASSERT_EQ(right.vertexCount, left.vertexCount) << left.name;
        ASSERT_EQ(right.triangleCount, left.triangleCount) << left.name;
        EXPECT_EQ(right.joint, hanim::mirrorName(left.joint));
        ++pairs;
        for (std::uint32_t i = 0; i < left.vertexCount; ++i) {
            const std::size_t l = left.firstVertex + i, r = right.firstVertex + i;
            const Vec3& p = mesh.positions[l];
            const Vec3& q = mesh.positions[r];
            ASSERT_LT(std::abs(q.x + p.x) + std::abs(q.y - p.y) + std::abs(q.z - p.z), 1e-6) << left.name << " vertex " << i;
            ASSERT_LT(std::abs(mesh.normals[r].x + mesh.normals[l].x), 1e-6);
            for (std::size_t k = 0; k < 4; ++k) {
                ASSERT_EQ(character.skin.weights[r * 4 + k], character.skin.weights[l * 4 + k]);
                if (character.skin.weights[l * 4 + k] > 0) {
                    ASSERT_EQ(character.skeleton.joint(character.skin.joints[r * 4 + k]).name,
                              hanim::mirrorName(character.skeleton.joint(character.skin.joints[l * 4 + k]).name));
                }
            }
        }
    }
    EXPECT_GE(pairs, 20u);

    // Mid-line segments are symmetric in themselves.
    for (const Segment& s : mesh.segments) {
        if (s.name.starts_with("l_") || s.name.starts_with("r_"))
            continue;
        std::size_t unmatched = 0;
        for (std::uint32_t v = s.firstVertex; v < s.firstVertex + s.vertexCount; ++v) {
            const Vec3& p = mesh.positions[v];
            bool found = false;
            for (std::uint32_t w = s.firstVertex; w < s.firstVertex + s.vertexCount && !found; ++w) {
                const Vec3& q = mesh.positions[w];
                found = std::abs(q.x + p.x) + std::abs(q.y - p.y) + std::abs(q.z - p.z) < 1e-6;
            }
            unmatched += !found;
        }
        EXPECT_EQ(unmatched, 0u) << s.name;
    }
}

TEST(DefaultHumanoid, IsDeterministic)
{
    const Character a = makeHumanoid(Level::Loa2);
    const Character b = makeHumanoid(Level::Loa2);
    ASSERT_EQ(a.mesh.vertexCount(), b.mesh.vertexCount());
    EXPECT_TRUE(std::equal(a.mesh.positions.begin(), a.mesh.positions.end(), b.mesh.positions.begin()));
    EXPECT_TRUE(std::equal(a.mesh.normals.begin(), a.mesh.normals.end(), b.mesh.normals.begin()));
    EXPECT_EQ(a.mesh.indices, b.mesh.indices);
    EXPECT_EQ(a.skin.joints, b.skin.joints);
    EXPECT_EQ(a.skin.weights, b.skin.weights);
    EXPECT_EQ(a.segmentMaterials, b.segmentMaterials);
    ASSERT_EQ(a.mesh.segments.size(), b.mesh.segments.size());
    for (std::size_t s = 0; s < a.mesh.segments.size(); ++s) {
        EXPECT_EQ(a.mesh.segments[s].name, b.mesh.segments[s].name);
        EXPECT_EQ(a.mesh.segments[s].firstVertex, b.mesh.segments[s].firstVertex);
    }
}

TEST(DefaultHumanoid, StandsOnTheGroundFacingPlusZ)
{
    const Character character = makeHumanoid();
    const CharacterMesh& mesh = character.mesh;
    Vec3d lower{1e9, 1e9, 1e9}, upper{-1e9, -1e9, -1e9};
    for (const Vec3& p : mesh.positions) {
        lower = {std::min(lower.x, double(p.x)), std::min(lower.y, double(p.y)), std::min(lower.z, double(p.z))};
        upper = {std::max(upper.x, double(p.x)), std::max(upper.y, double(p.y)), std::max(upper.z, double(p.z))};
    }
    EXPECT_NEAR(lower.y, 0.0, 0.003); // soles on the ground
    EXPECT_GE(upper.y - lower.y, 1.75);
    EXPECT_LE(upper.y - lower.y, 1.85);
    EXPECT_LT(upper.x - lower.x, 0.6); // arms at the sides
    EXPECT_NEAR(upper.x, -lower.x, 1e-6);

    // The nose tip is the head's frontmost point, on the mid-line at face height.
    const Segment& skull = segment(character, "skull");
    const Segment& hair = segment(character, "hair");
    auto frontmost = [&](const Segment& s) {
        return *std::max_element(mesh.positions.begin() + s.firstVertex, mesh.positions.begin() + s.firstVertex + s.vertexCount,
                                 [](const Vec3& a, const Vec3& b) { return a.z < b.z; });
    };
    const Vec3 nose = frontmost(skull);
    EXPECT_LT(std::abs(nose.x), 1e-3);
    EXPECT_GT(nose.y, 1.60);
    EXPECT_LT(nose.y, 1.70);
    EXPECT_GT(nose.z, frontmost(hair).z);
    // Toes point to +Z: the shoe reaches further forward than back.
    const Segment& toes = segment(character, "l_tarsal_proximal_phalanx");
    EXPECT_GT(frontmost(toes).z, 0.15);
}

} // namespace
} // namespace thespis::core::scene
