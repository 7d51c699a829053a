#include "gl/Texture.h"

#include "gl/GlError.h"

#include <utility>

namespace gl {

Texture::Texture(GLenum target) : target_(target)
{
    glGenTextures(1, &id_);
}

Texture::~Texture()
{
    if (id_ != 0)
        glDeleteTextures(1, &id_);
}

Texture::Texture(Texture&& other) noexcept
    : target_(other.target_), id_(std::exchange(other.id_, 0))
{
}

Texture& Texture::operator=(Texture&& other) noexcept
{
    if (this != &other) {
        if (id_ != 0)
            glDeleteTextures(1, &id_);
        target_ = other.target_;
        id_ = std::exchange(other.id_, 0);
    }
    return *this;
}

void Texture::bind(int unit) const
{
    glActiveTexture(GL_TEXTURE0 + static_cast<GLenum>(unit));
    glBindTexture(target_, id_);
}

void Texture::setSampling(GLint minFilter, GLint magFilter, GLint wrapS, GLint wrapT) const
{
    glTexParameteri(target_, GL_TEXTURE_MIN_FILTER, minFilter);
    glTexParameteri(target_, GL_TEXTURE_MAG_FILTER, magFilter);
    glTexParameteri(target_, GL_TEXTURE_WRAP_S, wrapS);
    glTexParameteri(target_, GL_TEXTURE_WRAP_T, wrapT);
}

Texture createTexture2D(GLenum internalFormat, int width, int height, GLenum format, GLenum type,
                        const void* pixels)
{
    Texture texture(GL_TEXTURE_2D);
    texture.bind(0);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexImage2D(GL_TEXTURE_2D, 0, static_cast<GLint>(internalFormat), width, height, 0, format,
                 type, pixels);
    texture.setSampling(GL_NEAREST, GL_NEAREST, GL_CLAMP_TO_EDGE, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 0);
    throwOnGlError("creating a " + std::to_string(width) + "x" + std::to_string(height) +
                   " texture");
    return texture;
}

}  // namespace gl
