#include "render/offscreen_renderer.h"

#include <algorithm>
#include <cmath>
#include <cstring>

#include <malloc.h>

#include <osg/Image>
#include <osg/NodeVisitor>
#include <osg/Program>
#include <osgViewer/Viewer>

#include <stb_image_write.h>

#include "util/file_io.h"

namespace thespis::core::render {

namespace {

// Collects the programs the scene's state sets use (the characters' current shading included).
class ProgramCollector : public osg::NodeVisitor {
public:
    ProgramCollector() : osg::NodeVisitor(TRAVERSE_ALL_CHILDREN) {}
    void apply(osg::Node& node) override
    {
        if (const osg::StateSet* state = node.getStateSet())
            if (auto* program = dynamic_cast<const osg::Program*>(state->getAttribute(osg::StateAttribute::PROGRAM)))
                programs.push_back(program);
        traverse(node);
    }
    std::vector<const osg::Program*> programs;
};

} // namespace

Result<std::unique_ptr<OffscreenRenderer>> OffscreenRenderer::create(int width, int height, int samples)
{
    constexpr int maxSize = 16384;
    if (width < 1 || height < 1 || width > maxSize || height > maxSize)
        return makeError(ErrorCode::InvalidArgument, "A picture of " + std::to_string(width) + " × " +
                                                         std::to_string(height) + " pixels cannot be rendered (1 to " +
                                                         std::to_string(maxSize) + " pixels each way).");
    if (samples < 0 || samples > 16)
        return makeError(ErrorCode::InvalidArgument,
                         "Anti-aliasing takes 0 to 16 samples per pixel, not " + std::to_string(samples) + ".");
    const int factor = std::max(1, int(std::sqrt(double(samples))));
    if (width * factor > maxSize || height * factor > maxSize)
        return makeError(ErrorCode::InvalidArgument,
                         "A picture of " + std::to_string(width) + " × " + std::to_string(height) + " pixels with " +
                             std::to_string(samples) + " samples per pixel is too large to draw.");
    auto context = OffscreenGlContext::create();
    if (!context)
        return context.error();
    quietOsgNotifications();
    // llvmpipe frees its binning memory at the end of every frame; glibc then trims the heap and
    // the next frame faults the pages in again (a third of llvmpipe's CPU time at 1280×720).
    // Keeping up to 128 MiB of freed heap avoids that; it only matters to software GL.
    if ((*context)->description().find("llvmpipe") != std::string::npos)
        mallopt(M_TRIM_THRESHOLD, 128 << 20);

    std::unique_ptr<OffscreenRenderer> renderer(new OffscreenRenderer);
    renderer->m_width = width;
    renderer->m_height = height;
    renderer->m_factor = factor;
    renderer->m_context = std::move(*context);
    renderer->m_image = new osg::Image;
    renderer->m_image->allocateImage(width * factor, height * factor, 1, GL_RGBA, GL_UNSIGNED_BYTE);

    // The embedded window takes the context as it is: current on this thread, and OSG never
    // switches contexts itself.
    osg::ref_ptr<osgViewer::Viewer> viewer = new osgViewer::Viewer;
    viewer->setUpViewerAsEmbeddedInWindow(0, 0, width * factor, height * factor);
    viewer->setThreadingModel(osgViewer::Viewer::SingleThreaded);
    viewer->setLightingMode(osg::View::NO_LIGHT);
    viewer->setKeyEventSetsDone(0);
    osg::Camera* camera = viewer->getCamera();
    camera->setRenderTargetImplementation(osg::Camera::FRAME_BUFFER_OBJECT);
    camera->attach(osg::Camera::COLOR_BUFFER, renderer->m_image.get());
    camera->attach(osg::Camera::DEPTH_BUFFER, GL_DEPTH_COMPONENT24);
    camera->setComputeNearFarMode(osg::CullSettings::DO_NOT_COMPUTE_NEAR_FAR);
    camera->setClearMask(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    viewer->realize();
    renderer->m_viewer = viewer;
    return renderer;
}

OffscreenRenderer::~OffscreenRenderer()
{
    // Closing the viewer's window releases the GL objects of the scene it shows, which needs the
    // context current.
    if (m_context)
        m_context->makeCurrent();
    m_viewer = nullptr;
}

Result<void> OffscreenRenderer::render(const RenderScene& scene, const CameraView& view, RgbaImage& out)
{
    if (!m_context->makeCurrent())
        return makeError(ErrorCode::Internal, "The offscreen OpenGL context could not be made current.");
    osg::Node* root = scene.root();
    if (m_viewer->getSceneData() != root) {
        // The previous scene may be drawn elsewhere later: give back its objects in this context.
        if (osg::Node* previous = m_viewer->getSceneData())
            previous->releaseGLObjects(m_viewer->getCamera()->getGraphicsContext()->getState());
        m_viewer->setSceneData(root);
    }
    osg::Camera* camera = m_viewer->getCamera();
    const std::array<float, 3>& background = scene.backgroundColor();
    camera->setClearColor(scene.transparentBackground() ? osg::Vec4(0, 0, 0, 0)
                                                        : osg::Vec4(background[0], background[1], background[2], 1.0f));
    camera->setViewMatrix(viewMatrix(view));
    camera->setProjectionMatrix(projectionMatrix(view, double(m_width) / m_height));
    m_viewer->frame();
    if (auto linked = checkPrograms(*root); !linked)
        return linked;

    out.width = m_width;
    out.height = m_height;
    out.rgba.resize(std::size_t(m_width) * std::size_t(m_height) * 4);
    const std::size_t rowBytes = std::size_t(m_width) * 4;
    if (m_factor == 1) {
        for (int y = 0; y < m_height; ++y) // GL's rows go up from the bottom
            std::memcpy(out.rgba.data() + std::size_t(y) * rowBytes, m_image->data(0, m_height - 1 - y), rowBytes);
        return {};
    }
    // Supersampled: each output pixel is the mean of its factor × factor block (rounded). The
    // block's rows are looked up once per output row (osg::Image::data works out the pixel size
    // on every call).
    const int blockSize = m_factor * m_factor;
    const std::uint8_t* rows[4]; // the factor is at most 4 (16 samples)
    for (int y = 0; y < m_height; ++y) {
        std::uint8_t* target = out.rgba.data() + std::size_t(y) * rowBytes;
        for (int by = 0; by < m_factor; ++by)
            rows[by] = m_image->data(0, (m_height - 1 - y) * m_factor + by);
        for (int x = 0; x < m_width; ++x)
            for (int c = 0; c < 4; ++c) {
                int sum = 0;
                for (int by = 0; by < m_factor; ++by)
                    for (int bx = 0; bx < m_factor; ++bx)
                        sum += rows[by][4 * (x * m_factor + bx) + c];
                target[4 * x + c] = std::uint8_t((sum + blockSize / 2) / blockSize);
            }
    }
    return {};
}

Result<RgbaImage> OffscreenRenderer::render(const RenderScene& scene, const CameraView& view)
{
    RgbaImage image;
    if (auto rendered = render(scene, view, image); !rendered)
        return rendered.error();
    return image;
}

Result<void> OffscreenRenderer::checkPrograms(osg::Node& root)
{
    ProgramCollector collector;
    root.accept(collector);
    osg::State& state = *m_viewer->getCamera()->getGraphicsContext()->getState();
    for (const osg::Program* program : collector.programs) {
        const osg::Program::PerContextProgram* compiled = program->getPCP(state);
        if (compiled && !compiled->isLinked()) {
            std::string log;
            compiled->getInfoLog(log);
            return makeError(ErrorCode::Internal,
                             "The OpenGL driver (" + glDescription() + ") could not build the shader \"" +
                                 program->getName() + "\"; it may be too old for GLSL 1.20.",
                             log);
        }
    }
    return {};
}

Result<void> writePng(const std::filesystem::path& path, const RgbaImage& image)
{
    if (image.width < 1 || image.height < 1 ||
        image.rgba.size() != std::size_t(image.width) * std::size_t(image.height) * 4)
        return makeError(ErrorCode::InvalidArgument, "Cannot write " + path.string() + ": the picture is empty or malformed.");
    std::string bytes;
    const auto append = [](void* context, void* data, int size) {
        static_cast<std::string*>(context)->append(static_cast<const char*>(data), std::size_t(size));
    };
    if (!stbi_write_png_to_func(append, &bytes, image.width, image.height, 4, image.rgba.data(), image.width * 4))
        return makeError(ErrorCode::IoError, "Could not encode " + path.string() + " as PNG.");
    return writeFileAtomically(path, bytes);
}

} // namespace thespis::core::render
