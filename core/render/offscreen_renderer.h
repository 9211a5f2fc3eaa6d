#pragma once
// Headless rendering of a RenderScene into RGBA8 pictures: an OffscreenGlContext (EGL, no X
// server) hosting an osgViewer::Viewer in an embedded window whose camera draws into a framebuffer
// object and reads the pixels back after each frame. Used by `thespis-cli render` and the tests.
// A renderer belongs to the thread that created it.

#include <array>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include <osg/ref_ptr>

#include "render/camera.h"
#include "render/gl_context.h"
#include "render/render_scene.h"
#include "util/error.h"

namespace osg {
class Image;
class Node;
}
namespace osgViewer {
class Viewer;
}

namespace thespis::core::render {

/// 8-bit RGBA pixels, rows from the top.
struct RgbaImage {
    int width = 0;
    int height = 0;
    std::vector<std::uint8_t> rgba;
    std::array<std::uint8_t, 4> pixel(int x, int y) const
    {
        const std::uint8_t* p = rgba.data() + 4 * (std::size_t(y) * std::size_t(width) + std::size_t(x));
        return {p[0], p[1], p[2], p[3]};
    }
};

class OffscreenRenderer {
public:
    /// A renderer for width × height pictures (1 … 16384 each). `samples` (0 … 16) anti-aliases
    /// by supersampling: the frame is drawn k × k times larger, k = ⌊√samples⌋ (4 → 2 × 2, 16 →
    /// 4 × 4), and each pixel is the mean of its block; 0 or 1 draws the picture as it is. (OSG's
    /// multisampled framebuffer objects are incomplete on Mesa's llvmpipe.) Fails with a clear
    /// message when no OpenGL context can be made (see OffscreenGlContext::create).
    static Result<std::unique_ptr<OffscreenRenderer>> create(int width, int height, int samples = 0);
    ~OffscreenRenderer();
    OffscreenRenderer(const OffscreenRenderer&) = delete;
    OffscreenRenderer& operator=(const OffscreenRenderer&) = delete;

    int width() const { return m_width; }
    int height() const { return m_height; }
    /// The GL renderer and version, for logs ("llvmpipe (LLVM 15.0.6, 256 bits), OpenGL 4.5 …").
    const std::string& glDescription() const { return m_context->description(); }

    /// Draws one frame of the scene as seen from `view` into `out` (resized on first use; later
    /// calls of the same size do not allocate). Fails when a shader does not compile or link on
    /// this GL, with the driver's log as detail.
    Result<void> render(const RenderScene& scene, const CameraView& view, RgbaImage& out);
    Result<RgbaImage> render(const RenderScene& scene, const CameraView& view);

private:
    OffscreenRenderer() = default;
    Result<void> checkPrograms(osg::Node& root);

    int m_width = 0, m_height = 0;
    int m_factor = 1; // supersampling: the frame is drawn m_factor times wider and higher
    std::unique_ptr<OffscreenGlContext> m_context; // destroyed after the viewer (members go in reverse)
    osg::ref_ptr<osgViewer::Viewer> m_viewer;
    osg::ref_ptr<osg::Image> m_image;
};

/// Writes an RGBA picture as PNG (atomically); errors name the file.
Result<void> writePng(const std::filesystem::path& path, const RgbaImage& image);

} // namespace thespis::core::render
