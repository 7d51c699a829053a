#pragma once
#include "gl/EntryPoints.h"

namespace gl {

// An empty vertex array object: core profiles need one bound to draw, even when the vertex
// shader makes its vertices from gl_VertexID. Move-only.
class VertexArray {
public:
    VertexArray();
    ~VertexArray();
    VertexArray(VertexArray&& other) noexcept;
    VertexArray& operator=(VertexArray&& other) noexcept;
    VertexArray(const VertexArray&) = delete;
    VertexArray& operator=(const VertexArray&) = delete;

    // Draws the one triangle that covers the viewport.
    void drawFullscreenTriangle() const;

private:
    GLuint id_ = 0;
};

}  // namespace gl
