#include "render/ar_compositor.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <osg/ColorMask>
#include <osg/Depth>
#include <osg/Geometry>
#include <osg/MatrixTransform>

#include "lighting/sh_rotation.h"
#include "render/ar_view.h"
#include "render/shaders.h"
#include "scene/gltf_mesh.h"

namespace thespis::core::render {

namespace {

// Draw order: phantoms fill the depth buffer first, then the shadow catcher, then the characters.
constexpr int OccluderBin = -2, ShadowBin = -1;
// The shadow catcher's extent around the world's origin (metres of the world).
constexpr float ShadowCatcherRadius = 6.0f;
// Characters become spheres by gathering their posed vertices in cubes this wide (metres).
constexpr double ShadowCellSize = 0.16;
constexpr int ShadowCellMinimumVertices = 6;
constexpr std::size_t ShadowGridSlots = 4096; // a power of two

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

osg::ref_ptr<osg::Node> makeShadowCatcher(osg::Uniform* spheres, osg::Uniform* count, float strength)
{
    std::vector<osg::Vec3f> disc{{0, 0, 0}};
    std::vector<unsigned> fan;
    constexpr int Sides = 48;
    for (int i = 0; i <= Sides; ++i) {
        const double a = 2 * std::numbers::pi * i / Sides;
        disc.emplace_back(ShadowCatcherRadius * float(std::cos(a)), 0, -ShadowCatcherRadius * float(std::sin(a)));
        if (i > 0)
            fan.insert(fan.end(), {0u, unsigned(i), unsigned(i + 1)});
    }
    osg::ref_ptr<osg::Geometry> ground = triangles(disc, fan);
    ground->setName("shadow catcher");
    osg::StateSet* state = ground->getOrCreateStateSet();
    state->setAttributeAndModes(shaders::shadowCatcherProgram().get());
    state->addUniform(spheres);
    state->addUniform(count);
    state->addUniform(new osg::Uniform("shadowStrength", strength));
    state->addUniform(new osg::Uniform("exposure", 1.0f));
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
    self->m_spheres = new osg::Uniform(osg::Uniform::FLOAT_VEC4, "occluders", shaders::kMaxShadowSpheres);
    self->m_sphereCountUniform = new osg::Uniform("occluderCount", 0);
    self->m_shadowCatcher = makeShadowCatcher(self->m_spheres.get(), self->m_sphereCountUniform.get(),
                                              settings.shadowStrength);
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

void ArCompositor::updateShadowSpheres()
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
            std::size_t slot = std::size_t((key * 0x9E3779B97F4A7C15ull) >> 52) & (ShadowGridSlots - 1);
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
    // The fullest cubes first, as many as the shader takes.
    std::partial_sort(m_cells.begin(), m_cells.begin() + shaders::kMaxShadowSpheres, m_cells.end(),
                      [](const Cell& a, const Cell& b) { return a.count > b.count; });
    m_sphereCount = 0;
    for (int i = 0; i < shaders::kMaxShadowSpheres; ++i) {
        const Cell& cell = m_cells[std::size_t(i)];
        if (cell.count < ShadowCellMinimumVertices)
            break;
        m_spheres->setElement(unsigned(i), osg::Vec4f(float(cell.x / cell.count), float(cell.y / cell.count),
                                                      float(cell.z / cell.count), float(0.55 * ShadowCellSize)));
        ++m_sphereCount;
    }
    m_sphereCountUniform->set(m_sphereCount);
}

Result<void> ArCompositor::compose(ar::VideoFrame& frame, const ar::TargetPose& pose)
{
    if (frame.width != m_camera.width || frame.height != m_camera.height)
        return makeError(ErrorCode::InvalidArgument,
                         "A " + std::to_string(frame.width) + " × " + std::to_string(frame.height) +
                             " frame, but the camera is calibrated for " + std::to_string(m_camera.width) + " × " +
                             std::to_string(m_camera.height));
    if (m_placement.shadowCatcher)
        updateShadowSpheres();
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
