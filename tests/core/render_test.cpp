// Rendering (core/render): the headless EGL context, the character node's per-frame work (posed
// vertices uploaded, the light rotated into each segment's frame), and pictures checked against
// what the camera matrices and the light say: the character's mask where its projected bounds
// are (every shading, boxes and the default humanoid), the exact levels of PRT under simple
// lights for DU and for a given bake, a rotated segment lit on the side that now faces the light,
// sRGB base-colour textures, supersampling, the probe background's orientation and the ground's
// irradiance. Renders are saved under <build>/test-artifacts/render_*.png for people to look at.
//
// Without an OpenGL context (no EGL, no Mesa) the picture tests fail, saying why: Mesa's
// software GL is a dependency, so every machine that builds Thespis has one.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <memory>
#include <numbers>
#include <random>
#include <set>
#include <string>
#include <vector>

#include <unistd.h>

#include "lighting/probe.h"
#include "lighting/sh.h"
#include "render/camera.h"
#include "render/character_node.h"
#include "render/offscreen_renderer.h"
#include "render/render_scene.h"
#include "render/scenario_scene.h"
#include "render/shading.h"
#include "scenario/scenario_character.h"
#include "scenario/scenario_io.h"
#include "scene/character.h"
#include "scene/default_humanoid.h"
#include "offscreen_suite.h"
#include "test_support.h"

