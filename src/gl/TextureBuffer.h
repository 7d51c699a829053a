#pragma once
#include "gl/EntryPoints.h"

#include <cstddef>

namespace gl {

// A buffer texture (GL_TEXTURE_BUFFER): a buffer object of texels that a shader reads with
// texelFetch from a samplerBuffer, however many there are up to GL_MAX_TEXTURE_BUFFER_SIZE
// (128 M texels on llvmpipe) where a uniform array holds a few thousand vec4s. Move-only;
// deletes the texture and the buffer it owns.
class TextureBuffer {
public:
    // `texels` texels of `internalFormat` (GL_RGBA32F, GL_RGBA32I) from `data`, which holds
    // texels * `bytesPerTexel` bytes. Throws, naming the limit, where there are more texels
    // than this OpenGL's buffer textures hold.
    TextureBuffer(GLenum internalFormat, const void* data, std::size_t texels,
                  std::size_t bytesPerTexel);
    ~TextureBuffer();
    TextureBuffer(TextureBuffer&& other) noexcept;
    TextureBuffer& operator=(TextureBuffer&& other) noexcept;
    TextureBuffer(const TextureBuffer&) = delete;
    TextureBuffer& operator=(const TextureBuffer&) = delete;

    // Binds to texture unit `unit`.
    void bind(int unit) const;
    std::size_t bytes() const { return bytes_; }

private:
    void release();

    GLuint buffer_ = 0;
    GLuint texture_ = 0;
    std::size_t bytes_ = 0;
};

}  // namespace gl
