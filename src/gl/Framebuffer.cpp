#include "gl/Framebuffer.h"

#include "gl/Texture.h"

#include <stdexcept>
#include <string>
#include <utility>

namespace gl {

Framebuffer::Framebuffer(const std::vector<const Texture*>& colorAttachments)
{
    glGenFramebuffers(1, &id_);
    glBindFramebuffer(GL_FRAMEBUFFER, id_);
    std::vector<GLenum> drawBuffers;
    for (std::size_t i = 0; i < colorAttachments.size(); ++i) {
        const GLenum attachment = GL_COLOR_ATTACHMENT0 + static_cast<GLenum>(i);
        glFramebufferTexture2D(GL_FRAMEBUFFER, attachment, GL_TEXTURE_2D, colorAttachments[i]->id(),
                               0);
        drawBuffers.push_back(attachment);
    }
    glDrawBuffers(static_cast<GLsizei>(drawBuffers.size()), drawBuffers.data());
    const GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    if (status != GL_FRAMEBUFFER_COMPLETE) {
        glDeleteFramebuffers(1, &id_);
        throw std::runtime_error("this OpenGL cannot render to the accumulation targets "
                                 "(framebuffer status " +
                                 std::to_string(status) + ")");
    }
}

Framebuffer::~Framebuffer()
{
    if (id_ != 0)
        glDeleteFramebuffers(1, &id_);
}

Framebuffer::Framebuffer(Framebuffer&& other) noexcept : id_(std::exchange(other.id_, 0)) {}

Framebuffer& Framebuffer::operator=(Framebuffer&& other) noexcept
{
    if (this != &other) {
        if (id_ != 0)
            glDeleteFramebuffers(1, &id_);
        id_ = std::exchange(other.id_, 0);
    }
    return *this;
}

void Framebuffer::bindForDrawing() const
{
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, id_);
}

void Framebuffer::bindForReading(int index) const
{
    glBindFramebuffer(GL_READ_FRAMEBUFFER, id_);
    glReadBuffer(GL_COLOR_ATTACHMENT0 + static_cast<GLenum>(index));
}

}  // namespace gl