namespace thespis::core::render {
namespace {

using anim::Quat;
using anim::Quatd;
using anim::Vec3;
using anim::Vec3d;
using lighting::ShRgb;

constexpr int kWidth = 320;
constexpr int kHeight = 240;
constexpr double kPi = std::numbers::pi;

using thespis::test::artifact;

/// The picture tests share one renderer, made once for the suite and closed before exit.
using Render = thespis::test::OffscreenSuite<kWidth, kHeight>;

// Six faces of 4 vertices (flat normals), wound counter-clockwise seen from outside.
void addBox(scene::Character& character, const std::string& joint, Vec3 lower, Vec3 upper, int material)
{
    scene::CharacterMesh& mesh = character.mesh;
    scene::Segment segment;
    segment.name = joint;
    segment.joint = joint;
    segment.firstVertex = std::uint32_t(mesh.positions.size());
    segment.firstTriangle = std::uint32_t(mesh.triangleCount());
    const int jointIndex = character.skeleton.find(joint);
    const Vec3d rest = character.skeleton.worldPositions(character.skeleton.restFrame())[std::size_t(jointIndex)];
    segment.bindTranslation = rest;
    const float lo[3] = {lower.x, lower.y, lower.z}, hi[3] = {upper.x, upper.y, upper.z};
    for (int axis = 0; axis < 3; ++axis)
        for (int sign : {1, -1}) {
            // u × v = the outward normal.
            int u = (axis + 1) % 3, v = (axis + 2) % 3;
            if (sign < 0)
                std::swap(u, v);
            const std::uint32_t base = std::uint32_t(mesh.positions.size());
            constexpr std::array<std::array<int, 2>, 4> corners{{{0, 0}, {1, 0}, {1, 1}, {0, 1}}};
            for (auto [cu, cv] : corners) {
                float p[3];
                p[axis] = sign > 0 ? hi[axis] : lo[axis];
                p[u] = cu ? hi[u] : lo[u];
                p[v] = cv ? hi[v] : lo[v];
                float n[3] = {0, 0, 0};
                n[axis] = float(sign);
                mesh.positions.push_back({p[0], p[1], p[2]});
                mesh.normals.push_back({n[0], n[1], n[2]});
            }
            for (std::uint32_t i : {0u, 1u, 2u, 0u, 2u, 3u})
                mesh.indices.push_back(base + i);
        }
    segment.vertexCount = std::uint32_t(mesh.positions.size()) - segment.firstVertex;
    segment.triangleCount = std::uint32_t(mesh.triangleCount()) - segment.firstTriangle;
    mesh.segments.push_back(segment);
    character.segmentMaterials.push_back(material);
}

// A body box (0.5 × 1 × 0.3 m) standing on the ground and following the root, and an "arm" box
// on top of it (0.2 × 0.6 × 0.2 m) following a joint at (0, 1, 0). No skin: rigid segments.
std::shared_ptr<scene::Character> makeBoxCharacter()
{
    auto character = std::make_shared<scene::Character>();
    character->name = "boxes";
    std::vector<anim::Joint> joints(2);
    joints[0].name = "root";
    joints[1].name = "arm";
    joints[1].parent = 0;
    joints[1].offset = {0, 1, 0};
    character->skeleton = std::move(anim::Skeleton::create(std::move(joints))).value();
    character->materials = {{"grey", {0.5f, 0.5f, 0.5f, 1}, -1}, {"orange", {0.9f, 0.55f, 0.25f, 1}, -1}};
    addBox(*character, "root", {-0.25f, 0, -0.15f}, {0.25f, 1, 0.15f}, 0);
    addBox(*character, "arm", {-0.1f, 1, -0.1f}, {0.1f, 1.6f, 0.1f}, 1);
    EXPECT_TRUE(character->validate().ok());
    return character;
}

/// A light of constant radiance `constant` plus k·Y₁(d) in band 1: on a surface with normal n,
/// DU transfer gives radiance constant + k·(n·d)/(2π) (Â₁/π = 2/3, Σ_m Y₁m(n)Y₁m(d) = 3(n·d)/4π).
ShRgb constantPlusBand1(double constant, double k, const Vec3d& d)
{
    ShRgb light;
    light.order = 2;
    std::array<double, 4> basis{};
    lighting::evaluateSh(2, d, basis);
    for (int c = 0; c < 3; ++c) {
        light.channel[c][0] = constant * 2 * std::sqrt(kPi);
        for (int i = 1; i < 4; ++i)
            light.channel[c][i] = k * basis[std::size_t(i)];
    }
    return light;
}

int displayByte(double radiance) { return int(std::lround(255 * encodeSrgb(radiance))); }

std::array<int, 2> pixelOf(const Vec3& point, const CameraView& view)
{
    const PixelRect at = projectToPixels(std::span(&point, 1), view, kWidth, kHeight);
    return {int(std::floor(at.left)), int(std::floor(at.top))};
}

std::vector<float> restFrame(const scene::Character& character) { return character.skeleton.restFrame(); }

void setRotation(std::vector<float>& frame, int joint, const Quat& q)
{
    anim::rotationAt(std::span<float>(frame), joint) = q;
}

// -- Pure CPU parts -------------------------------------------------------------------------

TEST(Shading, NamesRoundTripAndUnknownNamesAreRefused)
{
    for (Shading shading : {Shading::Prt, Shading::Phong, Shading::Unlit}) {
        auto parsed = parseShading(shadingName(shading));
        ASSERT_TRUE(parsed.ok());
        EXPECT_EQ(*parsed, shading);
    }
    auto bad = parseShading("gouraud");
    ASSERT_FALSE(bad.ok());
    EXPECT_NE(bad.error().message.find("gouraud"), std::string::npos);
}

TEST(Shading, DominantLightGivesBackADirectionalLight)
{
    // A directional light of colour c from d, projected: L_i = c·Y_i(d) (bands 0 and 1).
    const Vec3d d = [] {
        const Vec3d v{0.3, 0.8, -0.52};
        return v * (1 / std::sqrt(v.x * v.x + v.y * v.y + v.z * v.z));
    }();
    const std::array<double, 3> color{2.0, 1.5, 0.5};
    ShRgb light;
    light.order = 3;
    std::array<double, 9> basis{};
    lighting::evaluateSh(3, d, basis);
    for (int c = 0; c < 3; ++c)
        for (int i = 0; i < 9; ++i)
            light.channel[c][std::size_t(i)] = color[std::size_t(c)] * basis[std::size_t(i)];
    const DirectionalLight extracted = dominantLight(light);
    EXPECT_NEAR(extracted.direction.x, d.x, 1e-9);
    EXPECT_NEAR(extracted.direction.y, d.y, 1e-9);
    EXPECT_NEAR(extracted.direction.z, d.z, 1e-9);
    for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(extracted.color[std::size_t(c)], color[std::size_t(c)], 1e-9);
        EXPECT_NEAR(extracted.ambientIrradiance[std::size_t(c)], 0, 1e-9);
    }
    // A constant light has no direction, only ambient: irradiance π·radiance.
    const DirectionalLight ambient = dominantLight(constantPlusBand1(0.7, 0, {0, 1, 0}));
    EXPECT_NEAR(ambient.color[0], 0, 1e-12);
    EXPECT_NEAR(ambient.ambientIrradiance[1], kPi * 0.7, 1e-9);
    // Irradiance of the same constant light on any normal is π·radiance.
    EXPECT_NEAR(irradiance(constantPlusBand1(0.7, 0, {0, 1, 0}), {1, 0, 0})[2], kPi * 0.7, 1e-9);
}

TEST(Camera, FramedBoundsProjectInsideThePicture)
{
    Bounds bounds;
    bounds.add(Vec3d{-0.3, 0, -0.2});
    bounds.add(Vec3d{0.3, 1.8, 0.2});
    for (double azimuth : {0.0, 45.0, 180.0}) {
        const CameraView view = frameBounds(bounds, azimuth, 15, double(kWidth) / kHeight);
        std::vector<Vec3> corners;
        for (int k = 0; k < 8; ++k)
            corners.push_back({float(k & 1 ? bounds.max.x : bounds.min.x), float(k & 2 ? bounds.max.y : bounds.min.y),
                               float(k & 4 ? bounds.max.z : bounds.min.z)});
        const PixelRect rect = projectToPixels(corners, view, kWidth, kHeight);
        EXPECT_GE(rect.left, 0);
        EXPECT_GE(rect.top, 0);
        EXPECT_LE(rect.right, kWidth);
        EXPECT_LE(rect.bottom, kHeight);
        // Framed, not lost in the middle: the box spans most of the height.
        EXPECT_GT(rect.bottom - rect.top, 0.6 * kHeight);
    }
}

TEST(CharacterNode, RefusesTransferOrdersAboveSix)
{
    lighting::TransferBake bake;
    bake.order = 7;
    auto node = CharacterNode::create(makeBoxCharacter(), &bake);
    ASSERT_FALSE(node.ok());
    EXPECT_NE(node.error().message.find("1 to 6"), std::string::npos) << node.error().message;
}

TEST(CharacterNode, RefusesABakeOfAnotherMesh)
{
    lighting::TransferBake bake;
    bake.order = 3;
    bake.vertexCount = 5;
    EXPECT_FALSE(CharacterNode::create(makeBoxCharacter(), &bake).ok());
}

// A character's bake file named by the scenario (Character::bake) is used when it fits the body;
// a missing, damaged or stale one (tags changed since) leaves the character unshadowed (DU) and
// the scene still builds, with a warning naming the character and the file. A bake the caller
// passes wins over the file.
TEST(ScenarioScene, UsesTheCharactersBakeFileOnlyWhileItFitsTheBody)
{
    const std::filesystem::path folder =
        std::filesystem::temp_directory_path() / ("thespis_render_bake_" + std::to_string(::getpid()));
    std::filesystem::remove_all(folder);
    std::filesystem::create_directories(folder / "bakes");
    // The demo moved, with the motion files it names.
    std::filesystem::copy(thespis::test::resources("motion"), folder / "motion", std::filesystem::copy_options::recursive);
    auto demo = scenario::loadScenario(thespis::test::resources("demo.thespis"));
    ASSERT_TRUE(demo.ok()) << describe(demo.error());
    const auto antigone = std::size_t(demo->findCharacter("Antigone") - demo->characters.data());
    ASSERT_LT(antigone, demo->characters.size());
    auto body = scenario::loadCharacterBody(*demo, antigone, folder);
    ASSERT_TRUE(body.ok()) << describe(body.error());
    lighting::BakeSettings settings;
    settings.order = 2; // the DU the scene makes without a bake has order 3: the node tells them apart
    settings.raysPerVertex = 4;
    settings.transfer = lighting::TransferKind::DiffuseShadowedMerged;
    auto bake = lighting::bakeTransfer(body->mesh, settings);
    ASSERT_TRUE(bake.ok()) << describe(bake.error());
    ASSERT_TRUE(lighting::writeBakeFile(folder / "bakes" / "antigone.prt", *bake).ok());

    auto orderOf = [&](const ScenarioScene& built) { return built.scene().character(antigone).transferOrder(); };
    auto bakeWarnings = [](const ScenarioScene& built) {
        std::vector<std::string> found;
        for (const std::string& warning : built.warnings())
            if (warning.find("bake") != std::string::npos)
                found.push_back(warning);
        return found;
    };

    scenario::Scenario s = *demo;
    s.characters[antigone].bake = "bakes/antigone.prt";
    {
        auto built = ScenarioScene::create(s, folder);
        ASSERT_TRUE(built.ok()) << describe(built.error());
        EXPECT_EQ(orderOf(**built), 2);
        EXPECT_TRUE(bakeWarnings(**built).empty());
        EXPECT_EQ((*built)->scene().character(1 - antigone).transferOrder(), 3); // Creon has none
    }
    struct Broken {
        const char* what;
        std::function<void(scenario::Scenario&)> change;
        const char* reason;
    };
    std::ofstream(folder / "bakes" / "garbage.prt") << "not a bake";
    const std::vector<Broken> cases = {
        {"missing file", [](scenario::Scenario& d) { d.characters[1].bake = "bakes/gone.prt"; }, "does not exist"},
        {"not a bake", [](scenario::Scenario& d) { d.characters[1].bake = "bakes/garbage.prt"; }, "not a Thespis bake file"},
        {"tags changed since", [](scenario::Scenario& d) {
             d.characters[1].segmentTags = {{"hair", scene::SegmentRole::Receiver}};
         }, "was baked as none and is now tagged receiver"},
    };
    ASSERT_EQ(antigone, 1u);
    for (const Broken& broken : cases) {
        SCOPED_TRACE(broken.what);
        scenario::Scenario changed = s;
        broken.change(changed);
        auto built = ScenarioScene::create(changed, folder);
        ASSERT_TRUE(built.ok()) << describe(built.error());
        EXPECT_EQ(orderOf(**built), 3);
        const auto warnings = bakeWarnings(**built);
        ASSERT_EQ(warnings.size(), 1u);
        EXPECT_EQ(warnings[0].rfind("Antigone: its bake \"" + changed.characters[1].bake + "\" is left out", 0), 0u)
            << warnings[0];
        EXPECT_NE(warnings[0].find(broken.reason), std::string::npos) << warnings[0];
    }
    {
        // The caller's bake wins: the file is not even read.
        scenario::Scenario missing = s;
        missing.characters[antigone].bake = "bakes/gone.prt";
        ScenarioSceneOptions options;
        settings.order = 1;
        settings.transfer = lighting::TransferKind::DiffuseUnshadowed;
        options.bakes["Antigone"] = std::make_shared<const lighting::TransferBake>(*lighting::bakeTransfer(body->mesh, settings));
        auto built = ScenarioScene::create(missing, folder, options);
        ASSERT_TRUE(built.ok()) << describe(built.error());
        EXPECT_EQ(orderOf(**built), 1);
        EXPECT_TRUE(bakeWarnings(**built).empty());
    }
    std::filesystem::remove_all(folder);
}

TEST(CharacterNode, UploadsThePosedVertices)
{
    const auto character = makeBoxCharacter();
    auto node = std::move(CharacterNode::create(character)).value();
    std::vector<float> frame = restFrame(*character);
    const Quat rootRotation = anim::normalize(Quat::fromAxisAngle({0, 1, 0}, 0.4f));
    const Quat armRotation = anim::normalize(Quat::fromAxisAngle({0, 0, 1}, 1.2f)); // relative to the root
    setRotation(frame, 0, rootRotation);
    setRotation(frame, 1, armRotation);
    const std::size_t translation = character->skeleton.frameLayout()->translationOffset();
    frame[translation] = 0.5f;
    frame[translation + 1] = 0.1f;
    frame[translation + 2] = -2.0f;
    node->setPose(frame);

    // Rigid segments: p' = Q_j·(p − rest_j) + P_j, with the joints' world transforms by hand.
    const Vec3 rootPosition{0.5f, 0.1f, -2.0f};
    const Quat armWorld = rootRotation * armRotation;
    const Vec3 armPosition = rootPosition + anim::rotate(rootRotation, Vec3{0, 1, 0});
    const osg::Vec3Array* uploaded = dynamic_cast<const osg::Vec3Array*>(node->segmentGeometry(1)->getVertexArray());
    const osg::Vec3Array* normals = dynamic_cast<const osg::Vec3Array*>(node->segmentGeometry(0)->getNormalArray());
    ASSERT_TRUE(uploaded && normals);
    ASSERT_EQ(uploaded->size(), character->mesh.vertexCount());
    for (const scene::Segment& segment : character->mesh.segments) {
        const bool arm = segment.joint == "arm";
        const Quat q = arm ? armWorld : rootRotation;
        const Vec3 rest = arm ? Vec3{0, 1, 0} : Vec3{0, 0, 0};
        const Vec3 position = arm ? armPosition : rootPosition;
        for (std::uint32_t v = segment.firstVertex; v < segment.firstVertex + segment.vertexCount; ++v) {
            const Vec3 expected = anim::rotate(q, character->mesh.positions[v] - rest) + position;
            const Vec3 expectedNormal = anim::rotate(q, character->mesh.normals[v]);
            const osg::Vec3f& got = (*uploaded)[v];
            const osg::Vec3f& gotNormal = (*normals)[v];
            EXPECT_NEAR(got.x(), expected.x, 1e-5f);
            EXPECT_NEAR(got.y(), expected.y, 1e-5f);
            EXPECT_NEAR(got.z(), expected.z, 1e-5f);
            EXPECT_NEAR(gotNormal.x(), expectedNormal.x, 1e-5f);
            EXPECT_NEAR(gotNormal.y(), expectedNormal.y, 1e-5f);
            EXPECT_NEAR(gotNormal.z(), expectedNormal.z, 1e-5f);
            const Vec3& posed = node->posedPositions()[v];
            EXPECT_TRUE(posed.x == got.x() && posed.y == got.y() && posed.z == got.z());
        }
    }
}

TEST(CharacterNode, RotatesTheLightIntoEachSegmentsFrame)
{
    const auto character = makeBoxCharacter();
    auto node = std::move(CharacterNode::create(character)).value();
    ASSERT_EQ(node->transferOrder(), 3);
    // A light with every coefficient of the three bands set, so any mix-up shows.
    ShRgb light;
    light.order = 4; // more bands than the transfer: the node keeps the first three
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> value(-1, 1);
    for (int c = 0; c < 3; ++c)
        for (int i = 0; i < 16; ++i)
            light.channel[c][std::size_t(i)] = value(rng);
    node->setLight(light);

    std::vector<float> frame = restFrame(*character);
    const Quat armRotation = anim::normalize(Quat::fromAxisAngle({1, 0, 0}, float(kPi / 2)));
    setRotation(frame, 1, armRotation);
    node->setPose(frame);

    // L_seg(ω) = L(Q_seg·ω): the light seen from the segment's frame. Compare reconstructions at
    // random directions, independently of the rotation code.
    for (std::size_t s = 0; s < node->segmentCount(); ++s) {
        const Quatd q = node->segmentRotation(s);
        const Quat expectedQ = s == 1 ? armRotation : Quat{};
        EXPECT_NEAR(anim::angleBetween(q, Quatd{expectedQ.x, expectedQ.y, expectedQ.z, expectedQ.w}), 0, 1e-6);
        const std::span<const float> uploaded = node->segmentLight(s);
        ASSERT_EQ(uploaded.size(), 27u);
        for (int trial = 0; trial < 20; ++trial) {
            Vec3d omega{value(rng), value(rng), value(rng)};
            omega = omega * (1 / std::sqrt(omega.x * omega.x + omega.y * omega.y + omega.z * omega.z));
            const Vec3d world = anim::rotate(q, omega);
            for (int c = 0; c < 3; ++c) {
                std::array<double, 9> local{};
                for (int i = 0; i < 9; ++i)
                    local[std::size_t(i)] = uploaded[3 * std::size_t(i) + std::size_t(c)];
                EXPECT_NEAR(lighting::reconstructSh(3, local, omega),
                            lighting::reconstructSh(3, std::span(light.channel[c]).first(9), world), 1e-5);
            }
        }
    }
}

// -- Pictures -------------------------------------------------------------------------------

/// Foreground = pixels that differ from the background colour.
struct Mask {
    int left = kWidth, top = kHeight, right = -1, bottom = -1;
    int pixels = 0;
};

Mask foreground(const RgbaImage& image, const std::array<int, 3>& background)
{
    Mask mask;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            const auto p = image.pixel(x, y);
            if (p[0] == background[0] && p[1] == background[1] && p[2] == background[2])
                continue;
            ++mask.pixels;
            mask.left = std::min(mask.left, x);
            mask.right = std::max(mask.right, x);
            mask.top = std::min(mask.top, y);
            mask.bottom = std::max(mask.bottom, y);
        }
    return mask;
}

