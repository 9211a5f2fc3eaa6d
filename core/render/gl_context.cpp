#include "render/gl_context.h"

#define EGL_NO_X11 // keep X11's macros (None, Status, …) out of the build
#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <GL/gl.h>

#include <osg/Notify>

#include <array>
#include <cstdio>
#include <cstdlib>
#include <cstring>

namespace thespis::core::render {

namespace {

std::string eglErrorName(EGLint error)
{
    switch (error) {
    case EGL_SUCCESS: return "EGL_SUCCESS";
    case EGL_NOT_INITIALIZED: return "EGL_NOT_INITIALIZED";
    case EGL_BAD_ACCESS: return "EGL_BAD_ACCESS";
    case EGL_BAD_ALLOC: return "EGL_BAD_ALLOC";
    case EGL_BAD_ATTRIBUTE: return "EGL_BAD_ATTRIBUTE";
    case EGL_BAD_CONFIG: return "EGL_BAD_CONFIG";
    case EGL_BAD_CONTEXT: return "EGL_BAD_CONTEXT";
    case EGL_BAD_DISPLAY: return "EGL_BAD_DISPLAY";
    case EGL_BAD_MATCH: return "EGL_BAD_MATCH";
    case EGL_BAD_PARAMETER: return "EGL_BAD_PARAMETER";
    default: {
        char text[32];
        std::snprintf(text, sizeof text, "EGL error 0x%04x", unsigned(error));
        return text;
    }
    }
}

bool hasExtension(const char* extensions, const char* name)
{
    if (!extensions)
        return false;
    const std::size_t length = std::strlen(name);
    for (const char* at = std::strstr(extensions, name); at; at = std::strstr(at + length, name))
        if ((at == extensions || at[-1] == ' ') && (at[length] == ' ' || at[length] == '\0'))
            return true;
    return false;
}

// IoError: the system failed us, the caller did nothing wrong (ErrorCode has no "unavailable").
Error missing(std::string what, std::string detail)
{
    return makeError(ErrorCode::IoError,
                     "Offscreen rendering needs an OpenGL context, but " + std::move(what) +
                         " (install Mesa's EGL and OpenGL drivers, e.g. libegl1 and libgl1-mesa-dri).",
                     std::move(detail));
}

// The surfaceless platform (Mesa) needs neither a window system nor a device; the device platform
// is what NVIDIA's EGL offers instead.
EGLDisplay openDisplay(std::string& tried)
{
    const char* clientExtensions = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
    auto getPlatformDisplay =
        reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(eglGetProcAddress("eglGetPlatformDisplayEXT"));
    if (!getPlatformDisplay) {
        tried = "eglGetPlatformDisplayEXT is missing";
        return EGL_NO_DISPLAY;
    }
    if (hasExtension(clientExtensions, "EGL_MESA_platform_surfaceless")) {
        EGLDisplay display = getPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
        if (display != EGL_NO_DISPLAY && eglInitialize(display, nullptr, nullptr))
            return display;
        tried += "surfaceless platform: " + eglErrorName(eglGetError()) + "; ";
    }
    auto queryDevices = reinterpret_cast<PFNEGLQUERYDEVICESEXTPROC>(eglGetProcAddress("eglQueryDevicesEXT"));
    if (queryDevices && hasExtension(clientExtensions, "EGL_EXT_platform_device")) {
        std::array<EGLDeviceEXT, 8> devices{};
        EGLint count = 0;
        if (queryDevices(EGLint(devices.size()), devices.data(), &count))
            for (EGLint i = 0; i < count; ++i) {
                EGLDisplay display = getPlatformDisplay(EGL_PLATFORM_DEVICE_EXT, devices[std::size_t(i)], nullptr);
                if (display != EGL_NO_DISPLAY && eglInitialize(display, nullptr, nullptr))
                    return display;
            }
        tried += "device platform: " + std::to_string(count) + " devices, none initialised; ";
    }
    if (tried.empty())
        tried = "EGL offers neither EGL_MESA_platform_surfaceless nor EGL_EXT_platform_device";
    return EGL_NO_DISPLAY;
}

} // namespace

Result<std::unique_ptr<OffscreenGlContext>> OffscreenGlContext::create()
{
    std::string tried;
    EGLDisplay display = openDisplay(tried);
    if (display == EGL_NO_DISPLAY)
        return missing("no EGL display could be opened without a window system", tried);
    std::unique_ptr<OffscreenGlContext> context(new OffscreenGlContext);
    context->m_display = display;

    const char* extensions = eglQueryString(display, EGL_EXTENSIONS);
    if (!hasExtension(extensions, "EGL_KHR_surfaceless_context"))
        return missing("the EGL display cannot make a context current without a surface",
                       "EGL_KHR_surfaceless_context is missing");
    if (!eglBindAPI(EGL_OPENGL_API))
        return missing("EGL does not offer desktop OpenGL", eglErrorName(eglGetError()));

    // A pbuffer-capable configuration exists on every EGL; the context never draws to a surface.
    const std::array<EGLint, 5> configAttributes{EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_RENDERABLE_TYPE,
                                                 EGL_OPENGL_BIT, EGL_NONE};
    EGLConfig config = nullptr;
    EGLint configCount = 0;
    if (!eglChooseConfig(display, configAttributes.data(), &config, 1, &configCount) || configCount < 1) {
        if (!hasExtension(extensions, "EGL_KHR_no_config_context"))
            return missing("EGL has no configuration for desktop OpenGL", eglErrorName(eglGetError()));
        config = EGL_NO_CONFIG_KHR;
    }
    // No profile attributes: EGL then gives a compatibility-profile context, which OSG needs.
    EGLContext glContext = eglCreateContext(display, config, EGL_NO_CONTEXT, nullptr);
    if (glContext == EGL_NO_CONTEXT)
        return missing("EGL could not create an OpenGL context", eglErrorName(eglGetError()));
    context->m_context = glContext;
    if (!context->makeCurrent())
        return missing("the OpenGL context could not be made current", eglErrorName(eglGetError()));

    const char* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
    const char* version = reinterpret_cast<const char*>(glGetString(GL_VERSION));
    int major = 0, minor = 0;
    if (!version || std::sscanf(version, "%d.%d", &major, &minor) != 2)
        return missing("the OpenGL context does not report its version", "glGetString(GL_VERSION) failed");
    context->m_description = std::string(renderer ? renderer : "unknown renderer") + ", OpenGL " + version;
    // Framebuffer objects and GLSL 1.20 are core in OpenGL 3.0.
    if (major < 3)
        return missing("the OpenGL context is version " + std::to_string(major) + "." + std::to_string(minor) +
                           " and 3.0 is the minimum",
                       context->m_description);
    return context;
}

OffscreenGlContext::~OffscreenGlContext()
{
    if (!m_display)
        return;
    if (m_context && eglGetCurrentContext() == m_context)
        eglMakeCurrent(m_display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    if (m_context)
        eglDestroyContext(m_display, m_context);
    // The display stays initialised: EGL hands every caller the same display for a platform, so
    // terminating it would break the other renderers of the process.
}

bool OffscreenGlContext::makeCurrent()
{
    return eglMakeCurrent(m_display, EGL_NO_SURFACE, EGL_NO_SURFACE, m_context) == EGL_TRUE;
}

void quietOsgNotifications()
{
    if (!std::getenv("OSG_NOTIFY_LEVEL"))
        osg::setNotifyLevel(osg::WARN);
}

} // namespace thespis::core::render
