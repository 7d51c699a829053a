#pragma once
#include "render/EnvironmentMap.h"
#include "settings/RenderSettings.h"
#include "shadergen/SceneShaderGenerator.h"
#include "scene/Scene.h"
#include "scene/SceneBounds.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <filesystem>
#include <vector>

namespace gl {
class Program;
}

namespace render {

// The scene's numbers laid out as the shader's uniform arrays (shaders/modules/scene_data.glsl
// documents each record). Built from the scene on the CPU; uploaded without recompiling.
struct SceneUniforms {
    std::vector<glm::ivec4> objects;
    std::vector<glm::vec4> pigments;
    std::vector<glm::vec4> finishes;
    // Per finish, the rough conductor's complex index of refraction (scene_data.glsl).
    std::vector<glm::vec4> conductors;
    std::vector<glm::vec4> lights;
    // The culling bits of the lights that are objects and have one (scene_data.glsl).
    std::uint32_t sphereLightPieces = 0;
    // Image files in texture-array layer order; pigments refer to them by layer.
    std::vector<std::filesystem::path> textureLayers;

    scene::CameraFrame cameraFrame;
    glm::vec3 cameraEye{0.0f};
    float tanHalfFovy = 1.0f;
    scene::ThinLens lens;  // aperture radius 0: a pinhole
    scene::SceneBounds bounds;
    scene::Environment environment;

    // Every number equal: uploading the one in place of the other changes nothing.
    bool operator==(const SceneUniforms& other) const;
    bool operator!=(const SceneUniforms& other) const { return !(*this == other); }
};

// `environmentMap`: the scene's map (render/EnvironmentMap.h), whose power its light's
// selection probability needs; nullptr where the scene has none.
SceneUniforms packSceneUniforms(const scene::Scene& scene, const shadergen::SceneShaderCode& code,
                                const EnvironmentMap* environmentMap = nullptr);

// Sets every scene and settings uniform of `program` (which must be in use).
void uploadUniforms(const gl::Program& program, const SceneUniforms& uniforms,
                    const shadergen::SceneShaderCode& code, const settings::RenderSettings& settings, int width,
                    int height);

}  // namespace render
