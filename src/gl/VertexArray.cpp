#include "gl/VertexArray.h"

#include <utility>

namespace gl {

VertexArray::VertexArray()
{
    glGenVertexArrays(1, &id_);
}

VertexArray::~VertexArray()
{
    if (id_ != 0)
        glDeleteVertexArrays(1, &id_);
}

VertexArray::VertexArray(VertexArray&& other) noexcept : id_(std::exchange(other.id_, 0)) {}

VertexArray& VertexArray::operator=(VertexArray&& other) noexcept
{
    if (this != &other) {
        if (id_ != 0)
            glDeleteVertexArrays(1, &id_);
        id_ = std::exchange(other.id_, 0);
    }
    return *this;
}

void VertexArray::drawFullscreenTriangle() const
{
    glBindVertexArray(id_);
    glDrawArrays(GL_TRIANGLES, 0, 3);
}

}  // namespace gl
