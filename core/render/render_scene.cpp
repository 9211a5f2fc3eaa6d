#include "render/render_scene.h"

#include <cmath>
#include <numbers>

#include <osg/Depth>
#include <osg/Geometry>
#include <osg/Image>
#include <osg/Texture2D>

#include "render/shaders.h"
#include "util/quadrature.h"

namespace thespis::core::render {

namespace {

constexpr float kGroundRadius = 10.0f;
constexpr double kGroundAlbedo = 0.5;

osg::ref_ptr<osg::Geometry> makeGround(osg::Uniform* groundColor)
{
    constexpr int sides = 96;
    osg::ref_ptr<osg::Vec3Array> vertices = new osg::Vec3Array;
    osg::ref_ptr<osg::Vec3Array> normals = new osg::Vec3Array(osg::Array::BIND_OVERALL);
    vertices->push_back(osg::Vec3f(0, 0, 0));
    for (int k = 0; k <= sides; ++k) {
        const double angle = 2 * std::numbers::pi * k / sides;
        vertices->push_back(osg::Vec3f(kGroundRadius * float(std::cos(angle)), 0, -kGroundRadius * float(std::sin(angle))));
    }
    normals->push_back(osg::Vec3f(0, 1, 0));
    osg::ref_ptr<osg::Geometry> ground = new osg::Geometry;
    ground->setName("ground");
    ground->setUseDisplayList(false);
    ground->setUseVertexBufferObjects(true);
    ground->setVertexArray(vertices.get());
    ground->setNormalArray(normals.get());
    ground->addPrimitiveSet(new osg::DrawArrays(GL_TRIANGLE_FAN, 0, GLsizei(vertices->size())));
    osg::StateSet* state = ground->getOrCreateStateSet();
    state->setAttributeAndModes(shaders::groundProgram().get());
    state->addUniform(groundColor);
    return ground;
}

osg::ref_ptr<osg::Geometry> makeBackground(const lighting::LightProbe& probe, int width, double degrees, double intensity)
{
    // The light from world direction d was the probe's from d turned back.
    const double half = -degrees * std::numbers::pi / 360.0;
    const anim::Quatd back{0.0, std::sin(half), 0.0, std::cos(half)};
    // Resample to lat-long once, so the shader has a single mapping whatever the probe's layout.
    const int height = std::max(width / 2, 1);
    osg::ref_ptr<osg::Image> image = new osg::Image;
    image->allocateImage(width, height, 1, GL_RGB, GL_FLOAT);
    image->setInternalTextureFormat(GL_RGB32F_ARB);
    float* pixels = reinterpret_cast<float*>(image->data());
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            anim::Vec3d direction;
            lighting::directionOfPixel(lighting::ProbeLayout::LatLong, width, height, x, y, direction);
            const std::array<float, 3> radiance = probe.radiance(anim::rotate(back, direction));
            float* pixel = pixels + 3 * (std::size_t(y) * std::size_t(width) + std::size_t(x));
            for (int c = 0; c < 3; ++c)
                pixel[c] = float(radiance[std::size_t(c)] * intensity);
        }
    osg::ref_ptr<osg::Texture2D> texture = new osg::Texture2D(image.get());
    texture->setFilter(osg::Texture::MIN_FILTER, osg::Texture::LINEAR);
    texture->setFilter(osg::Texture::MAG_FILTER, osg::Texture::LINEAR);
    texture->setWrap(osg::Texture::WRAP_S, osg::Texture::REPEAT);
    texture->setWrap(osg::Texture::WRAP_T, osg::Texture::CLAMP_TO_EDGE);
    texture->setResizeNonPowerOfTwoHint(false);

