#pragma once
#include "gl/EntryPoints.h"

#include <vector>

namespace gl {

class Texture;

// A framebuffer object drawing into the given colour textures, in attachment order.
// Move-only; deletes the framebuffer (not the textures) it owns.
class Framebuffer {
public:
    // Throws std::runtime_error when the attachments do not make a complete framebuffer.
    explicit Framebuffer(const std::vector<const Texture*>& colorAttachments);
    ~Framebuffer();
    Framebuffer(Framebuffer&& other) noexcept;
    Framebuffer& operator=(Framebuffer&& other) noexcept;
    Framebuffer(const Framebuffer&) = delete;
    Framebuffer& operator=(const Framebuffer&) = delete;

    void bindForDrawing() const;
    // Selects colour attachment `index` as the source of glReadPixels.
    void bindForReading(int index) const;

private:
    GLuint id_ = 0;
};

}  // namespace gl