void expectMaskMatchesProjection(const RgbaImage& image, std::span<const Vec3> points, const CameraView& view,
                                 const std::array<int, 3>& background)
{
    const PixelRect projected = projectToPixels(points, view, kWidth, kHeight);
    ASSERT_GT(projected.left, 2);
    ASSERT_GT(projected.top, 2);
    ASSERT_LT(projected.right, kWidth - 2);
    ASSERT_LT(projected.bottom, kHeight - 2);
    const Mask mask = foreground(image, background);
    // Every covered pixel lies within the projected bounds (a pixel of slack for rasterisation),
    // and the covered pixels reach the bounds on all four sides.
    EXPECT_NEAR(mask.left, projected.left, 1.5);
    EXPECT_NEAR(mask.right + 1, projected.right, 1.5);
    EXPECT_NEAR(mask.top, projected.top, 1.5);
    EXPECT_NEAR(mask.bottom + 1, projected.bottom, 1.5);
    // And the character fills a good part of them (it is not a scatter of stray pixels).
    const double area = (projected.right - projected.left) * (projected.bottom - projected.top);
    EXPECT_GT(mask.pixels, 0.15 * area);
}

void expectMaskMatchesProjection(const RgbaImage& image, const CharacterNode& node, const CameraView& view,
                                 const std::array<int, 3>& background)
{
    expectMaskMatchesProjection(image, node.posedPositions(), view, background);
}

