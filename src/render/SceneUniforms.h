#pragma once
#include "render/EnvironmentMap.h"
#include "scene/Scene.h"
#include "scene/SceneBounds.h"
#include "settings/OptionValues.h"
#include "settings/RenderSettings.h"
#include "shadergen/SceneShaderGenerator.h"
#include "shadergen/UniformBlock.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <filesystem>
#include <functional>
#include <vector>

namespace render {

class ProgramUniforms;

// The scene's numbers laid out as the shader's uniform arrays (the records' layouts are
// shadergen/SceneRecords.h's). Built from the scene on the CPU; uploaded without recompiling.
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

    // The general shader's hierarchy over the objects (shadergen/ObjectHierarchy.h), laid out
    // as its buffer textures hold it (shape_interpreter.glsl, render/SceneDataBuffers.h);
    // empty for a shader with specialised shapes.
    std::vector<glm::vec4> hierarchyBoxes;   // per node, its box's lower and upper corner
    std::vector<glm::ivec4> hierarchyLinks;  // the objects' list, four a texel, then per node
    double hierarchySeconds = 0.0;           // what building it took (not compared)

    // Every number equal: uploading the one in place of the other changes nothing.
    bool operator==(const SceneUniforms& other) const;
    bool operator!=(const SceneUniforms& other) const { return !(*this == other); }
};

// `environmentMap`: the scene's map (render/EnvironmentMap.h), whose power its light's
// selection probability needs; nullptr where the scene has none.
SceneUniforms packSceneUniforms(const scene::Scene& scene, const shadergen::SceneShaderCode& code,
                                const EnvironmentMap* environmentMap = nullptr);

// Called now and then while the scene is prepared (the hierarchy's build): it may throw to
// abandon the set-up (the program's interrupt, app/RenderCommand.cpp). None by default.
void setSetUpCheckpoint(std::function<void()> checkpoint);
const std::function<void()>& setUpCheckpoint();

// What the uniforms' values come from.
struct UniformSources {
    const SceneUniforms& scene;
    const settings::RenderSettings& settings;
    int width = 0;
    int height = 0;
    float pigmentTextureSize = 0.0f;  // texels along the larger side of a texture layer
};

// A value of the scene's (or of the image's) that the shader reads as a uniform: its
// declaration and where its value comes from.
struct SceneValueUniform {
    shadergen::UniformDeclaration declaration;
    std::function<settings::UniformValue(const UniformSources&)> value;
};
const std::vector<SceneValueUniform>& sceneValueUniforms();

// Every uniform the generated block declares that is not an array: the settings' and the
// scene's values.
std::vector<shadergen::UniformDeclaration> pathTracerUniformDeclarations();

// Sets every scene and settings uniform the program declares (it must be in use): the
// arrays, the records and every value above.
void uploadUniforms(ProgramUniforms& program, const UniformSources& sources,
                    const shadergen::SceneShaderCode& code);

}  // namespace render
