#include "gl/TextureBuffer.h"

#include "gl/GlError.h"

#include <stdexcept>
#include <string>
#include <utility>

namespace gl {

TextureBuffer::TextureBuffer(GLenum internalFormat, const void* data, std::size_t texels,
                             std::size_t bytesPerTexel)
    : bytes_(texels * bytesPerTexel)
{
    GLint most = 0;
    glGetIntegerv(GL_MAX_TEXTURE_BUFFER_SIZE, &most);
    if (texels > static_cast<std::size_t>(most))
        throw std::runtime_error("the scene needs a buffer texture of " + std::to_string(texels) +
                                 " texels; this OpenGL's hold at most " + std::to_string(most) +
                                 " (GL_MAX_TEXTURE_BUFFER_SIZE)");
    glGenBuffers(1, &buffer_);
    glBindBuffer(GL_TEXTURE_BUFFER, buffer_);
    glBufferData(GL_TEXTURE_BUFFER, static_cast<GLsizeiptr>(bytes_), data, GL_STATIC_DRAW);
    glBindBuffer(GL_TEXTURE_BUFFER, 0);
    glGenTextures(1, &texture_);
    glBindTexture(GL_TEXTURE_BUFFER, texture_);
    glTexBuffer(GL_TEXTURE_BUFFER, internalFormat, buffer_);
    glBindTexture(GL_TEXTURE_BUFFER, 0);
    throwOnGlError("creating a buffer texture");
}

TextureBuffer::~TextureBuffer()
{
    release();
}

void TextureBuffer::release()
{
    if (texture_ != 0)
        glDeleteTextures(1, &texture_);
    if (buffer_ != 0)
        glDeleteBuffers(1, &buffer_);
    texture_ = 0;
    buffer_ = 0;
}

TextureBuffer::TextureBuffer(TextureBuffer&& other) noexcept
    : buffer_(std::exchange(other.buffer_, 0)),
      texture_(std::exchange(other.texture_, 0)),
      bytes_(other.bytes_)
{
}

TextureBuffer& TextureBuffer::operator=(TextureBuffer&& other) noexcept
{
    if (this != &other) {
        release();
        buffer_ = std::exchange(other.buffer_, 0);
        texture_ = std::exchange(other.texture_, 0);
        bytes_ = other.bytes_;
    }
    return *this;
}

void TextureBuffer::bind(int unit) const
{
    glActiveTexture(GL_TEXTURE0 + static_cast<GLenum>(unit));
    glBindTexture(GL_TEXTURE_BUFFER, texture_);
}

}  // namespace gl
