#pragma once
// An environment map's two textures (render/EnvironmentMap.h, read by
// shaders/modules/environment.glsl): the radiance with its density, filtered bilinearly,
// repeating in longitude and clamped at the poles; and the CDFs, read texel by texel.
#include "gl/Texture.h"
#include "render/EnvironmentMap.h"
#include "render/TextureUnits.h"

namespace render {

struct EnvironmentMapTextures {
    gl::Texture radiance{GL_TEXTURE_2D};
    gl::Texture distribution{GL_TEXTURE_2D};

    static constexpr int kRadianceUnit = texture_units::kEnvironmentRadiance;
    static constexpr int kDistributionUnit = texture_units::kEnvironmentDistribution;
    void bind() const;
};

// Throws std::runtime_error when the map is larger than this OpenGL's textures may be.
EnvironmentMapTextures uploadEnvironmentMap(const EnvironmentMap& map);

}  // namespace render