TEST_F(Render, CreatesAHeadlessContext)
{
    OffscreenRenderer* renderer = s_renderer.get();
    EXPECT_FALSE(renderer->glDescription().empty());
    std::cout << "GL: " << renderer->glDescription() << "\n";
}

TEST_F(Render, CharacterMaskMatchesItsProjectedBoundsInEveryShading)
{
    OffscreenRenderer* renderer = s_renderer.get();
    RenderScene scene(1);
    const std::array<int, 3> background{40, 44, 52};
    scene.setBackgroundColor({40 / 255.0f, 44 / 255.0f, 52 / 255.0f});
    const auto character = makeBoxCharacter();
    CharacterNode* node = std::move(scene.addCharacter(character)).value();
    std::vector<float> frame = restFrame(*character);
    setRotation(frame, 1, anim::normalize(Quat::fromAxisAngle({0, 0, 1}, 0.7f))); // arm out to the side
    node->setPose(frame);
    const CameraView view = frameBounds(scene.characterBounds(), 30, 20, double(kWidth) / kHeight);
    for (Shading shading : {Shading::Prt, Shading::Phong, Shading::Unlit}) {
        SCOPED_TRACE(shadingName(shading));
        scene.setShading(shading);
        auto image = renderer->render(scene, view);
        ASSERT_TRUE(image.ok()) << describe(image.error());
        ASSERT_TRUE(writePng(artifact(std::string("render_boxes_") + shadingName(shading) + ".png"), *image).ok());
        expectMaskMatchesProjection(*image, *node, view, background);
    }
}

