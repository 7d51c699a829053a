#pragma once
#include "gl/EntryPoints.h"

namespace gl {

// A GL texture object of a fixed target. Move-only; deletes the texture it owns.
class Texture {
public:
    explicit Texture(GLenum target);
    ~Texture();
    Texture(Texture&& other) noexcept;
    Texture& operator=(Texture&& other) noexcept;
    Texture(const Texture&) = delete;
    Texture& operator=(const Texture&) = delete;

    GLuint id() const { return id_; }
    GLenum target() const { return target_; }
    // Binds to texture unit `unit`.
    void bind(int unit) const;
    // How the bound texture is filtered and wrapped (it must be bound: GL sets the parameters
    // of the texture bound to the active unit).
    void setSampling(GLint minFilter, GLint magFilter, GLint wrapS, GLint wrapT) const;

private:
    GLenum target_;
    GLuint id_ = 0;
};

// A 2D texture of one level, nearest-filtered: a render target or a data image.
Texture createTexture2D(GLenum internalFormat, int width, int height, GLenum format, GLenum type,
                        const void* pixels);

}  // namespace gl
