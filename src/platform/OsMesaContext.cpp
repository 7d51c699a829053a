#include "platform/OsMesaContext.h"

#include "gl/EntryPoints.h"

// glew.h, included above, undefines GLAPI, which osmesa.h still uses for its declarations.
#ifndef GLAPI
#define GLAPI extern
#endif
#include <GL/osmesa.h>

#include <stdexcept>

namespace platform {

namespace {

void* osMesaLoader(const char* name)
{
    return reinterpret_cast<void*>(OSMesaGetProcAddress(name));
}

// The renderer never draws to the context's own buffer (it has framebuffer objects), but
// OSMesa needs one to make the context current.
constexpr int kDefaultFramebufferSide = 16;

}  // namespace

OsMesaContext::OsMesaContext()
{
    const int attributes[] = {OSMESA_FORMAT,
                              OSMESA_RGBA,
                              OSMESA_DEPTH_BITS,
                              0,
                              OSMESA_STENCIL_BITS,
                              0,
                              OSMESA_PROFILE,
                              OSMESA_CORE_PROFILE,
                              OSMESA_CONTEXT_MAJOR_VERSION,
                              3,
                              OSMESA_CONTEXT_MINOR_VERSION,
                              3,
                              0};
    context_ = OSMesaCreateContextAttribs(attributes, nullptr);
    if (context_ == nullptr)
        throw std::runtime_error(
            "OSMesa could not create an OpenGL 3.3 core context (is Mesa's libOSMesa "
            "built with llvmpipe?)");

    defaultFramebuffer_.assign(kDefaultFramebufferSide * kDefaultFramebufferSide * 4, 0);
    if (!OSMesaMakeCurrent(context_, defaultFramebuffer_.data(), GL_UNSIGNED_BYTE,
                           kDefaultFramebufferSide, kDefaultFramebufferSide)) {
        OSMesaDestroyContext(context_);
        throw std::runtime_error("OSMesa could not make its context current");
    }
    try {
        gl::loadEntryPoints(&osMesaLoader, /*contextHasGlx=*/false);
        requireGl33();
    } catch (...) {
        OSMesaDestroyContext(context_);
        throw;
    }
    identity_ = identifyCurrentContext("OSMesa");
}

OsMesaContext::~OsMesaContext()
{
    OSMesaMakeCurrent(nullptr, nullptr, 0, 0, 0);
    OSMesaDestroyContext(context_);
}

}  // namespace platform
