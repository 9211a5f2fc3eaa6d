#include "render/ar_compositor.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <osg/ColorMask>
#include <osg/Depth>
#include <osg/Geometry>
#include <osg/MatrixTransform>
#include <osg/Texture2D>

#include "lighting/sh_rotation.h"
#include "render/ar_view.h"
#include "render/shaders.h"
#include "scene/gltf_mesh.h"

namespace thespis::core::render {

namespace {

// Draw order: phantoms fill the depth buffer first, then the shadow catcher, then the characters.
constexpr int OccluderBin = -2, ShadowBin = -1;
// Characters become spheres by gathering their posed vertices in cubes this wide (metres).
constexpr double ShadowCellSize = 0.16;
constexpr int ShadowCellMinimumVertices = 6;
constexpr std::size_t ShadowGridSlots = 4096; // a power of two
constexpr int MaxShadowSpheres = 64;
// The shadow's texture: texels over a square reaching this far beyond the characters' footprint
// (metres), where a standing person's shadow has faded to a few per cent.
constexpr int ShadowTexels = 48;
constexpr double ShadowReach = 1.5;

osg::ref_ptr<osg::Geometry> triangles(const std::vector<osg::Vec3f>& vertices, const std::vector<unsigned>& indices)
{
    osg::ref_ptr<osg::Geometry> geometry = new osg::Geometry;
    geometry->setUseDisplayList(false);
    geometry->setUseVertexBufferObjects(true);
    geometry->setVertexArray(new osg::Vec3Array(vertices.begin(), vertices.end()));
    geometry->addPrimitiveSet(new osg::DrawElementsUInt(GL_TRIANGLES, indices.begin(), indices.end()));
    return geometry;
}

// A unit box standing on y = 0 (x and z from −½ to ½, y from 0 to 1).
osg::ref_ptr<osg::Geometry> unitBox()
{
    std::vector<osg::Vec3f> v;
    for (int i = 0; i < 8; ++i)
        v.emplace_back(i & 1 ? 0.5f : -0.5f, i & 2 ? 1.0f : 0.0f, i & 4 ? 0.5f : -0.5f);
    const std::vector<unsigned> faces = {0, 1, 3, 0, 3, 2, 4, 6, 7, 4, 7, 5, 0, 4, 5, 0, 5, 1,
                                         2, 3, 7, 2, 7, 6, 0, 2, 6, 0, 6, 4, 1, 5, 7, 1, 7, 3};
    return triangles(v, faces);
}

// A unit upright plane: x from −½ to ½, y from 0 to 1, at z = 0.
osg::ref_ptr<osg::Geometry> unitPlane()
{
    return triangles({{-0.5f, 0, 0}, {0.5f, 0, 0}, {0.5f, 1, 0}, {-0.5f, 1, 0}}, {0, 1, 2, 0, 2, 3});
}

osg::ref_ptr<osg::Node> makeShadowCatcher(osg::Texture2D* texture, osg::Uniform* area, float strength)
{
    osg::ref_ptr<osg::Geometry> ground = triangles({{-1, 0, -1}, {1, 0, -1}, {1, 0, 1}, {-1, 0, 1}}, {0, 2, 1, 0, 3, 2});
    ground->setName("shadow catcher");
    ground->setCullingActive(false); // its vertex shader places it
    osg::StateSet* state = ground->getOrCreateStateSet();
    state->setAttributeAndModes(shaders::shadowCatcherProgram().get());
    state->setTextureAttributeAndModes(0, texture);
    state->addUniform(new osg::Uniform("shadowTexture", 0));
    state->addUniform(area);
    state->addUniform(new osg::Uniform("shadowStrength", strength));
    state->setAttributeAndModes(new osg::Depth(osg::Depth::LESS, 0, 1, false)); // the characters' feet go under it
    state->setRenderBinDetails(ShadowBin, "RenderBin");
    return ground;
}

} // namespace

struct ArCompositor::Cell {
    std::int64_t key = 0;
    double x = 0, y = 0, z = 0;
    int count = 0;
};

ArCompositor::~ArCompositor() = default;

Result<std::unique_ptr<ArCompositor>> ArCompositor::create(const scenario::Scenario& scenario,
                                                           const scenario::Assets& assets,
                                                           const ar::CameraIntrinsics& camera,
                                                           const ar::TargetGeometry& target,
                                                           const ArCompositorSettings& settings)
{
    if (camera.width <= 0 || camera.height <= 0 || camera.fx() <= 0 || camera.fy() <= 0)
        return makeError(ErrorCode::InvalidArgument, "The camera needs a picture size and focal lengths");
    ScenarioSceneOptions options;
    options.skinning = settings.skinning;
    options.stage = settings.stage;
    auto scene = ScenarioScene::create(scenario, assets, options);
    if (!scene)
        return scene.error();
    auto renderer = OffscreenRenderer::create(camera.width, camera.height, settings.samples);
    if (!renderer)
        return renderer.error();
    std::unique_ptr<ArCompositor> self(new ArCompositor);
    self->m_camera = camera;
    self->m_target = target;
    self->m_assets = assets;
    self->m_settings = settings;
    self->m_scene = std::move(scene).value();
    self->m_renderer = std::move(renderer).value();
    RenderScene& render = self->m_scene->scene();
    render.setShading(settings.shading);
    render.setGroundVisible(false);
    render.setTransparentBackground(true);
    self->m_occluders = new osg::Group;
    self->m_occluders->setName("phantom occluders");
    osg::StateSet* state = self->m_occluders->getOrCreateStateSet();
    state->setAttributeAndModes(shaders::depthOnlyProgram().get());
    state->setAttributeAndModes(new osg::ColorMask(false, false, false, false));
    state->setRenderBinDetails(OccluderBin, "RenderBin");
    render.root()->addChild(self->m_occluders.get());
    self->m_shadowImage = new osg::Image;
    self->m_shadowImage->allocateImage(ShadowTexels, ShadowTexels, 1, GL_LUMINANCE, GL_UNSIGNED_BYTE);
    self->m_shadowImage->setDataVariance(osg::Object::DYNAMIC);
    osg::ref_ptr<osg::Texture2D> texture = new osg::Texture2D(self->m_shadowImage.get());
    texture->setFilter(osg::Texture::MIN_FILTER, osg::Texture::LINEAR);
    texture->setFilter(osg::Texture::MAG_FILTER, osg::Texture::LINEAR);
    texture->setWrap(osg::Texture::WRAP_S, osg::Texture::CLAMP_TO_EDGE);
    texture->setWrap(osg::Texture::WRAP_T, osg::Texture::CLAMP_TO_EDGE);
    texture->setResizeNonPowerOfTwoHint(false);
    self->m_shadowArea = new osg::Uniform("shadowArea", osg::Vec3f(0, 0, 1));
    self->m_shadowCatcher = makeShadowCatcher(texture.get(), self->m_shadowArea.get(), settings.shadowStrength);
    render.root()->addChild(self->m_shadowCatcher.get());
    self->m_cells.resize(ShadowGridSlots);
    if (auto placed = self->setPlacement(scenario.ar); !placed)
        return placed.error();
    return self;
}

Result<void> ArCompositor::setPlacement(const scenario::ArSpec& placement)
{
    m_placement = placement;
    m_shadowCatcher->setNodeMask(placement.shadowCatcher ? ~0u : 0u);
    return buildOccluders();
}

Result<void> ArCompositor::buildOccluders()
{
    m_occluders->removeChildren(0, m_occluders->getNumChildren());
    for (const scenario::PhantomOccluder& occluder : m_placement.occluders) {
        osg::ref_ptr<osg::Geometry> shape;
        switch (occluder.shape) {
        case scenario::PhantomOccluder::Shape::Box:
            shape = unitBox();
            break;
        case scenario::PhantomOccluder::Shape::Plane:
            shape = unitPlane();
            break;
        case scenario::PhantomOccluder::Shape::Model: {
            auto mesh = scene::loadGltfMesh(m_assets.path(occluder.model));
            if (!mesh)
                return makeError(mesh.error().code, "Phantom occluder " + occluder.name + " (" + occluder.model +
                                                        "): " + mesh.error().message);
            std::vector<osg::Vec3f> vertices;
            for (const scene::Vec3& p : mesh->positions)
                vertices.emplace_back(p.x, p.y, p.z);
            shape = triangles(vertices, std::vector<unsigned>(mesh->indices.begin(), mesh->indices.end()));
            break;
        }
        }
        shape->setName(occluder.name.empty() ? "phantom" : occluder.name);
        const auto& [x, y, z] = occluder.position;
        const auto& [sx, sy, sz] = occluder.size;
        osg::ref_ptr<osg::MatrixTransform> placed = new osg::MatrixTransform(
            osg::Matrixd::scale(sx, sy, occluder.shape == scenario::PhantomOccluder::Shape::Plane ? 1.0 : sz) *
            osg::Matrixd::rotate(occluder.heading * std::numbers::pi / 180, osg::Vec3d(0, 1, 0)) *
            osg::Matrixd::translate(x, y, z));
        placed->addChild(shape.get());
        m_occluders->addChild(placed.get());
    }
    return {};
}

void ArCompositor::setCameraLight(const lighting::ShRgb& light, const ar::TargetPose& pose)
{
    // A ball's light has the probe layout's directions (lighting/probe.h: towards the camera −z,
    // the picture's up +y, its right −x), which are the camera's (x right, y down, z forward)
    // turned half round z; the world's are those turned back by the world-to-camera rotation B:
    // world = Bᵀ · diag(−1, −1, 1) · probe.
    const std::array<double, 9> b = worldToCameraRotation(pose, m_target, m_placement);
    const lighting::Matrix3d toWorld = {-b[0], -b[3], b[6], -b[1], -b[4], b[7], -b[2], -b[5], b[8]};
    lighting::ShRgb turned;
    lighting::ShRotation(light.order, toWorld).applyRgb(light, turned);
    m_scene->scene().setLight(turned);
}

void ArCompositor::updateShadow()
{
    // Posed vertices gathered in cubes: each cube with enough of them is a sphere at their mean.
    for (Cell& cell : m_cells)
        cell.count = 0;
    const RenderScene& render = m_scene->scene();
    for (std::size_t c = 0; c < render.characterCount(); ++c)
        for (const anim::Vec3& p : render.character(c).posedPositions()) {
            const auto ix = std::int64_t(std::floor(p.x / ShadowCellSize)), iy = std::int64_t(std::floor(p.y / ShadowCellSize)),
                       iz = std::int64_t(std::floor(p.z / ShadowCellSize));
            const std::int64_t key = (ix & 0xFFFFF) | ((iy & 0xFFFFF) << 20) | ((iz & 0xFFFFF) << 40);
            std::size_t slot = std::size_t((std::uint64_t(key) * 0x9E3779B97F4A7C15ull) >> 52) & (ShadowGridSlots - 1);
            for (std::size_t probe = 0; probe < ShadowGridSlots; ++probe, slot = (slot + 1) & (ShadowGridSlots - 1)) {
                Cell& cell = m_cells[slot];
                if (cell.count == 0) {
                    cell = {key, p.x, p.y, p.z, 1};
                    break;
                }
                if (cell.key == key) {
                    cell.x += p.x, cell.y += p.y, cell.z += p.z, ++cell.count;
                    break;
                }
            }
        }
    // The fullest cubes first, as many as are worth it.
    std::partial_sort(m_cells.begin(), m_cells.begin() + MaxShadowSpheres, m_cells.end(),
                      [](const Cell& a, const Cell& b) { return a.count > b.count; });
    m_sphereCount = 0;
    double minX = 1e300, maxX = -1e300, minZ = 1e300, maxZ = -1e300;
    for (int i = 0; i < MaxShadowSpheres; ++i) {
        Cell& cell = m_cells[std::size_t(i)];
        if (cell.count < ShadowCellMinimumVertices)
            break;
        cell.x /= cell.count, cell.y /= cell.count, cell.z /= cell.count; // the sphere's centre
        minX = std::min(minX, cell.x), maxX = std::max(maxX, cell.x);
        minZ = std::min(minZ, cell.z), maxZ = std::max(maxZ, cell.z);
        ++m_sphereCount;
    }
    std::uint8_t* texels = m_shadowImage->data();
    if (m_sphereCount == 0) {
        std::fill(texels, texels + ShadowTexels * ShadowTexels, std::uint8_t(0));
        m_shadowImage->dirty();
        return;
    }
    // The ground under the spheres, and the reach of their shadow around it. A sphere of radius r
    // at distance d above a point, at angle θ from the ground's normal, hides the fraction
    // (r/d)²·cos θ of the cosine-weighted sky: ambient occlusion of sphere proxies, soft and
    // moving with the motion. Towards the square's edge the shadow fades out, so it has no border.
    const double centreX = 0.5 * (minX + maxX), centreZ = 0.5 * (minZ + maxZ);
    const double half = 0.5 * std::max(maxX - minX, maxZ - minZ) + ShadowReach;
    const double radius2 = (0.55 * ShadowCellSize) * (0.55 * ShadowCellSize);
    for (int row = 0; row < ShadowTexels; ++row)
        for (int column = 0; column < ShadowTexels; ++column) {
            const double u = (column + 0.5) / ShadowTexels * 2 - 1, v = (row + 0.5) / ShadowTexels * 2 - 1;
            const double x = centreX + u * half, z = centreZ + v * half;
            double visible = 1;
            for (int i = 0; i < m_sphereCount; ++i) {
                const Cell& s = m_cells[std::size_t(i)];
                const double dx = s.x - x, dy = s.y, dz = s.z - z;
                const double d2 = std::max(dx * dx + dy * dy + dz * dz, radius2);
                const double cosine = std::max(dy, 0.0) / std::sqrt(d2);
                visible *= 1 - std::min(1.0, radius2 / d2 * cosine);
            }
            const double edge = std::max(std::abs(u), std::abs(v));
            const double fade = edge < 0.8 ? 1 : std::max(0.0, (1 - edge) / 0.2);
            texels[row * ShadowTexels + column] = std::uint8_t(std::lround(255 * (1 - visible) * fade));
        }
    m_shadowImage->dirty();
    m_shadowArea->set(osg::Vec3f(float(centreX), float(centreZ), float(half)));
}

anim::Vec3d ArCompositor::cameraPosition(const ar::TargetPose& pose) const
{
    return arCameraView(m_camera, pose, m_target, m_placement).eye;
}

Result<void> ArCompositor::compose(ar::VideoFrame& frame, const ar::TargetPose& pose)
{
    if (frame.width != m_camera.width || frame.height != m_camera.height)
        return makeError(ErrorCode::InvalidArgument,
                         "A " + std::to_string(frame.width) + " × " + std::to_string(frame.height) +
                             " frame, but the camera is calibrated for " + std::to_string(m_camera.width) + " × " +
                             std::to_string(m_camera.height));
    if (m_placement.shadowCatcher)
        updateShadow();
    const CameraView view = arCameraView(m_camera, pose, m_target, m_placement);
    if (auto drawn = m_renderer->render(m_scene->scene(), view, m_layer); !drawn)
        return drawn.error();
    // frame = video · (1 − α) + layer (premultiplied), RGBA over BGR.
    const std::size_t pixels = std::size_t(frame.width) * std::size_t(frame.height);
    std::uint8_t* video = frame.bgr.data();
    const std::uint8_t* layer = m_layer.rgba.data();
    for (std::size_t i = 0; i < pixels; ++i, video += 3, layer += 4) {
        const unsigned alpha = layer[3];
        if (alpha == 0)
            continue;
        const unsigned keep = 255 - alpha;
        video[0] = std::uint8_t(std::min(255u, (video[0] * keep + 127) / 255 + layer[2]));
        video[1] = std::uint8_t(std::min(255u, (video[1] * keep + 127) / 255 + layer[1]));
        video[2] = std::uint8_t(std::min(255u, (video[2] * keep + 127) / 255 + layer[0]));
    }
    return {};
}

} // namespace thespis::core::render
