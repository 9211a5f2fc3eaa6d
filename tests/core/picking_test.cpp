// Selecting segments in the viewport (core/render/picking.h and CharacterNode's highlight): rays
// cast at the built-in humanoid hit the segment they aim at, on the posed mesh and not the rest
// pose, report where they hit, miss when they should, and allocate nothing; a highlighted
// segment is tinted towards orange in every shading mode while the rest of the picture stays
// exactly as it was. Pictures are saved under <build>/test-artifacts/picking_*.png.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "allocation_counter.h"
#include "anim/frame.h"
#include "render/camera.h"
#include "render/character_node.h"
#include "render/offscreen_renderer.h"
#include "render/picking.h"
#include "render/render_scene.h"
#include "scene/default_humanoid.h"
#include "offscreen_suite.h"
#include "test_support.h"

namespace thespis::core::render {
namespace {

using anim::Quat;
using anim::Vec3;
using anim::Vec3d;

std::shared_ptr<const scene::Character> humanoid()
{
    static const std::shared_ptr<const scene::Character> character = [] {
        auto made = scene::makeDefaultHumanoid();
        EXPECT_TRUE(made.ok()) << describe(made.error());
        return std::make_shared<const scene::Character>(std::move(*made));
    }();
    return character;
}

std::unique_ptr<CharacterNode> makeNode()
{
    auto node = CharacterNode::create(humanoid());
    EXPECT_TRUE(node.ok()) << describe(node.error());
    return std::move(node).value();
}

std::size_t segmentIndex(const scene::Character& character, const std::string& name)
{
    for (std::size_t s = 0; s < character.mesh.segments.size(); ++s)
        if (character.mesh.segments[s].name == name)
            return s;
    ADD_FAILURE() << "no segment " << name;
    return 0;
}

// The centre of a segment's posed bounding box.
Vec3d posedCentre(const CharacterNode& node, const std::string& name)
{
    const scene::Segment& segment = node.character().mesh.segments[segmentIndex(node.character(), name)];
    Bounds bounds;
    for (std::uint32_t v = segment.firstVertex; v < segment.firstVertex + segment.vertexCount; ++v) {
        const Vec3& p = node.posedPositions()[v];
        bounds.add(Vec3d{p.x, p.y, p.z});
    }
    return bounds.centre();
}

// A ray from 3 m in front of the character (+z) straight back at `target`.
PickRay fromTheFront(const Vec3d& target)
{
    return {Vec3d{target.x, target.y, target.z + 3.0}, Vec3d{0, 0, -1}};
}

std::string hitName(const CharacterNode& node, const std::optional<PickHit>& hit)
{
    return hit ? node.character().mesh.segments[hit->segment].name : std::string("(nothing)");
}

TEST(Picking, RaysAtSegmentCentresHitThoseSegments)
{
    const auto node = makeNode();
    for (const char* name : {"skull", "l_forearm", "r_forearm", "l_thigh", "r_calf", "l_talus"}) {
        SCOPED_TRACE(name);
        const Vec3d centre = posedCentre(*node, name);
        const auto hit = pick(*node, fromTheFront(centre), 3);
        ASSERT_TRUE(hit.has_value());
        EXPECT_EQ(hitName(*node, hit), name);
        EXPECT_EQ(hit->character, 3u);
        // The hit lies on the ray, in front of the segment's centre, at the reported distance.
        EXPECT_NEAR(hit->point.x, centre.x, 1e-9);
        EXPECT_NEAR(hit->point.y, centre.y, 1e-9);
        EXPECT_GT(hit->point.z, centre.z);
        EXPECT_LT(hit->point.z, centre.z + 0.2);
        EXPECT_NEAR(hit->distance, centre.z + 3.0 - hit->point.z, 1e-9);
        // The triangle belongs to the segment.
        const scene::Segment& segment = node->character().mesh.segments[hit->segment];
        EXPECT_GE(hit->triangle, segment.firstTriangle);
        EXPECT_LT(hit->triangle, segment.firstTriangle + segment.triangleCount);
    }
}

TEST(Picking, TheNearestSurfaceWins)
{
    // From behind, a ray at the skull's centre meets the hair first (it covers the back of the
    // head); from the front, the face.
    const auto node = makeNode();
    const Vec3d centre = posedCentre(*node, "skull");
    const auto front = pick(*node, fromTheFront(centre));
    const auto back = pick(*node, PickRay{Vec3d{centre.x, centre.y, centre.z - 3.0}, Vec3d{0, 0, 2}});
    EXPECT_EQ(hitName(*node, front), "skull");
    EXPECT_EQ(hitName(*node, back), "hair");
    ASSERT_TRUE(front && back);
    EXPECT_LT(back->point.z, front->point.z);
    // The direction's length does not change the distance, which is in metres.
    EXPECT_NEAR(back->distance, back->point.z - (centre.z - 3.0), 1e-9);
}

TEST(Picking, RaysThatMissHitNothing)
{
    const auto node = makeNode();
    const Vec3d head = posedCentre(*node, "skull");
    EXPECT_FALSE(pick(*node, PickRay{Vec3d{2.0, 1.0, 3.0}, Vec3d{0, 0, -1}})); // beside the character
    EXPECT_FALSE(pick(*node, PickRay{Vec3d{0, 2.5, 3.0}, Vec3d{0, 0, -1}}));   // above its head
    // Pointing away: the head is behind the origin.
    EXPECT_FALSE(pick(*node, PickRay{Vec3d{head.x, head.y, head.z + 3.0}, Vec3d{0, 0, 1}}));
    EXPECT_FALSE(pick(*node, PickRay{head, Vec3d{0, 0, 0}}));          // no direction
    EXPECT_FALSE(pick(*node, PickRay{head, Vec3d{std::nan(""), 0, 1}})); // not a direction
}

TEST(Picking, PicksThePosedMeshNotTheRestPose)
{
    const auto node = makeNode();
    const scene::Character& character = node->character();
    const Vec3d restForearm = posedCentre(*node, "l_forearm");
    // Raise the left arm sideways to shoulder height.
    std::vector<float> frame = character.skeleton.restFrame();
    const int shoulder = character.skeleton.find("l_shoulder");
    ASSERT_GE(shoulder, 0);
    anim::rotationAt(std::span<float>(frame), shoulder) = anim::normalize(Quat::fromAxisAngle({0, 0, 1}, 1.4f));
    node->setPose(frame);
    const Vec3d posedForearm = posedCentre(*node, "l_forearm");
    ASSERT_GT(posedForearm.y, restForearm.y + 0.3) << "the pose should lift the forearm";

    EXPECT_EQ(hitName(*node, pick(*node, fromTheFront(posedForearm))), "l_forearm");
    EXPECT_NE(hitName(*node, pick(*node, fromTheFront(restForearm))), "l_forearm");
}

TEST(Picking, PicksTheNearestCharacterOfAScene)
{
    RenderScene scene(1);
    ASSERT_TRUE(scene.addCharacter(humanoid()).ok());
    CharacterNode* second = std::move(scene.addCharacter(humanoid())).value();
    // Move the second character 1 m towards the camera: it hides the first.
    std::vector<float> frame = humanoid()->skeleton.restFrame();
    frame[humanoid()->skeleton.frameLayout()->translationOffset() + 2] += 1.0f;
    second->setPose(frame);
    const Vec3d head = posedCentre(*second, "skull");
    const auto hit = pick(scene, fromTheFront(head));
    ASSERT_TRUE(hit.has_value());
    EXPECT_EQ(hit->character, 1u);
    EXPECT_EQ(hitName(*second, hit), "skull");
    // Aimed at the first one's head from the side, where the second is not in the way.
    const Vec3d firstHead = posedCentre(scene.character(0), "skull");
    const auto side = pick(scene, PickRay{Vec3d{firstHead.x + 3.0, firstHead.y, firstHead.z}, Vec3d{-1, 0, 0}});
    ASSERT_TRUE(side.has_value());
    EXPECT_EQ(side->character, 0u);
    EXPECT_FALSE(pick(scene, PickRay{Vec3d{3, 1, 3}, Vec3d{0, 0, -1}}));
}

TEST(Picking, AllocatesNothing)
{
    const auto node = makeNode();
    const PickRay ray = fromTheFront(posedCentre(*node, "skull"));
    std::optional<PickHit> hit = pick(*node, ray); // warm up
    const long before = thespis::test::allocationCount();
    for (int i = 0; i < 5; ++i)
        hit = pick(*node, ray);
    EXPECT_EQ(thespis::test::allocationCount(), before);
    EXPECT_TRUE(hit.has_value());
}

TEST(CharacterNodeHighlight, StartsOffAndFollowsTheSetter)
{
    const auto node = makeNode();
    const std::size_t skull = segmentIndex(node->character(), "skull");
    for (std::size_t s = 0; s < node->segmentCount(); ++s)
        EXPECT_FALSE(node->segmentHighlighted(s));
    node->setSegmentHighlighted(skull, true);
    EXPECT_TRUE(node->segmentHighlighted(skull));
    float value = 0;
    ASSERT_TRUE(node->segmentGeometry(skull)->getStateSet()->getUniform("selectionHighlight")->get(value));
    EXPECT_EQ(value, 1.0f);
    node->setSegmentHighlighted(skull, false);
    EXPECT_FALSE(node->segmentHighlighted(skull));
}

using HighlightPicture = thespis::test::OffscreenSuite<240, 320>;

TEST_F(HighlightPicture, TintsTheSelectedSegmentInEveryShading)
{
    RenderScene scene(1);
    CharacterNode* node = std::move(scene.addCharacter(humanoid())).value();
    const CameraView view = frameBounds(scene.characterBounds(), 0, 0, double(kWidth) / kHeight);
    auto pixelAt = [&](const Vec3d& point) {
        const Vec3 p{float(point.x), float(point.y), float(point.z)};
        const PixelRect at = projectToPixels(std::span(&p, 1), view, kWidth, kHeight);
        return std::array<int, 2>{int(at.left), int(at.top)};
    };
    // The forehead (above the skull's vertices' centre, which the face's fine mesh pulls down
    // to the nose, where the rim light of the highlight adds more) and the chest, from the front.
    const auto face = pixelAt(posedCentre(*node, "skull") + Vec3d{0, 0.045, 0});
    const auto chest = pixelAt(posedCentre(*node, "t1"));
    const std::size_t skull = segmentIndex(node->character(), "skull");
    for (Shading shading : {Shading::Prt, Shading::Phong, Shading::Unlit}) {
        SCOPED_TRACE(shadingName(shading));
        scene.setShading(shading);
        node->setSegmentHighlighted(skull, false);
        auto plain = s_renderer->render(scene, view);
        node->setSegmentHighlighted(skull, true);
        auto selected = s_renderer->render(scene, view);
        ASSERT_TRUE(plain.ok() && selected.ok());
        ASSERT_TRUE(writePng(thespis::test::artifact(std::string("picking_highlight_") + shadingName(shading) + ".png"),
                             *selected).ok());
        const auto before = plain->pixel(face[0], face[1]);
        const auto after = selected->pixel(face[0], face[1]);
        // 35 % of the way to orange (255, 140, 26): red up, blue down, by about a third of the gap.
        EXPECT_NEAR(after[0], before[0] + 0.35 * (255 - before[0]), 12) << int(before[0]);
        EXPECT_NEAR(after[2], before[2] + 0.35 * (26 - before[2]), 12) << int(before[2]);
        EXPECT_GT(int(after[0]) - int(after[2]), int(before[0]) - int(before[2]) + 20);
        // Other segments are drawn exactly as before.
        EXPECT_EQ(plain->pixel(chest[0], chest[1]), selected->pixel(chest[0], chest[1]));
        // Switched off again, the picture is the plain one.
        node->setSegmentHighlighted(skull, false);
        auto again = s_renderer->render(scene, view);
        ASSERT_TRUE(again.ok());
        EXPECT_EQ(again->rgba, plain->rgba);
    }
}

} // namespace
} // namespace thespis::core::render