TEST_F(Render, SupersamplingSmoothsTheEdgesOfTheSameMask)
{
    auto supersampled = OffscreenRenderer::create(kWidth, kHeight, 4);
    ASSERT_TRUE(supersampled.ok()) << describe(supersampled.error());
    RenderScene scene(1);
    const std::array<int, 3> background{40, 44, 52};
    scene.setBackgroundColor({40 / 255.0f, 44 / 255.0f, 52 / 255.0f});
    scene.setShading(Shading::Unlit);
    const auto character = makeBoxCharacter();
    CharacterNode* node = std::move(scene.addCharacter(character)).value();
    std::vector<float> frame = restFrame(*character);
    setRotation(frame, 1, anim::normalize(Quat::fromAxisAngle({0, 0, 1}, 0.7f)));
    node->setPose(frame);
    const CameraView view = frameBounds(scene.characterBounds(), 30, 20, double(kWidth) / kHeight);
    auto sharp = s_renderer->render(scene, view);
    auto smooth = (*supersampled)->render(scene, view);
    ASSERT_TRUE(sharp.ok() && smooth.ok());
    ASSERT_TRUE(writePng(artifact("render_boxes_supersampled.png"), *smooth).ok());
    expectMaskMatchesProjection(*smooth, *node, view, background);
    // Unlit faces are flat colours: without anti-aliasing the picture holds the background and
    // the two albedos only; with it, edge pixels mix them.
    auto colours = [](const RgbaImage& image) {
        std::set<std::array<std::uint8_t, 4>> distinct;
        for (int y = 0; y < image.height; ++y)
            for (int x = 0; x < image.width; ++x)
                distinct.insert(image.pixel(x, y));
        return distinct.size();
    };
    EXPECT_EQ(colours(*sharp), 3u);
    EXPECT_GT(colours(*smooth), 6u); // 2 × 2 blocks: 3 mixes for each pair of colours
}

TEST_F(Render, PrtUnderSimpleLightsGivesTheExpectedLevels)
{
    OffscreenRenderer* renderer = s_renderer.get();
    RenderScene scene(1);
    const auto character = makeBoxCharacter();
    CharacterNode* node = std::move(scene.addCharacter(character)).value();
    const CameraView view = frameBounds(scene.characterBounds(), 20, 35, double(kWidth) / kHeight);
    const Vec3 top{0.17f, 1.0f, 0.08f};   // on the body's top face, beside the arm
    const Vec3 front{-0.12f, 0.5f, 0.15f}; // on the body's front face
    const auto [topX, topY] = pixelOf(top, view);
    const auto [frontX, frontY] = pixelOf(front, view);
    const double albedo = 0.5;

    // Constant radiance c: a diffuse surface reflects albedo·E/π = albedo·c whatever its normal.
    scene.setLight(constantPlusBand1(0.6, 0, {0, 1, 0}));
    auto flat = renderer->render(scene, view);
    ASSERT_TRUE(flat.ok()) << describe(flat.error());
    ASSERT_TRUE(writePng(artifact("render_boxes_constant_light.png"), *flat).ok());
    for (auto [x, y] : std::array<std::array<int, 2>, 2>{{{topX, topY}, {frontX, frontY}}})
        for (int c = 0; c < 3; ++c)
            EXPECT_NEAR(flat->pixel(x, y)[std::size_t(c)], displayByte(albedo * 0.6), 1) << x << "," << y;

    // Band 1 towards +y adds k/(2π) on the top face and nothing on the vertical front face.
    const double k = 2 * kPi * 0.5;
    scene.setLight(constantPlusBand1(0.3, k, {0, 1, 0}));
    auto lit = renderer->render(scene, view);
    ASSERT_TRUE(lit.ok());
    ASSERT_TRUE(writePng(artifact("render_boxes_light_from_above.png"), *lit).ok());
    EXPECT_NEAR(lit->pixel(topX, topY)[1], displayByte(albedo * (0.3 + 0.5)), 1);
    EXPECT_NEAR(lit->pixel(frontX, frontY)[1], displayByte(albedo * 0.3), 1);

    // Exposure scales radiance before the encoding.
    scene.setExposure(0.5f);
    auto darker = renderer->render(scene, view);
    ASSERT_TRUE(darker.ok());
    EXPECT_NEAR(darker->pixel(topX, topY)[1], displayByte(0.5 * albedo * 0.8), 1);
    (void)node;
}

