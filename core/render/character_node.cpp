#include "render/character_node.h"

#include <algorithm>
#include <cassert>
#include <cstring>
#include <numbers>
#include <type_traits>

#include <osg/CullFace>
#include <osg/Image>
#include <osg/PrimitiveSet>
#include <osg/Texture2D>

#include "render/shaders.h"

namespace thespis::core::render {

namespace {

static_assert(sizeof(osg::Vec3f) == sizeof(anim::Vec3) && std::is_trivially_copyable_v<osg::Vec3f>,
              "posed vertices are copied into OSG arrays as they are");

// Transfer of a white diffuse surface without shadows (see character_node.h), for a normal
// already expressed in its segment's bind frame; order² floats into `out`.
void unshadowedTransfer(int order, const anim::Vec3d& normal, std::span<float> out)
{
    std::array<double, lighting::kMaxShCoefficients> basis{};
    lighting::evaluateSh(order, normal, basis);
    for (int l = 0; l < order; ++l) {
        const double kernel = lighting::clampedCosineKernel(l) / std::numbers::pi;
        for (int i = l * l; i < (l + 1) * (l + 1); ++i)
            out[std::size_t(i)] = float(kernel * basis[std::size_t(i)]);
    }
}

osg::ref_ptr<osg::Texture2D> makeTexture(const scene::TextureImage& texture)
{
    osg::ref_ptr<osg::Image> image = new osg::Image;
    image->allocateImage(texture.width, texture.height, 1, GL_RGBA, GL_UNSIGNED_BYTE);
    std::memcpy(image->data(), texture.rgba.data(), texture.rgba.size());
    // glTF's first row is v = 0, and so is the first row of a GL texture: no flip.
    osg::ref_ptr<osg::Texture2D> result = new osg::Texture2D(image.get());
    result->setInternalFormat(GL_SRGB8_ALPHA8); // base colour is sRGB-encoded; sampling decodes it
    result->setFilter(osg::Texture::MIN_FILTER, osg::Texture::LINEAR_MIPMAP_LINEAR);
    result->setFilter(osg::Texture::MAG_FILTER, osg::Texture::LINEAR);
    result->setWrap(osg::Texture::WRAP_S, osg::Texture::REPEAT);
    result->setWrap(osg::Texture::WRAP_T, osg::Texture::REPEAT);
    result->setResizeNonPowerOfTwoHint(false);
    return result;
}

} // namespace

Result<std::unique_ptr<CharacterNode>> CharacterNode::create(std::shared_ptr<const scene::Character> character,
                                                             const lighting::TransferBake* bake,
                                                             const CharacterNodeOptions& options)
{
    if (!character)
        return makeError(ErrorCode::InvalidArgument, "No character was given to render.");
    if (auto valid = character->validate(); !valid)
        return valid.error();
    const int order = bake ? bake->order : options.unbakedOrder;
    if (order < 1 || order > shaders::kMaxTransferOrder)
        return makeError(ErrorCode::InvalidArgument,
                         "The lighting of character \"" + character->name + "\" has SH order " + std::to_string(order) +
                             "; the renderer takes orders 1 to " + std::to_string(shaders::kMaxTransferOrder) +
                             " (bake again with a lower order).");
    if (bake)
        if (auto matches = lighting::checkBakeMatchesMesh(*bake, character->mesh); !matches)
            return matches.error();

    std::unique_ptr<CharacterNode> node(new CharacterNode);
    node->m_character = std::move(character);
    node->m_order = order;
    node->m_skinning = options.skinning;
    if (options.workers) {
        node->m_workers = options.workers;
    } else {
        node->m_ownWorkers = std::make_unique<scene::SkinningWorkers>(1);
        node->m_workers = node->m_ownWorkers.get();
    }

    const scene::Character& c = *node->m_character;
    const std::size_t joints = std::size_t(c.skeleton.jointCount());
    node->m_restJointPositions = c.skeleton.worldPositions(c.skeleton.restFrame());
    node->m_jointPositions.resize(joints);
    node->m_jointOrientations.resize(joints);
    node->m_jointTransforms.resize(joints);
    node->m_positions.resize(c.mesh.vertexCount());
    node->m_normals.resize(c.mesh.vertexCount());
    for (std::size_t s = 0; s < c.mesh.segments.size(); ++s)
        node->m_segmentJoints.push_back(c.segmentJoint(s));
    node->m_segmentRotations.resize(c.mesh.segments.size());
    node->m_face = scene::FaceDeformer(c);
    if (!node->m_face.empty()) {
        node->m_frame.resize(c.skeleton.frameLayout()->floatCount());
        node->m_facePositions = c.mesh.positions;
        node->m_faceNormals = c.mesh.normals;
    }
    node->m_worldLight.order = order;
    node->m_segmentLight.order = order;

    node->buildGeometry(bake);
    node->setShading(Shading::Prt);
    node->setPose(c.skeleton.restFrame());
    return node;
}

void CharacterNode::buildGeometry(const lighting::TransferBake* bake)
{
    const scene::Character& c = *m_character;
    const scene::CharacterMesh& mesh = c.mesh;
    const std::size_t vertices = mesh.vertexCount();
    const std::size_t coefficients = std::size_t(m_order) * std::size_t(m_order);

    m_group = new osg::Group;
    m_group->setName(c.name);
    osg::StateSet* groupState = m_group->getOrCreateStateSet();
    groupState->setAttributeAndModes(new osg::CullFace(osg::CullFace::BACK));
    for (Shading shading : {Shading::Prt, Shading::Phong, Shading::Unlit})
        m_programs[std::size_t(shading)] = shaders::characterProgram(shading, m_order);
    m_lightDirection = new osg::Uniform("lightDirection", osg::Vec3f(0, 1, 0));
    m_lightColor = new osg::Uniform("lightColor", osg::Vec3f());
    m_ambientIrradiance = new osg::Uniform("ambientIrradiance", osg::Vec3f());
    for (osg::Uniform* uniform : {m_lightDirection.get(), m_lightColor.get(), m_ambientIrradiance.get()}) {
        uniform->setDataVariance(osg::Object::DYNAMIC);
        groupState->addUniform(uniform);
    }
    // Not selected, for anything drawn under the group without a value of its own.
    groupState->addUniform(new osg::Uniform("selectionHighlight", 0.0f));

    m_vertexArray = new osg::Vec3Array(unsigned(vertices));
    m_normalArray = new osg::Vec3Array(unsigned(vertices));
    for (osg::Vec3Array* array : {m_vertexArray.get(), m_normalArray.get()}) {
        array->setDataVariance(osg::Object::DYNAMIC);
        array->setBinding(osg::Array::BIND_PER_VERTEX);
    }

    // Transfer, order² floats per vertex zero-padded to whole vec4s: the bake's where it has one,
    // the closed-form DU transfer in the segment's bind frame elsewhere.
    const int attributeCount = shaders::transferAttributeCount(m_order);
    std::vector<osg::ref_ptr<osg::Vec4Array>> transfer;
    for (int a = 0; a < attributeCount; ++a)
        transfer.push_back(new osg::Vec4Array(osg::Array::BIND_PER_VERTEX, unsigned(vertices)));
    std::vector<float> padded(std::size_t(attributeCount) * 4);
    auto store = [&](std::size_t vertex) {
        for (int a = 0; a < attributeCount; ++a)
            (*transfer[std::size_t(a)])[unsigned(vertex)].set(padded[4 * std::size_t(a)], padded[4 * std::size_t(a) + 1],
                                                              padded[4 * std::size_t(a) + 2], padded[4 * std::size_t(a) + 3]);
    };
    std::vector<bool> baked(vertices, false);
    if (bake)
        for (const lighting::BakedSegment& segment : bake->segments) {
            if (!segment.baked)
                continue;
            for (std::uint32_t k = 0; k < segment.vertexCount; ++k) {
                const float* t = bake->transfer.data() + segment.transferOffset + std::size_t(k) * coefficients;
                std::copy(t, t + coefficients, padded.begin());
                store(segment.firstVertex + k);
                baked[segment.firstVertex + k] = true;
            }
        }
    for (const scene::Segment& segment : mesh.segments)
        for (std::uint32_t v = segment.firstVertex; v < segment.firstVertex + segment.vertexCount; ++v) {
            if (baked[v])
                continue;
            const anim::Vec3& n = mesh.normals[v];
            unshadowedTransfer(m_order, anim::rotate(anim::conjugate(segment.bindRotation), anim::Vec3d{n.x, n.y, n.z}),
                               padded);
            store(v);
        }

    osg::ref_ptr<osg::Vec2Array> texcoords;
    if (!c.texcoords.empty()) {
        texcoords = new osg::Vec2Array(osg::Array::BIND_PER_VERTEX, unsigned(vertices));
        for (std::size_t v = 0; v < vertices; ++v)
            (*texcoords)[unsigned(v)].set(c.texcoords[v][0], c.texcoords[v][1]);
    }
    std::vector<osg::ref_ptr<osg::Texture2D>> textures(c.textures.size());

    for (std::size_t s = 0; s < mesh.segments.size(); ++s) {
        const scene::Segment& segment = mesh.segments[s];
        osg::ref_ptr<osg::Geometry> geometry = new osg::Geometry;
        geometry->setName(segment.name);
        geometry->setDataVariance(osg::Object::DYNAMIC);
        geometry->setUseDisplayList(false);
        geometry->setUseVertexBufferObjects(true);
        geometry->setVertexArray(m_vertexArray.get());
        geometry->setNormalArray(m_normalArray.get());
        if (texcoords)
            geometry->setVertexAttribArray(shaders::kTexcoordLocation, texcoords.get());
        for (int a = 0; a < attributeCount; ++a)
            geometry->setVertexAttribArray(shaders::kFirstTransferLocation + unsigned(a), transfer[std::size_t(a)].get());
        const auto first = mesh.indices.begin() + std::ptrdiff_t(segment.firstTriangle) * 3;
        geometry->addPrimitiveSet(
            new osg::DrawElementsUInt(GL_TRIANGLES, first, first + std::ptrdiff_t(segment.triangleCount) * 3));

        osg::StateSet* state = geometry->getOrCreateStateSet();
        osg::ref_ptr<osg::Uniform> light = new osg::Uniform(osg::Uniform::FLOAT_VEC3, "shLight", int(coefficients));
        light->setDataVariance(osg::Object::DYNAMIC);
        state->addUniform(light.get());
        m_lightUniforms.push_back(light);
        // Every segment holds its own value: GL would keep the last segment's otherwise.
        osg::ref_ptr<osg::Uniform> highlight = new osg::Uniform("selectionHighlight", 0.0f);
        highlight->setDataVariance(osg::Object::DYNAMIC);
        state->addUniform(highlight.get());
        m_highlightUniforms.push_back(highlight);

        const int materialIndex = c.segmentMaterials.empty() ? -1 : c.segmentMaterials[s];
        const scene::Material material = materialIndex >= 0 ? c.materials[std::size_t(materialIndex)] : scene::Material{};
        state->addUniform(new osg::Uniform("baseColor", osg::Vec4f(material.baseColor[0], material.baseColor[1],
                                                                   material.baseColor[2], material.baseColor[3])));
        const bool textured = texcoords && material.baseColorTexture >= 0;
        state->addUniform(new osg::Uniform("textureWeight", textured ? 1.0f : 0.0f));
        if (textured) {
            osg::ref_ptr<osg::Texture2D>& texture = textures[std::size_t(material.baseColorTexture)];
            if (!texture)
                texture = makeTexture(c.textures[std::size_t(material.baseColorTexture)]);
            state->setTextureAttributeAndModes(0, texture.get());
            state->addUniform(new osg::Uniform("baseColorTexture", 0));
        }
        m_group->addChild(geometry.get());
        m_geometries.push_back(geometry);
    }
    m_highlighted.assign(mesh.segments.size(), 0);
}

void CharacterNode::setShading(Shading shading)
{
    m_shading = shading;
    m_group->getOrCreateStateSet()->setAttributeAndModes(m_programs[std::size_t(shading)].get());
}

void CharacterNode::setLight(const lighting::ShRgb& worldLight)
{
    const int shared = std::min(worldLight.order, m_order);
    for (int c = 0; c < 3; ++c) {
        std::fill(m_worldLight.channel[c].begin(), m_worldLight.channel[c].end(), 0.0);
        std::copy_n(worldLight.channel[c].begin(), shared * shared, m_worldLight.channel[c].begin());
    }
    const DirectionalLight phong = dominantLight(worldLight);
    m_lightDirection->set(osg::Vec3f(float(phong.direction.x), float(phong.direction.y), float(phong.direction.z)));
    m_lightColor->set(osg::Vec3f(float(phong.color[0]), float(phong.color[1]), float(phong.color[2])));
    m_ambientIrradiance->set(osg::Vec3f(float(phong.ambientIrradiance[0]), float(phong.ambientIrradiance[1]),
                                        float(phong.ambientIrradiance[2])));
    updateSegmentLights();
}

void CharacterNode::setPose(std::span<const float> frame, std::span<const float> face)
{
    const scene::Character& c = *m_character;
    assert(frame.size() == c.skeleton.frameLayout()->floatCount());
    if (!m_face.empty()) {
        std::copy(frame.begin(), frame.end(), m_frame.begin());
        m_face.turnJoints(face, m_frame);
        frame = m_frame;
        m_face.deform(face, m_facePositions, m_faceNormals);
    }
    scene::computeSkinningTransforms(c.skeleton, frame, m_restJointPositions, m_jointPositions, m_jointOrientations,
                                     m_jointTransforms);
    m_workers->skin(c, m_jointTransforms, m_skinning, m_positions, m_normals, m_facePositions, m_faceNormals);
    ++m_poseCount;

    std::memcpy(static_cast<void*>(&m_vertexArray->front()), m_positions.data(), m_positions.size() * sizeof(anim::Vec3));
    std::memcpy(static_cast<void*>(&m_normalArray->front()), m_normals.data(), m_normals.size() * sizeof(anim::Vec3));
    m_vertexArray->dirty();
    m_normalArray->dirty();
    for (const osg::ref_ptr<osg::Geometry>& geometry : m_geometries)
        geometry->dirtyBound();

    for (std::size_t s = 0; s < m_segmentRotations.size(); ++s) {
        const anim::Quat& joint = m_jointTransforms[std::size_t(m_segmentJoints[s])].rotation;
        m_segmentRotations[s] =
            anim::normalize(anim::Quatd{joint.x, joint.y, joint.z, joint.w} * c.mesh.segments[s].bindRotation);
    }
    updateSegmentLights();
}

void CharacterNode::updateSegmentLights()
{
    const std::size_t coefficients = std::size_t(m_order) * std::size_t(m_order);
    for (std::size_t s = 0; s < m_lightUniforms.size(); ++s) {
        m_rotation.build(m_order, lighting::rotationMatrix(anim::conjugate(m_segmentRotations[s])));
        m_rotation.applyRgb(m_worldLight, m_segmentLight);
        osg::FloatArray& values = *m_lightUniforms[s]->getFloatArray();
        for (std::size_t i = 0; i < coefficients; ++i)
            for (int c = 0; c < 3; ++c)
                values[unsigned(3 * i + std::size_t(c))] = float(m_segmentLight.channel[c][i]);
        m_lightUniforms[s]->dirty();
    }
}

Bounds CharacterNode::bounds() const
{
    Bounds result;
    for (const anim::Vec3& p : m_positions)
        result.add(anim::Vec3d{p.x, p.y, p.z});
    return result;
}

void CharacterNode::setSegmentHighlighted(std::size_t segment, bool highlighted)
{
    assert(segment < m_highlightUniforms.size());
    m_highlighted[segment] = highlighted ? 1 : 0;
    m_highlightUniforms[segment]->set(highlighted ? 1.0f : 0.0f);
}

std::span<const float> CharacterNode::segmentLight(std::size_t segment) const
{
    const osg::FloatArray& values = *m_lightUniforms[segment]->getFloatArray();
    return {&values.front(), values.size()};
}

} // namespace thespis::core::render
