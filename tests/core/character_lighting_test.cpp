// PRT on the built-in humanoid (issue 4 §3): DS and DSM shadowing where bodies occlude
// themselves, and paper Fig. 14 — hair lying close over the skull darkens the skull with DSM
// unless the hair is tagged receiver.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <tuple>

#include <algorithm>

#include "anim/keyframe_clip.h"
#include "lighting/sh.h"
#include "lighting/transfer_bake.h"
#include "render/character_node.h"
#include "render/offscreen_renderer.h"
#include "scene/default_humanoid.h"
#include "test_support.h"

namespace {

using namespace thespis::core;

scene::Character humanoid()
{
    auto made = scene::makeDefaultHumanoid();
    EXPECT_TRUE(made.ok());
    return std::move(made).value();
}

lighting::TransferBake bake(const scene::CharacterMesh& mesh, lighting::TransferKind kind)
{
    lighting::BakeSettings settings;
    settings.order = 3;
#ifdef THESPIS_SANITIZED
    settings.raysPerVertex = 64;
#else
    settings.raysPerVertex = 256;
#endif
    settings.transfer = kind;
    auto baked = lighting::bakeTransfer(mesh, settings);
    EXPECT_TRUE(baked.ok()) << (baked.ok() ? "" : baked.error().message);
    return std::move(baked).value();
}

// The DC coefficient of the transfer: the vertex's ambient occlusion × π·Y00-scale, the same
// for any light, so it compares shadowing without choosing a light.
double dc(const lighting::TransferBake& baked, std::uint32_t vertex)
{
    const auto t = baked.vertexTransfer(vertex);
    return t.empty() ? 0.0 : double(t[0]);
}

const scene::Segment& segment(const scene::CharacterMesh& mesh, const std::string& name)
{
    const scene::Segment* found = mesh.findSegment(name);
    EXPECT_NE(found, nullptr) << name;
    return *found;
}

template <class Select>
std::vector<std::uint32_t> select(const scene::CharacterMesh& mesh, std::initializer_list<const char*> segments, Select keep)
{
    std::vector<std::uint32_t> vertices;
    for (const char* name : segments) {
        const scene::Segment& s = segment(mesh, name);
        for (std::uint32_t v = s.firstVertex; v < s.firstVertex + s.vertexCount; ++v)
            if (keep(mesh.positions[v], mesh.normals[v]))
                vertices.push_back(v);
    }
    return vertices;
}

double meanDc(const lighting::TransferBake& baked, const std::vector<std::uint32_t>& vertices)
{
    double sum = 0;
    for (std::uint32_t v : vertices)
        sum += dc(baked, v);
    return vertices.empty() ? 0.0 : sum / double(vertices.size());
}

// The paper's DS (Sloan et al.) traces rays against the vertex's own segment only, so on a
// segmented body it shadows only where a segment hides part of itself (between the fingers of a
// hand segment); the arm hanging beside the torso and the other thigh are other segments, which
// only DSM's merged proxy mesh sees (paper §6.1.1). Same rays for all three kinds: where nothing
// is hit DS equals DU.
TEST(CharacterLighting, ShadowedTransferIsDarkerUnderTheArmsAndBetweenTheLegs)
{
    const scene::Character body = humanoid();
    const auto du = bake(body.mesh, lighting::TransferKind::DiffuseUnshadowed);
    const auto ds = bake(body.mesh, lighting::TransferKind::DiffuseShadowed);
    const auto dsm = bake(body.mesh, lighting::TransferKind::DiffuseShadowedMerged);

    // The torso's flanks facing the hanging arms, and the arms' inner sides facing the torso.
    const auto underArms = select(body.mesh, {"t6", "t10", "l1", "l_upperarm", "r_upperarm"},
                                  [](const anim::Vec3& p, const anim::Vec3& n) {
                                      const bool flank = std::abs(p.x) > 0.08f && n.x * p.x > 0.5f * std::abs(p.x);
                                      const bool innerArm = std::abs(p.x) > 0.15f && n.x * p.x < -0.5f * std::abs(p.x);
                                      return p.y > 1.05f && p.y < 1.35f && (flank || innerArm);
                                  });
    // The thighs' inner sides, facing each other.
    const auto betweenLegs = select(body.mesh, {"l_thigh", "r_thigh"}, [](const anim::Vec3& p, const anim::Vec3& n) {
        return p.y > 0.55f && p.y < 0.85f && n.x * p.x < -0.5f * std::abs(p.x);
    });
    const auto hands = select(body.mesh, {"l_carpal", "r_carpal"}, [](const anim::Vec3&, const anim::Vec3&) { return true; });
    ASSERT_GT(underArms.size(), 50u);
    ASSERT_GT(betweenLegs.size(), 50u);
    for (const auto& [region, vertices] : {std::pair{"under the arms", underArms}, std::pair{"between the legs", betweenLegs},
                                           std::pair{"hands", hands}}) {
        const double unshadowed = meanDc(du, vertices), shadowed = meanDc(ds, vertices), merged = meanDc(dsm, vertices);
        std::printf("%s (%zu vertices): DU %.4f, DS %.4f, DSM %.4f\n", region, vertices.size(), unshadowed, shadowed, merged);
        EXPECT_LT(merged, 0.8 * unshadowed) << region;
        EXPECT_LE(merged, shadowed) << region;
    }
    EXPECT_LT(meanDc(ds, hands), 0.95 * meanDc(du, hands)) << "fingers shadow the rest of their hand segment";
    for (std::uint32_t v = 0; v < body.mesh.vertexCount(); ++v) {
        ASSERT_LE(dc(ds, v), dc(du, v) + 1e-6) << "vertex " << v << ": DS is brighter than DU";
        ASSERT_LE(dc(dsm, v), dc(ds, v) + 1e-6) << "vertex " << v << ": DSM is brighter than DS";
    }
}

// Skull vertices within 2 cm of a hair vertex: the band under and along the hair's edge.
std::vector<std::uint32_t> skullNextToHair(const scene::CharacterMesh& mesh)
{
    const scene::Segment& hair = segment(mesh, "hair");
    return select(mesh, {"skull"}, [&](const anim::Vec3& p, const anim::Vec3&) {
        for (std::uint32_t h = hair.firstVertex; h < hair.firstVertex + hair.vertexCount; ++h) {
            const anim::Vec3& q = mesh.positions[h];
            const float dx = p.x - q.x, dy = p.y - q.y, dz = p.z - q.z;
            if (dx * dx + dy * dy + dz * dz < 0.02f * 0.02f)
                return true;
        }
        return false;
    });
}

// Vertices whose transfer keeps less than half of the unshadowed energy.
std::size_t darkened(const std::vector<std::uint32_t>& vertices, const lighting::TransferBake& shadowed,
                     const lighting::TransferBake& unshadowed)
{
    std::size_t count = 0;
    for (std::uint32_t v : vertices)
        count += dc(shadowed, v) < 0.5 * dc(unshadowed, v) ? 1 : 0;
    return count;
}

TEST(CharacterLighting, HairOverTheSkullDarkensItUnlessTaggedReceiver) // paper Fig. 14
{
    scene::Character body = humanoid();
    const auto du = bake(body.mesh, lighting::TransferKind::DiffuseUnshadowed);
    const auto untagged = bake(body.mesh, lighting::TransferKind::DiffuseShadowedMerged);
    auto untaggedBody = std::make_shared<const scene::Character>(body);
    ASSERT_TRUE(scene::applySegmentTags(body.mesh, {{"hair", scene::SegmentRole::Receiver}}).ok());
    const auto tagged = bake(body.mesh, lighting::TransferKind::DiffuseShadowedMerged);

    const auto band = skullNextToHair(body.mesh);
    const std::size_t darkUntagged = darkened(band, untagged, du);
    const std::size_t darkTagged = darkened(band, tagged, du);
    std::printf("skull next to the hair: %zu vertices, darkened %zu with untagged hair, %zu with hair tagged receiver\n",
                band.size(), darkUntagged, darkTagged);
    EXPECT_GT(darkUntagged, band.size() / 2);
    EXPECT_LT(darkTagged, darkUntagged / 10);

    // The two heads side by side as pictures (the paper's figure), for people to look at.
    auto renderer = render::OffscreenRenderer::create(480, 480, 4);
    ASSERT_TRUE(renderer) << "No OpenGL context for the Fig. 14 pictures: " << describe(renderer.error());
    auto taggedBody = std::make_shared<const scene::Character>(std::move(body));
    const scene::Segment& skull = segment(taggedBody->mesh, "skull");
    render::Bounds head;
    for (std::uint32_t v = skull.firstVertex; v < skull.firstVertex + skull.vertexCount; ++v)
        head.add(anim::Vec3d{taggedBody->mesh.positions[v].x, taggedBody->mesh.positions[v].y, taggedBody->mesh.positions[v].z});
    const std::size_t hairIndex = std::size_t(taggedBody->mesh.findSegment("hair") - taggedBody->mesh.segments.data());
    for (const auto& [name, character, baked] :
         {std::tuple{"fig14_hair_untagged", untaggedBody, &untagged}, std::tuple{"fig14_hair_receiver", taggedBody, &tagged}}) {
        render::RenderScene scene(1);
        auto added = scene.addCharacter(character, baked);
        ASSERT_TRUE(added.ok()) << added.error().message;
        // From the side and a little above, with the hair and then without it: what the hair does
        // to the skull shows once the hair is lifted off.
        const render::CameraView view = render::frameBounds(head, 100, 15, 1.0);
        for (const bool showHair : {true, false}) {
            (*added)->segmentGeometry(hairIndex)->setNodeMask(showHair ? ~0u : 0u);
            auto picture = (*renderer)->render(scene, view);
            ASSERT_TRUE(picture.ok()) << picture.error().message;
            ASSERT_TRUE(render::writePng(thespis::test::artifact(std::string(name) + (showHair ? ".png" : "_lifted.png")),
                                         *picture).ok());
        }
    }
}

// One segment alone as a mesh (its vertices, triangles re-indexed), posed or not: DS sees only
// the vertex's own segment, so baking the skull alone is baking it in the whole body.
scene::CharacterMesh segmentMesh(const scene::CharacterMesh& mesh, const scene::Segment& s,
                                 std::span<const anim::Vec3> positions, std::span<const anim::Vec3> normals)
{
    scene::CharacterMesh part;
    part.positions.assign(positions.begin() + s.firstVertex, positions.begin() + s.firstVertex + s.vertexCount);
    part.normals.assign(normals.begin() + s.firstVertex, normals.begin() + s.firstVertex + s.vertexCount);
    for (std::size_t i = std::size_t(s.firstTriangle) * 3; i < (std::size_t(s.firstTriangle) + s.triangleCount) * 3; ++i)
        part.indices.push_back(mesh.indices[i] - s.firstVertex);
    scene::Segment only = s;
    only.firstVertex = only.firstTriangle = 0;
    only.bindRotation = {};
    part.segments = {only};
    return part;
}

// Paper §6.1.1: a rigid segment (the skull, in the paper's posture-independent set) keeps its
// transfer whatever the pose; turning it is lighting it with the world light rotated into its frame. So the skull turned by a clip and
// shaded with the renderer's rotated light matches a fresh bake of the turned skull.
TEST(CharacterLighting, TurningTheSkullRotatesItsLightingLikeABakeOfThePose)
{
    auto body = std::make_shared<const scene::Character>(humanoid());
    const scene::CharacterMesh& mesh = body->mesh;
    const std::size_t skullIndex = std::size_t(mesh.findSegment("skull") - mesh.segments.data());
    const scene::Segment& skull = mesh.segments[skullIndex];

    // A clip from rest to the head turned 50° to its left and tilted 25° down, evaluated at its end.
    const anim::Skeleton& skeleton = body->skeleton;
    std::vector<float> keys = skeleton.restFrame();
    std::vector<float> turned = keys;
    const anim::Quat turn = anim::Quat::fromAxisAngle(anim::Vec3{0, 1, 0}, 0.87f) *
                            anim::Quat::fromAxisAngle(anim::Vec3{1, 0, 0}, 0.44f);
    anim::rotationAt(std::span<float>(turned), skeleton.find("skullbase")) = turn;
    keys.insert(keys.end(), turned.begin(), turned.end());
    auto clip = anim::KeyframeClip::create(skeleton.frameLayout(), 1.0, keys, "turn head");
    ASSERT_TRUE(clip.ok());
    std::vector<float> frame(skeleton.frameLayout()->floatCount());
    (*clip)->evaluate(1.0, frame);

    auto node = render::CharacterNode::create(body, nullptr, {.unbakedOrder = 4});
    ASSERT_TRUE(node.ok()) << node.error().message;
    // A light with a bright key from the front left, so that turning the head changes its shading.
    lighting::ShRgb light;
    light.order = 4;
    std::vector<double> basis(16);
    lighting::evaluateSh(4, anim::Vec3d{0.6, 0.5, 0.62}, basis);
    for (int c = 0; c < 3; ++c)
        for (int i = 0; i < 16; ++i)
            light[c][std::size_t(i)] = (c == 0 ? 3.0 : 2.4) * basis[std::size_t(i)] + (i == 0 ? 0.5 : 0.0);
    (*node)->setLight(light);
    (*node)->setPose(frame);
    const auto segmentLight = (*node)->segmentLight(skullIndex); // RGB triplets

    lighting::BakeSettings settings;
    settings.order = 4;
    settings.transfer = lighting::TransferKind::DiffuseShadowed;
    settings.raysPerVertex = 1024; // the skull alone: quick even under sanitizers, and noise well below the tolerance
    auto atRest = lighting::bakeTransfer(segmentMesh(mesh, skull, mesh.positions, mesh.normals), settings);
    auto posed = lighting::bakeTransfer(segmentMesh(mesh, skull, (*node)->posedPositions(), (*node)->posedNormals()), settings);
    ASSERT_TRUE(atRest.ok() && posed.ok());

    std::vector<double> rotatedError, unrotatedError;
    for (std::uint32_t v = 0; v < skull.vertexCount; ++v) {
        const auto rest = atRest->vertexTransfer(v), pose = posed->vertexTransfer(v);
        double withRotatedLight = 0, withWorldLight = 0, reference = 0;
        for (std::size_t i = 0; i < 16; ++i) {
            withRotatedLight += rest[i] * segmentLight[3 * i];
            withWorldLight += rest[i] * light[0][i];
            reference += pose[i] * light[0][i];
        }
        if (reference < 0.05)
            continue; // facing away from the key: relative errors of nothing
        rotatedError.push_back(std::abs(withRotatedLight - reference) / reference);
        unrotatedError.push_back(std::abs(withWorldLight - reference) / reference);
    }
    ASSERT_GT(rotatedError.size(), skull.vertexCount / 3);
    auto quantile = [](std::vector<double> values, double q) {
        std::sort(values.begin(), values.end());
        return values[std::size_t(q * double(values.size() - 1))];
    };
    std::printf("skull under a turned head: relative radiance error median %.4f, 90%% %.4f (light not rotated: median %.3f)\n",
                quantile(rotatedError, 0.5), quantile(rotatedError, 0.9), quantile(unrotatedError, 0.5));
    EXPECT_LT(quantile(rotatedError, 0.5), 0.02);
    EXPECT_LT(quantile(rotatedError, 0.9), 0.06);
    EXPECT_GT(quantile(unrotatedError, 0.5), 0.15) << "the pose must matter, or this test proves nothing";
}

} // namespace