TEST_F(Render, ARotatedSegmentIsLitOnTheSideThatNowFacesTheLight)
{
    OffscreenRenderer* renderer = s_renderer.get();
    RenderScene scene(1);
    const auto character = makeBoxCharacter();
    CharacterNode* node = std::move(scene.addCharacter(character)).value();
    // Light from the front (+z): front faces get c + k/(2π), faces across it only c.
    const double c = 0.2, k = 2 * kPi * 0.5;
    scene.setLight(constantPlusBand1(c, k, {0, 0, 1}));
    // Turn the arm 90° about +x: its top face (+y in its bind frame) now faces the light and the
    // camera; its former front face points down.
    std::vector<float> frame = restFrame(*character);
    setRotation(frame, 1, anim::normalize(Quat::fromAxisAngle({1, 0, 0}, float(kPi / 2))));
    node->setPose(frame);
    const CameraView view = frameBounds(scene.characterBounds(), 0, 0, double(kWidth) / kHeight);
    auto image = renderer->render(scene, view);
    ASSERT_TRUE(image.ok()) << describe(image.error());
    ASSERT_TRUE(writePng(artifact("render_boxes_rotated_arm.png"), *image).ok());
    // The arm now reaches from z = 0 to z = 0.6 at height 1 ± 0.1; its end face is at z = 0.6.
    const auto [armX, armY] = pixelOf(Vec3{0.0f, 1.02f, 0.6f}, view);
    const auto [bodyX, bodyY] = pixelOf(Vec3{0.1f, 0.4f, 0.15f}, view);
    const double lit = 0.9 * (c + k / (2 * kPi)); // the arm's red albedo channel
    EXPECT_NEAR(image->pixel(armX, armY)[0], displayByte(lit), 1);
    EXPECT_NEAR(image->pixel(bodyX, bodyY)[0], displayByte(0.5 * (c + k / (2 * kPi))), 1);
    // Had the light not been turned with the arm, the face would get c only (normal ⟂ light).
    EXPECT_GT(image->pixel(armX, armY)[0], displayByte(0.9 * c) + 20);
}

TEST_F(Render, BakedTransferIsWhatTheShaderSums)
{
    OffscreenRenderer* renderer = s_renderer.get();
    RenderScene scene(1);
    const auto character = makeBoxCharacter();
    // A bake of order 3 (three vec4 attributes, the last one padded) with a transfer vector of
    // its own on each face of the body; the arm is an occluder and keeps the DU transfer.
    lighting::TransferBake bake;
    bake.order = 3;
    bake.transferKind = lighting::TransferKind::DiffuseShadowed;
    bake.vertexCount = character->mesh.vertexCount();
    std::mt19937 rng(11);
    std::uniform_real_distribution<float> coefficient(-0.15f, 0.15f);
    for (const scene::Segment& segment : character->mesh.segments) {
        lighting::BakedSegment baked;
        baked.name = segment.name;
        baked.firstVertex = segment.firstVertex;
        baked.vertexCount = segment.vertexCount;
        baked.transferOffset = bake.transfer.size();
        baked.baked = segment.joint == "root";
        bake.segments.push_back(baked);
        if (!baked.baked)
            continue;
        for (std::uint32_t face = 0; face < segment.vertexCount / 4; ++face) {
            std::array<float, 9> t{};
            for (float& value : t)
                value = coefficient(rng);
            t[0] = 0.25f; // mostly lit, so the clamp at 0 never shows
            for (int corner = 0; corner < 4; ++corner)
                bake.transfer.insert(bake.transfer.end(), t.begin(), t.end());
        }
    }
    CharacterNode* node = std::move(scene.addCharacter(character, &bake)).value();
    ShRgb light;
    light.order = 3;
    for (int c = 0; c < 3; ++c)
        for (int i = 0; i < 9; ++i)
            light.channel[c][std::size_t(i)] = i == 0 ? 2.0 + 0.2 * c : 0.6 * std::cos(1.7 * i + c);
    scene.setLight(light);
    std::vector<float> frame = restFrame(*character);
    const Quat turn = anim::normalize(Quat::fromAxisAngle({0, 1, 0}, 0.5f));
    setRotation(frame, 0, turn);
    node->setPose(frame);
    const CameraView view = frameBounds(scene.characterBounds(), 20, 10, double(kWidth) / kHeight);
    auto image = renderer->render(scene, view);
    ASSERT_TRUE(image.ok()) << describe(image.error());
    ASSERT_TRUE(writePng(artifact("render_boxes_baked.png"), *image).ok());

    // The body's front face (+z at rest: vertices 16 … 19): the bake's reference shading.
    const std::array<double, 3> baked = lighting::shadeVertex(bake, character->mesh, 16, light, node->segmentRotation(0));
    const auto [bodyX, bodyY] = pixelOf(anim::rotate(turn, Vec3{-0.12f, 0.5f, 0.15f}), view);
    for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(image->pixel(bodyX, bodyY)[std::size_t(c)], displayByte(0.5 * baked[std::size_t(c)]), 1);
    // The arm's front face, unbaked: DU, i.e. irradiance/π for its current normal.
    const Vec3 armNormal = anim::rotate(turn, Vec3{0, 0, 1});
    const std::array<double, 3> du = irradiance(light, Vec3d{armNormal.x, armNormal.y, armNormal.z});
    const auto [armX, armY] = pixelOf(anim::rotate(turn, Vec3{0.0f, 1.3f, 0.1f}), view);
    EXPECT_NEAR(image->pixel(armX, armY)[0], displayByte(0.9 * du[0] / kPi), 1);
    EXPECT_NEAR(image->pixel(armX, armY)[2], displayByte(0.25 * du[2] / kPi), 1);
}

