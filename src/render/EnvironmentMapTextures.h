#pragma once
// An environment map's two textures (render/EnvironmentMap.h, read by
// shaders/modules/environment.glsl): the radiance with its density, filtered bilinearly,
// repeating in longitude and clamped at the poles; and the CDFs, read texel by texel.
#include "gl/Texture.h"
#include "render/EnvironmentMap.h"

namespace render {

struct EnvironmentMapTextures {
    gl::Texture radiance{GL_TEXTURE_2D};
    gl::Texture distribution{GL_TEXTURE_2D};

    // The texture units the path tracer binds them to.
    static constexpr int kRadianceUnit = 5;
    static constexpr int kDistributionUnit = 6;
    void bind() const;
};

// Throws std::runtime_error when the map is larger than this OpenGL's textures may be.
EnvironmentMapTextures uploadEnvironmentMap(const EnvironmentMap& map);

}  // namespace render
