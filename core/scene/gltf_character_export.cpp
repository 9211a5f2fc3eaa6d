#include "scene/gltf_character_export.h"

#include <algorithm>
#include <cstdint>
#include <map>

#include "scene/gltf_writing.h"

namespace thespis::core::scene {

namespace {

// glTF carries 4 influences per JOINTS_n / WEIGHTS_n pair.
constexpr int kInfluencesPerSet = 4;

/// Per vertex, `sets` × 4 joint indices and weights: the skin's (padded with weight 0 on joint 0),
/// or weight 1 on the segment's joint for a rigid mesh.
void vertexInfluences(const Character& character, int sets, std::vector<std::uint16_t>& joints,
                      std::vector<float>& weights)
{
    const std::size_t vertices = character.mesh.vertexCount();
    const std::size_t slots = std::size_t(sets * kInfluencesPerSet);
    joints.assign(vertices * slots, 0);
    weights.assign(vertices * slots, 0.0f);
    if (character.skin.empty()) {
        for (std::size_t s = 0; s < character.mesh.segments.size(); ++s) {
            const Segment& segment = character.mesh.segments[s];
            for (std::uint32_t v = segment.firstVertex; v < segment.firstVertex + segment.vertexCount; ++v) {
                joints[v * slots] = std::uint16_t(character.segmentJoint(s));
                weights[v * slots] = 1.0f;
            }
        }
        return;
    }
    const auto influences = std::size_t(character.skin.influences);
    for (std::size_t v = 0; v < vertices; ++v)
        for (std::size_t i = 0; i < influences; ++i) {
            const float weight = character.skin.weights[v * influences + i];
            if (weight <= 0)
                continue; // an unused slot names joint 0, as the validator wants
            joints[v * slots + i] = character.skin.joints[v * influences + i];
            weights[v * slots + i] = weight;
        }
}

/// Set `set` (4 slots) of every vertex out of the interleaved per-vertex slots.
template <class T> std::vector<T> slotSet(const std::vector<T>& all, int sets, int set)
{
    const std::size_t slots = std::size_t(sets * kInfluencesPerSet);
    std::vector<T> out;
    out.reserve(all.size() / std::size_t(sets));
    for (std::size_t v = 0; v < all.size() / slots; ++v)
        for (int i = 0; i < kInfluencesPerSet; ++i)
            out.push_back(all[v * slots + std::size_t(set * kInfluencesPerSet + i)]);
    return out;
}

/// The mesh node, its mesh (a primitive per material in use) and its skin.
void addSkinnedMesh(tinygltf::Model& out, const Character& character, const std::vector<anim::Vec3d>& rest,
                    GltfCharacterResult& result)
{
    const CharacterMesh& mesh = character.mesh;
    std::vector<float> positions, normals, texcoords;
    for (std::size_t v = 0; v < mesh.vertexCount(); ++v) {
        positions.insert(positions.end(), {float(mesh.positions[v].x), float(mesh.positions[v].y), float(mesh.positions[v].z)});
        normals.insert(normals.end(), {float(mesh.normals[v].x), float(mesh.normals[v].y), float(mesh.normals[v].z)});
        if (!character.texcoords.empty())
            texcoords.insert(texcoords.end(), {character.texcoords[v][0], character.texcoords[v][1]});
    }
    const int skinSets = std::max(1, (character.skin.influences + kInfluencesPerSet - 1) / kInfluencesPerSet);
    std::vector<std::uint16_t> joints;
    std::vector<float> weights;
    vertexInfluences(character, skinSets, joints, weights);

    std::map<std::string, int> attributes;
    attributes["POSITION"] = gltf::addAccessor(out, positions, TINYGLTF_TYPE_VEC3, 3, true, TINYGLTF_TARGET_ARRAY_BUFFER);
    attributes["NORMAL"] = gltf::addAccessor(out, normals, TINYGLTF_TYPE_VEC3, 3, false, TINYGLTF_TARGET_ARRAY_BUFFER);
    if (!texcoords.empty())
        attributes["TEXCOORD_0"] = gltf::addAccessor(out, texcoords, TINYGLTF_TYPE_VEC2, 2, false, TINYGLTF_TARGET_ARRAY_BUFFER);
    for (int set = 0; set < skinSets; ++set) {
        const std::vector<std::uint16_t> indices = slotSet(joints, skinSets, set);
        attributes["JOINTS_" + std::to_string(set)] =
            gltf::addIntegerAccessor(out, indices.data(), indices.size() * sizeof(std::uint16_t),
                                     TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT, TINYGLTF_TYPE_VEC4, indices.size() / 4,
                                     TINYGLTF_TARGET_ARRAY_BUFFER);
        attributes["WEIGHTS_" + std::to_string(set)] =
            gltf::addAccessor(out, slotSet(weights, skinSets, set), TINYGLTF_TYPE_VEC4, 4, false, TINYGLTF_TARGET_ARRAY_BUFFER);
    }

    // Materials as the renderer shades them: a diffuse base colour.
    for (const Material& material : character.materials) {
        tinygltf::Material m;
        m.name = material.name;
        m.pbrMetallicRoughness.baseColorFactor.assign(material.baseColor.begin(), material.baseColor.end());
        m.pbrMetallicRoughness.metallicFactor = 0;
        m.pbrMetallicRoughness.roughnessFactor = 1;
        out.materials.push_back(std::move(m));
        if (material.baseColorTexture >= 0 && result.warnings.empty())
            result.warnings.push_back("Textures are not written yet: the materials keep their base colours only.");
    }
    tinygltf::Mesh gltfMesh;
    gltfMesh.name = character.name;
    const int materialCount = std::max<int>(1, int(character.materials.size()));
    for (int material = 0; material < materialCount; ++material) {
        std::vector<std::uint32_t> indices;
        for (std::size_t s = 0; s < mesh.segments.size(); ++s) {
            const int own = character.segmentMaterials.empty() ? 0 : character.segmentMaterials[s];
            if (own != material)
                continue;
            const Segment& segment = mesh.segments[s];
            indices.insert(indices.end(), mesh.indices.begin() + std::ptrdiff_t(segment.firstTriangle) * 3,
                           mesh.indices.begin() + std::ptrdiff_t(segment.firstTriangle + segment.triangleCount) * 3);
        }
        if (indices.empty())
            continue;
        tinygltf::Primitive primitive;
        primitive.attributes = attributes;
        primitive.indices = gltf::addIntegerAccessor(out, indices.data(), indices.size() * sizeof(std::uint32_t),
                                                     TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT, TINYGLTF_TYPE_SCALAR,
                                                     indices.size(), TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER);
        primitive.material = character.materials.empty() ? -1 : material;
        primitive.mode = TINYGLTF_MODE_TRIANGLES;
        gltfMesh.primitives.push_back(std::move(primitive));
    }
    result.primitives = gltfMesh.primitives.size();
    out.meshes.push_back(std::move(gltfMesh));

    // The skin: every joint node, each bound where it stands at rest (no rest rotation).
    tinygltf::Skin skin;
    skin.name = character.name;
    skin.skeleton = 0;
    std::vector<float> inverseBind;
    for (int j = 0; j < character.skeleton.jointCount(); ++j) {
        skin.joints.push_back(j);
        const anim::Vec3d& p = rest[std::size_t(j)];
        inverseBind.insert(inverseBind.end(), {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, float(-p.x), float(-p.y), float(-p.z), 1});
    }
    skin.inverseBindMatrices = gltf::addAccessor(out, inverseBind, TINYGLTF_TYPE_MAT4, 16, false);
    out.skins.push_back(std::move(skin));

    tinygltf::Node node;
    node.name = character.name.empty() ? "body" : character.name + " body";
    node.mesh = 0;
    node.skin = 0;
    out.nodes.push_back(std::move(node));
    out.scenes[0].nodes.push_back(int(out.nodes.size()) - 1);
}

} // namespace

Result<GltfCharacterResult> writeGltfCharacter(const std::filesystem::path& output, const Character& character,
                                               const GltfMotion& motion, bool animationOnly)
{
    if (output.extension() != ".glb")
        return makeError(ErrorCode::InvalidArgument, output.string() + ": a glTF character is written as a .glb file");
    if (auto valid = character.validate(); !valid)
        return valid.error();
    const anim::Skeleton& skeleton = character.skeleton;
    const std::size_t floats = skeleton.frameLayout()->floatCount();
    if (!(motion.fps > 0) || motion.bodyFrames.empty() || motion.bodyFrames.size() % floats != 0)
        return makeError(ErrorCode::InvalidArgument, "The motion to write has no whole frames of its skeleton at a positive rate");
    const std::size_t frameCount = motion.bodyFrames.size() / floats;

    tinygltf::Model out;
    out.asset.version = "2.0";
    out.asset.generator = "Thespis Studio (bake-motion)";
    out.buffers.emplace_back();
    out.scenes.emplace_back();
    out.scenes[0].name = character.name;
    out.defaultScene = 0;

    // Joint nodes, in the skeleton's order (parents first), at their rest offsets.
    const int jointCount = skeleton.jointCount();
    for (int j = 0; j < jointCount; ++j) {
        tinygltf::Node node;
        node.name = skeleton.joint(j).name;
        const anim::Vec3d& offset = skeleton.joint(j).offset;
        node.translation = {offset.x, offset.y, offset.z};
        out.nodes.push_back(std::move(node));
        const int parent = skeleton.joint(j).parent;
        if (parent >= 0)
            out.nodes[std::size_t(parent)].children.push_back(j);
        else
            out.scenes[0].nodes.push_back(j);
    }
    GltfCharacterResult result;
    result.nodes = std::size_t(jointCount);
    if (!animationOnly)
        addSkinnedMesh(out, character, skeleton.worldPositions(skeleton.restFrame()), result);

    // The motion: each joint's rotation in its parent (identity at rest, so the node's rotation),
    // and the translating joints' translations.
    tinygltf::Animation animation;
    animation.name = motion.name;
    const int timeAccessor = gltf::addFrameTimes(out, frameCount, motion.fps);
    for (int j = 0; j < jointCount; ++j) {
        std::vector<float> rotations, translations;
        const int element = skeleton.translationElement(j);
        for (std::size_t f = 0; f < frameCount; ++f) {
            const std::span<const float> frame = motion.bodyFrames.subspan(f * floats, floats);
            const anim::Quat q = anim::rotationAt(frame, j);
            gltf::appendRotation(rotations, anim::normalize(anim::Quatd{q.x, q.y, q.z, q.w}));
            if (element >= 0) {
                const float* t = frame.data() + skeleton.frameLayout()->floatOffset(element);
                translations.insert(translations.end(), {t[0], t[1], t[2]});
            }
        }
        gltf::addChannel(out, animation, timeAccessor, j, "rotation", rotations, TINYGLTF_TYPE_VEC4, 4);
        if (element >= 0)
            gltf::addChannel(out, animation, timeAccessor, j, "translation", translations, TINYGLTF_TYPE_VEC3, 3);
    }
    out.animations.push_back(std::move(animation));
    if (auto written = gltf::writeGlb(out, output); !written)
        return written.error();
    return result;
}

} // namespace thespis::core::scene