TEST_F(Render, DefaultHumanoidMaskMatchesItsProjectedBounds)
{
    OffscreenRenderer* renderer = s_renderer.get();
    auto humanoid = scene::makeDefaultHumanoid();
    ASSERT_TRUE(humanoid.ok()) << describe(humanoid.error());
    const auto character = std::make_shared<scene::Character>(std::move(*humanoid));
    RenderScene scene(1);
    const std::array<int, 3> background{40, 44, 52};
    scene.setBackgroundColor({40 / 255.0f, 44 / 255.0f, 52 / 255.0f});
    CharacterNode* node = std::move(scene.addCharacter(character)).value();
    // Raise the left arm and bend the right elbow, so the pose is not the rest pose.
    std::vector<float> frame = restFrame(*character);
    const anim::Skeleton& skeleton = character->skeleton;
    if (const int shoulder = skeleton.find("l_shoulder"); shoulder >= 0)
        setRotation(frame, shoulder, anim::normalize(Quat::fromAxisAngle({0, 0, 1}, 1.1f)));
    if (const int elbow = skeleton.find("r_elbow"); elbow >= 0)
        setRotation(frame, elbow, anim::normalize(Quat::fromAxisAngle({1, 0, 0}, -1.2f)));
    node->setPose(frame);
    const CameraView view = frameBounds(scene.characterBounds(), 20, 10, double(kWidth) / kHeight);
    for (Shading shading : {Shading::Prt, Shading::Phong, Shading::Unlit}) {
        SCOPED_TRACE(shadingName(shading));
        scene.setShading(shading);
        auto image = renderer->render(scene, view);
        ASSERT_TRUE(image.ok()) << describe(image.error());
        ASSERT_TRUE(writePng(artifact(std::string("render_humanoid_") + shadingName(shading) + ".png"), *image).ok());
        expectMaskMatchesProjection(*image, *node, view, background);
    }
}

// The built-in demo as the CLI and the studio draw it (ScenarioScene): both characters, posed by
// their schedules mid-wave, cover exactly the projection of their posed meshes.
TEST_F(Render, DemoScenarioMaskMatchesItsCharactersProjectedBounds)
{
    auto demo = scenario::loadScenario(thespis::test::resources("demo.thespis"));
    ASSERT_TRUE(demo.ok()) << describe(demo.error());
    auto built = ScenarioScene::create(*demo, thespis::test::resources());
    ASSERT_TRUE(built.ok()) << describe(built.error());
    ScenarioScene& demoScene = **built;
    ASSERT_EQ(demoScene.scene().characterCount(), demo->characters.size());
    const std::array<int, 3> background{40, 44, 52};
    demoScene.scene().setBackgroundColor({40 / 255.0f, 44 / 255.0f, 52 / 255.0f});
    demoScene.playAt(core::secondsToTicks(2.0));
    std::vector<Vec3> posed;
    for (std::size_t c = 0; c < demoScene.scene().characterCount(); ++c) {
        const auto points = demoScene.scene().character(c).posedPositions();
        posed.insert(posed.end(), points.begin(), points.end());
    }
    const CameraView view = frameBounds(demoScene.scene().characterBounds(), 20, 8, double(kWidth) / kHeight);
    for (Shading shading : {Shading::Prt, Shading::Phong, Shading::Unlit}) {
        SCOPED_TRACE(shadingName(shading));
        demoScene.scene().setShading(shading);
        auto image = s_renderer->render(demoScene.scene(), view);
        ASSERT_TRUE(image.ok()) << describe(image.error());
        ASSERT_TRUE(writePng(artifact(std::string("render_demo_") + shadingName(shading) + ".png"), *image).ok());
        expectMaskMatchesProjection(*image, posed, view, background);
    }
}

