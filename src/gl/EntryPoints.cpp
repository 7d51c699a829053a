#include "gl/EntryPoints.h"

#include <dlfcn.h>

#include <stdexcept>
#include <string>

namespace gl {

CoreEntryPoints core;

namespace {

// The loader of the context made current last; null before any context exists.
ProcAddressLoader currentLoader = nullptr;

using GlxProcAddressFunction = void (*(*)(const GLubyte*))(void);

GlxProcAddressFunction systemGlxLoader()
{
    static const auto function =
        reinterpret_cast<GlxProcAddressFunction>(dlsym(RTLD_NEXT, "glXGetProcAddressARB"));
    return function;
}

template <typename Function>
void load(Function& slot, const char* name)
{
    slot = reinterpret_cast<Function>(currentLoader(name));
    if (slot == nullptr)
        throw std::runtime_error(std::string("OpenGL entry point ") + name +
                                 " is missing from the current context");
}

}  // namespace

void loadEntryPoints(ProcAddressLoader loader, bool contextHasGlx)
{
    currentLoader = loader;

    load(core.bindTexture, "glBindTexture");
    load(core.clear, "glClear");
    load(core.clearColor, "glClearColor");
    load(core.deleteTextures, "glDeleteTextures");
    load(core.disable, "glDisable");
    load(core.drawArrays, "glDrawArrays");
    load(core.drawBuffer, "glDrawBuffer");
    load(core.enable, "glEnable");
    load(core.finish, "glFinish");
    load(core.flush, "glFlush");
    load(core.genTextures, "glGenTextures");
    load(core.getError, "glGetError");
    load(core.getFloatv, "glGetFloatv");
    load(core.getIntegerv, "glGetIntegerv");
    load(core.getString, "glGetString");
    load(core.pixelStorei, "glPixelStorei");
    load(core.readBuffer, "glReadBuffer");
    load(core.readPixels, "glReadPixels");
    load(core.scissor, "glScissor");
    load(core.texImage2D, "glTexImage2D");
    load(core.texParameteri, "glTexParameteri");
    load(core.texSubImage2D, "glTexSubImage2D");
    load(core.viewport, "glViewport");

    // Core profiles list extensions with glGetStringi only; GLEW needs this to see them.
    glewExperimental = GL_TRUE;
    const GLenum status = glewInit();
    // glewInit first loads the GL entry points, then GLX's. Without GLX (OSMesa) the second
    // part fails after the first has succeeded; only the GL part matters to the renderer.
    const bool onlyGlxMissing = !contextHasGlx && (status == GLEW_ERROR_GLX_VERSION_11_ONLY ||
                                                   status == GLEW_ERROR_NO_GLX_DISPLAY);
    if (status != GLEW_OK && !onlyGlxMissing)
        throw std::runtime_error(std::string("GLEW could not load OpenGL: ") +
                                 reinterpret_cast<const char*>(glewGetErrorString(status)));
    // GLEW may query with enums a core profile rejects; that error is not the caller's.
    while (glGetError() != GL_NO_ERROR) {
    }
}

}  // namespace gl

// GLEW (as Debian builds it) finds every entry point by calling glXGetProcAddressARB. This
// definition takes the place of libGL's for the whole process (the executable exports it,
// see export_gl_loader in CMakeLists.txt), so GLEW's lookups go to the current context's
// loader: OSMesaGetProcAddress headless, glfwGetProcAddress in a window. Before any context
// is current it defers to the system's function, so GLX itself is never starved.
extern "C"
    __attribute__((visibility("default"))) void (*glXGetProcAddressARB(const GLubyte* name))(void)
{
    if (gl::currentLoader != nullptr)
        return reinterpret_cast<void (*)(void)>(
            gl::currentLoader(reinterpret_cast<const char*>(name)));
    if (const auto system = gl::systemGlxLoader())
        return system(name);
    return nullptr;
}
