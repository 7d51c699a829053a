#include "gl/GlError.h"

#include "gl/EntryPoints.h"

#include <stdexcept>

namespace gl {

namespace {

const char* errorName(GLenum error)
{
    switch (error) {
    case GL_INVALID_ENUM:
        return "GL_INVALID_ENUM";
    case GL_INVALID_VALUE:
        return "GL_INVALID_VALUE";
    case GL_INVALID_OPERATION:
        return "GL_INVALID_OPERATION";
    case GL_INVALID_FRAMEBUFFER_OPERATION:
        return "GL_INVALID_FRAMEBUFFER_OPERATION";
    case GL_OUT_OF_MEMORY:
        return "GL_OUT_OF_MEMORY";
    default:
        return "an unknown GL error";
    }
}

}  // namespace

void throwOnGlError(const std::string& operation)
{
    const GLenum error = glGetError();
    if (error == GL_NO_ERROR)
        return;
    while (glGetError() != GL_NO_ERROR) {
    }
    throw std::runtime_error(std::string("OpenGL reported ") + errorName(error) + " during " +
                             operation);
}

}  // namespace gl