TEST_F(Render, BaseColourTexturesAreSampledInSrgb)
{
    auto textured = makeBoxCharacter();
    // A 2 × 2 sRGB texture; the body's front face reads texel (0, 0) and its other faces texel
    // (1, 1), each at the texel's centre (constant coordinates, so no filtering mixes them).
    textured->textures.push_back({"checker", 2, 2, {200, 40, 30, 255, 0, 0, 0, 255, 0, 0, 0, 255, 30, 90, 220, 255}});
    textured->materials[0].baseColor = {1, 1, 1, 1};
    textured->materials[0].baseColorTexture = 0;
    textured->texcoords.assign(textured->mesh.vertexCount(), {0.75f, 0.75f});
    for (std::uint32_t v = 16; v < 20; ++v) // the body's +z face
        textured->texcoords[v] = {0.25f, 0.25f};
    ASSERT_TRUE(textured->validate().ok());
    RenderScene scene(1);
    scene.setShading(Shading::Unlit);
    ASSERT_TRUE(scene.addCharacter(textured).ok());
    const CameraView view = frameBounds(scene.characterBounds(), 20, 35, double(kWidth) / kHeight);
    auto image = s_renderer->render(scene, view);
    ASSERT_TRUE(image.ok()) << describe(image.error());
    ASSERT_TRUE(writePng(artifact("render_boxes_textured.png"), *image).ok());
    const auto [frontX, frontY] = pixelOf(Vec3{-0.12f, 0.5f, 0.15f}, view);
    const auto [topX, topY] = pixelOf(Vec3{0.17f, 1.0f, 0.08f}, view);
    const std::array<int, 3> red{200, 40, 30}, blue{30, 90, 220};
    for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(image->pixel(frontX, frontY)[std::size_t(c)], red[std::size_t(c)], 1);
        EXPECT_NEAR(image->pixel(topX, topY)[std::size_t(c)], blue[std::size_t(c)], 1);
    }
}

TEST_F(Render, BackgroundProbeIsSeenInItsOwnOrientation)
{
    OffscreenRenderer* renderer = s_renderer.get();
    // A lat-long probe whose colour says its direction: red towards +x, green towards −z, blue up.
    lighting::HdrImage image;
    image.width = 128;
    image.height = 64;
    image.rgb.resize(std::size_t(image.width * image.height * 3));
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            Vec3d d;
            lighting::directionOfPixel(lighting::ProbeLayout::LatLong, image.width, image.height, x, y, d);
            float* p = image.rgb.data() + 3 * (std::size_t(y) * std::size_t(image.width) + std::size_t(x));
            p[0] = float(std::max(d.x, 0.0));
            p[1] = float(std::max(-d.z, 0.0));
            p[2] = float(std::max(d.y, 0.0));
        }
    auto probe = lighting::LightProbe::fromImage(std::move(image), lighting::ProbeLayout::LatLong);
    ASSERT_TRUE(probe.ok());
    RenderScene scene(1);
    scene.setBackgroundProbe(*probe, 256);
    struct Look {
        Vec3d towards;
        int channel;
    };
    for (const Look& look : {Look{{0, 0, -1}, 1}, Look{{1, 0, 0}, 0}, Look{{0, 1, 0}, 2}}) {
        CameraView view;
        view.eye = {0, 0, 0};
        view.centre = look.towards;
        view.up = look.channel == 2 ? Vec3d{0, 0, -1} : Vec3d{0, 1, 0};
        auto picture = renderer->render(scene, view);
        ASSERT_TRUE(picture.ok()) << describe(picture.error());
        if (look.channel == 1) {
            ASSERT_TRUE(writePng(artifact("render_background_probe.png"), *picture).ok());
        }
        const auto centre = picture->pixel(kWidth / 2, kHeight / 2);
        for (int c = 0; c < 3; ++c) {
            if (c == look.channel)
                EXPECT_GE(centre[std::size_t(c)], 250) << "looking along channel " << look.channel;
            else
                EXPECT_LE(centre[std::size_t(c)], displayByte(0.05)) << "looking along channel " << look.channel;
        }
    }
}

TEST_F(Render, GroundShowsTheIrradianceOfItsUpNormal)
{
    OffscreenRenderer* renderer = s_renderer.get();
    RenderScene scene(1);
    scene.setGroundVisible(true);
    const ShRgb light = constantPlusBand1(0.4, 2 * kPi * 0.3, {0, 1, 0});
    scene.setLight(light);
    CameraView view;
    view.eye = {0.3, 3, 2};
    view.centre = {0.5, 0, 0.5};
    auto image = renderer->render(scene, view);
    ASSERT_TRUE(image.ok()) << describe(image.error());
    ASSERT_TRUE(writePng(artifact("render_ground.png"), *image).ok());
    // Radiance 0.5·E(up)/π, between the grid lines.
    const double expected = 0.5 * irradiance(light, {0, 1, 0})[0] / kPi;
    EXPECT_NEAR(expected, 0.5 * (0.4 + 0.3), 1e-9);
    const auto centre = image->pixel(kWidth / 2, kHeight / 2);
    EXPECT_NEAR(centre[0], displayByte(expected), 1);
}

TEST_F(Render, DemoLightLooksLitOnTheBoxes)
{
    OffscreenRenderer* renderer = s_renderer.get();
    RenderScene scene(1);
    scene.setGroundVisible(true);
    const auto character = makeBoxCharacter();
    ASSERT_TRUE(scene.addCharacter(character).ok());
    const CameraView view = frameBounds(scene.characterBounds(), 25, 15, double(kWidth) / kHeight);
    for (Shading shading : {Shading::Prt, Shading::Phong}) {
        scene.setShading(shading);
        auto image = renderer->render(scene, view);
        ASSERT_TRUE(image.ok()) << describe(image.error());
        ASSERT_TRUE(writePng(artifact(std::string("render_boxes_ground_") + shadingName(shading) + ".png"), *image).ok());
        // The top of the body is lit by the sky and brighter than the background.
        const auto [x, y] = pixelOf(Vec3{0.17f, 1.0f, 0.08f}, view);
        EXPECT_GT(image->pixel(x, y)[1], 60);
    }
}

} // namespace
} // namespace thespis::core::render
