#pragma once
// The one preparation stage between a parsed scene and the GPU: objects that do nothing to
// light are dropped, the shader code is generated for what is left, the environment map is
// read, its numbers are packed and the path-tracing shader is assembled for a kernel. Pure (it
// reads shader and image files, never GL state): the
// renderer, `--features`, `--print-shader` and the benchmarks all prepare a scene here, so
// they all see the same visible scene, features and source.
#include "render/SceneUniforms.h"
#include "scene/Scene.h"
#include "settings/PathKernel.h"
#include "settings/RenderSettings.h"
#include "shadergen/SceneShaderGenerator.h"
#include "shadergen/ShaderSource.h"

#include <filesystem>
#include <memory>

namespace render {

struct PreparedScene {
    scene::Scene visible;             // without its invisible objects (scene/InvisibleObjects.h)
    shadergen::SceneShaderCode code;  // code.features: what the shader is built for
    SceneUniforms uniforms;           // every number the shader reads from the scene
    // The environment map, read and made ready for sampling; nullptr where there is none.
    std::shared_ptr<const EnvironmentMap> environmentMap;
    shadergen::ShaderSource pathTracerSource;  // for the kernel asked (fragment or compute)
};

// `kernel`: Fragment or Compute (the renderer chooses Automatic's in its context).
PreparedScene prepareScene(const scene::Scene& scene, const shadergen::ShaderBuild& build,
                           const std::filesystem::path& shaderDirectory,
                           settings::PathKernel kernel = settings::PathKernel::Fragment);

// The project's shaders/ folder (FileLookup::dataDirectory()).
std::filesystem::path defaultShaderDirectory();

}  // namespace render
