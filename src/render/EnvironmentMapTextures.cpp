#include "render/EnvironmentMapTextures.h"

#include "gl/GlError.h"

#include <stdexcept>
#include <string>

namespace render {

void EnvironmentMapTextures::bind() const
{
    radiance.bind(kRadianceUnit);
    distribution.bind(kDistributionUnit);
}

EnvironmentMapTextures uploadEnvironmentMap(const EnvironmentMap& map)
{
    GLint maxSize = 0;
    glGetIntegerv(GL_MAX_TEXTURE_SIZE, &maxSize);
    if (map.cumulativeWidth() > maxSize || map.height + 1 > maxSize)
        throw std::runtime_error("an environment map of " + std::to_string(map.width) + "x" +
                                 std::to_string(map.height) +
                                 " texels is larger than this OpenGL's textures (" +
                                 std::to_string(maxSize) + " on a side)");
    EnvironmentMapTextures textures;
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    // Row 0 of the map (its top) at t = 0, where environment.glsl's v = 0 looks it up.
    textures.radiance.bind(EnvironmentMapTextures::kRadianceUnit);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, map.width, map.height, 0, GL_RGBA, GL_FLOAT,
                 map.texels.data());
    textures.radiance.setSampling(GL_LINEAR, GL_LINEAR, GL_REPEAT, GL_CLAMP_TO_EDGE);
    textures.distribution.bind(EnvironmentMapTextures::kDistributionUnit);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_R32F, map.cumulativeWidth(), map.height + 1, 0, GL_RED,
                 GL_FLOAT, map.cumulative.data());
    textures.distribution.setSampling(GL_NEAREST, GL_NEAREST, GL_CLAMP_TO_EDGE, GL_CLAMP_TO_EDGE);
    gl::throwOnGlError("uploading the environment map");
    return textures;
}

}  // namespace render