    osg::ref_ptr<osg::Vec3Array> corners = new osg::Vec3Array;
    for (const osg::Vec3f corner : {osg::Vec3f(-1, -1, 0), osg::Vec3f(1, -1, 0), osg::Vec3f(-1, 1, 0), osg::Vec3f(1, 1, 0)})
        corners->push_back(corner);
    osg::ref_ptr<osg::Geometry> background = new osg::Geometry;
    background->setName("background");
    background->setUseDisplayList(false);
    background->setUseVertexBufferObjects(true);
    background->setVertexArray(corners.get());
    background->addPrimitiveSet(new osg::DrawArrays(GL_TRIANGLE_STRIP, 0, 4));
    background->setCullingActive(false); // its vertices are in clip space, not in the world
    osg::StateSet* state = background->getOrCreateStateSet();
    state->setAttributeAndModes(shaders::backgroundProgram().get());
    state->setTextureAttributeAndModes(0, texture.get());
    state->addUniform(new osg::Uniform("probeTexture", 0));
    // Drawn after the opaque geometry at the far plane: only the pixels nothing covered.
    state->setAttributeAndModes(new osg::Depth(osg::Depth::LEQUAL, 0.0, 1.0, false));
    state->setRenderBinDetails(10, "RenderBin");
    return background;
}

lighting::ShRgb makeDefaultLight()
{
    using anim::Vec3d;
    constexpr int order = shaders::kMaxTransferOrder;
    const Vec3d key = [] {
        const Vec3d d{-0.5, 0.75, 0.6};
        return d * (1 / std::sqrt(d.x * d.x + d.y * d.y + d.z * d.z));
    }();
    auto radiance = [&](const Vec3d& d) {
        const std::array<double, 3> zenith{0.22, 0.32, 0.55}, horizon{0.55, 0.60, 0.65}, ground{0.10, 0.09, 0.08};
        std::array<double, 3> sky{};
        for (int c = 0; c < 3; ++c)
            sky[c] = d.y > 0 ? horizon[c] + (zenith[c] - horizon[c]) * d.y : ground[c];
        const double lobe = 16 * std::pow(std::max(0.0, d.x * key.x + d.y * key.y + d.z * key.z), 24);
        const std::array<double, 3> warm{1.0, 0.85, 0.68};
        for (int c = 0; c < 3; ++c)
            sky[c] += lobe * warm[c];
        return sky;
    };
    // Gauss–Legendre in cos θ times a uniform rule in φ: exact for the band-limited part.
    const GaussLegendreRule rule = gaussLegendre(64);
    constexpr int azimuths = 128;
    lighting::ShRgb light;
    light.order = order;
    std::array<double, lighting::kMaxShCoefficients> scratch{};
    for (std::size_t i = 0; i < rule.x.size(); ++i) {
        const double z = rule.x[i], s = std::sqrt(std::max(0.0, 1 - z * z));
        for (int k = 0; k < azimuths; ++k) {
            const double phi = 2 * std::numbers::pi * (k + 0.5) / azimuths;
            const Vec3d d{s * std::cos(phi), z, s * std::sin(phi)}; // y up as the polar axis
            const double weight = rule.w[i] * 2 * std::numbers::pi / azimuths;
            const std::array<double, 3> value = radiance(d);
            for (int c = 0; c < 3; ++c)
                lighting::accumulateShProjection(order, d, weight * value[c], light[c], scratch);
        }
    }
    return light;
}

} // namespace

RenderScene::RenderScene(int skinningThreads)
    : m_workers(std::make_unique<scene::SkinningWorkers>(skinningThreads)), m_light(defaultLight())
{
    m_root = new osg::Group;
    m_root->setName("thespis-scene");
    m_exposure = new osg::Uniform("exposure", 1.0f);
    m_root->getOrCreateStateSet()->addUniform(m_exposure.get());
    m_characterGroup = new osg::Group;
    m_characterGroup->setName("characters");
    m_root->addChild(m_characterGroup.get());
    m_groundColor = new osg::Uniform("groundColor", osg::Vec3f());
    m_ground = makeGround(m_groundColor.get());
    updateGroundColor();
}

RenderScene::~RenderScene() = default;

Result<CharacterNode*> RenderScene::addCharacter(std::shared_ptr<const scene::Character> character,
                                                 const lighting::TransferBake* bake, scene::SkinningMethod skinning)
{
    CharacterNodeOptions options;
    options.skinning = skinning;
    options.workers = m_workers.get();
    auto node = CharacterNode::create(std::move(character), bake, options);
    if (!node)
        return node.error();
    CharacterNode* added = node->get();
    added->setShading(m_shading);
    added->setLight(m_light);
    m_characterGroup->addChild(added->node());
    m_characters.push_back(std::move(*node));
    return added;
}

void RenderScene::clearCharacters()
{
    m_characterGroup->removeChildren(0, m_characterGroup->getNumChildren());
    m_characters.clear();
}

Bounds RenderScene::characterBounds() const
{
    Bounds bounds;
    for (const auto& character : m_characters)
        bounds.add(character->bounds());
    return bounds;
}

void RenderScene::setShading(Shading shading)
{
    m_shading = shading;
    for (const auto& character : m_characters)
        character->setShading(shading);
}

void RenderScene::setLight(const lighting::ShRgb& light)
{
    m_light = light;
    for (const auto& character : m_characters)
        character->setLight(light);
    updateGroundColor();
}

const lighting::ShRgb& RenderScene::defaultLight()
{
    static const lighting::ShRgb light = makeDefaultLight();
    return light;
}

void RenderScene::setExposure(float exposure) { m_exposure->set(exposure); }

void RenderScene::setGroundVisible(bool visible)
{
    if (visible && !groundVisible())
        m_root->addChild(m_ground.get());
    else if (!visible)
        m_root->removeChild(m_ground.get());
}

bool RenderScene::groundVisible() const { return m_root->containsNode(m_ground.get()); }

void RenderScene::setBackgroundProbe(const lighting::LightProbe& probe, int width, double degrees, double intensity)
{
    clearBackgroundProbe();
    m_background = makeBackground(probe, std::max(width, 2), degrees, intensity);
    m_root->addChild(m_background.get());
}

void RenderScene::clearBackgroundProbe()
{
    if (m_background)
        m_root->removeChild(m_background.get());
    m_background = nullptr;
}

bool RenderScene::hasBackgroundProbe() const { return m_background.valid(); }

void RenderScene::updateGroundColor()
{
    const std::array<double, 3> up = irradiance(m_light, anim::Vec3d{0, 1, 0});
    const double scale = kGroundAlbedo / std::numbers::pi;
    m_groundColor->set(osg::Vec3f(float(scale * up[0]), float(scale * up[1]), float(scale * up[2])));
}

} // namespace thespis::core::render
