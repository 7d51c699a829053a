#include "platform/EglContext.h"

#include "gl/EntryPoints.h"

#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <cstring>
#include <stdexcept>

namespace platform {

namespace {

// GLEW asks for GLX's functions too (gl/EntryPoints.cpp). EGL has none, but libglvnd's
// eglGetProcAddress answers any "gl..." name with a GL dispatch stub, which GLEW would then
// call as glXGetCurrentDisplay: GLX names get no answer, so GLEW sees no GLX, as under OSMesa.
void* eglLoader(const char* name)
{
    if (std::strncmp(name, "glX", 3) == 0)
        return nullptr;
    return reinterpret_cast<void*>(eglGetProcAddress(name));
}

bool displayHasExtension(EGLDisplay display, const char* name)
{
    return eglExtensionListHas(eglQueryString(display, EGL_EXTENSIONS), name);
}

EGLDisplay platformDisplay(EGLenum platform, void* nativeDisplay)
{
    const auto getPlatformDisplay = reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(
        eglGetProcAddress("eglGetPlatformDisplayEXT"));
    if (getPlatformDisplay == nullptr)
        throw std::runtime_error("libEGL lacks eglGetPlatformDisplayEXT (EGL_EXT_platform_base)");
    const EGLDisplay display = getPlatformDisplay(platform, nativeDisplay, nullptr);
    if (display == EGL_NO_DISPLAY)
        throw std::runtime_error("eglGetPlatformDisplayEXT failed: " + lastEglError());
    return display;
}

// The tiny pbuffer a context is made current with where the driver needs a surface.
constexpr EGLint kPbufferSide = 16;

}  // namespace

std::unique_ptr<EglContext> EglContext::onDevice(const EglDevice& device)
{
    return std::unique_ptr<EglContext>(
        new EglContext(platformDisplay(EGL_PLATFORM_DEVICE_EXT, device.handle), device.kind()));
}

std::unique_ptr<EglContext> EglContext::surfaceless()
{
    const char* client = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
    if (client == nullptr || std::strstr(client, "EGL_MESA_platform_surfaceless") == nullptr)
        throw std::runtime_error("libEGL lacks EGL_MESA_platform_surfaceless");
    return std::unique_ptr<EglContext>(new EglContext(
        platformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY), "EGL surfaceless"));
}

EglContext::EglContext(void* display, const std::string& kind) : display_(display)
{
    try {
        EGLint major = 0;
        EGLint minor = 0;
        if (!eglInitialize(display_, &major, &minor))
            throw std::runtime_error("eglInitialize failed: " + lastEglError());
        if (!eglBindAPI(EGL_OPENGL_API))
            throw std::runtime_error(
                "the display offers no desktop OpenGL (eglBindAPI: " + lastEglError() + ")");

        // A context without a config where the driver allows it (every surface it could
        // draw to is a framebuffer object); else any config that can make a pbuffer.
        EGLConfig config = EGL_NO_CONFIG_KHR;
        const bool configless = displayHasExtension(display_, "EGL_KHR_no_config_context") ||
                                displayHasExtension(display_, "EGL_MESA_configless_context");
        const bool surfaceless = displayHasExtension(display_, "EGL_KHR_surfaceless_context");
        if (!configless || !surfaceless) {
            const EGLint wanted[] = {EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_RENDERABLE_TYPE,
                                     EGL_OPENGL_BIT, EGL_NONE};
            EGLint found = 0;
            if (!eglChooseConfig(display_, wanted, &config, 1, &found) || found < 1)
                throw std::runtime_error("no EGL config renders desktop OpenGL to a pbuffer (" +
                                         lastEglError() + ")");
        }
        // OpenGL 3.3 core or later: drivers give the newest core version they have (the
        // compute kernel asks for 4.3 itself).
        const EGLint attributes[] = {EGL_CONTEXT_MAJOR_VERSION,
                                     3,
                                     EGL_CONTEXT_MINOR_VERSION,
                                     3,
                                     EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                     EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                     EGL_NONE};
        context_ = eglCreateContext(display_, config, EGL_NO_CONTEXT, attributes);
        if (context_ == EGL_NO_CONTEXT)
            throw std::runtime_error("eglCreateContext (OpenGL 3.3 core) failed: " +
                                     lastEglError());
        if (!surfaceless) {
            const EGLint size[] = {EGL_WIDTH, kPbufferSide, EGL_HEIGHT, kPbufferSide, EGL_NONE};
            surface_ = eglCreatePbufferSurface(display_, config, size);
            if (surface_ == EGL_NO_SURFACE)
                throw std::runtime_error("eglCreatePbufferSurface failed: " + lastEglError());
        }
        if (!eglMakeCurrent(display_, surface_, surface_, context_))
            throw std::runtime_error("eglMakeCurrent failed: " + lastEglError());
        gl::loadEntryPoints(&eglLoader, /*contextHasGlx=*/false);
        requireGl33();
    } catch (...) {
        release();
        throw;
    }
    identity_ = identifyCurrentContext(kind);
}

EglContext::~EglContext()
{
    release();
}

void EglContext::release()
{
    if (display_ == nullptr)
        return;
    eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    if (surface_ != nullptr)
        eglDestroySurface(display_, surface_);
    if (context_ != nullptr)
        eglDestroyContext(display_, context_);
    // Displays are shared per device within a process: terminating releases this one's
    // resources, and a later context on the device initialises it again.
    eglTerminate(display_);
    eglReleaseThread();
    display_ = context_ = surface_ = nullptr;
}

}  // namespace platform
