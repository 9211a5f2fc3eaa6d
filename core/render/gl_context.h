#pragma once
// A headless OpenGL context: EGL on Mesa's surfaceless platform (no X server, no window, no
// pbuffer), or on the first EGL device where surfaceless is not offered (NVIDIA's EGL). The
// context has the compatibility profile OSG needs; it has no default framebuffer, so everything
// is drawn into framebuffer objects. libglvnd routes OSG's GL calls to whichever context is current.

#include <memory>
#include <string>

#include "util/error.h"

namespace thespis::core::render {

class OffscreenGlContext {
public:
    /// Opens a display, creates a compatibility-profile OpenGL context and makes it current on
    /// the calling thread. Fails with a message naming what is missing (EGL display, OpenGL API,
    /// context, OpenGL 3.0) so that callers can tell the user why nothing can be rendered.
    static Result<std::unique_ptr<OffscreenGlContext>> create();
    ~OffscreenGlContext();
    OffscreenGlContext(const OffscreenGlContext&) = delete;
    OffscreenGlContext& operator=(const OffscreenGlContext&) = delete;

    /// Makes the context current on the calling thread (false if EGL refuses).
    bool makeCurrent();
    /// GL_RENDERER and GL_VERSION, e.g. "llvmpipe (LLVM 15.0.6, 256 bits), OpenGL 4.5 (Compatibility Profile) Mesa 22.3.6".
    const std::string& description() const { return m_description; }

private:
    OffscreenGlContext() = default;
    void* m_display = nullptr; // EGLDisplay
    void* m_context = nullptr; // EGLContext
    std::string m_description;
};

/// Lowers OSG's notification level to warnings (OSG prints notices on stderr otherwise) unless
/// the user asked for a level with OSG_NOTIFY_LEVEL. The offscreen renderer calls it; a viewer
/// hosted elsewhere (the studio) should too.
void quietOsgNotifications();

} // namespace thespis::core::render
