// PRT on the built-in humanoid (issue 4 §3): DS and DSM shadowing where bodies occlude
// themselves, and paper Fig. 14 — hair lying close over the skull darkens the skull with DSM
// unless the hair is tagged receiver.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "lighting/transfer_bake.h"
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
    ASSERT_TRUE(scene::applySegmentTags(body.mesh, {{"hair", scene::SegmentRole::Receiver, std::nullopt}}).ok());
    const auto tagged = bake(body.mesh, lighting::TransferKind::DiffuseShadowedMerged);

    const auto band = skullNextToHair(body.mesh);
    const std::size_t darkUntagged = darkened(band, untagged, du);
    const std::size_t darkTagged = darkened(band, tagged, du);
    std::printf("skull next to the hair: %zu vertices, darkened %zu with untagged hair, %zu with hair tagged receiver\n",
                band.size(), darkUntagged, darkTagged);
    EXPECT_GT(darkUntagged, band.size() / 2);
    EXPECT_LT(darkTagged, darkUntagged / 10);
}

} // namespace
