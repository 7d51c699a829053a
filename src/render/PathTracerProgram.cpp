#include "render/PathTracerProgram.h"

#include "shadergen/KindDispatchers.h"

#include <chrono>

namespace render {

namespace fs = std::filesystem;

namespace {

const char* const kVersion = "#version 330 core\n";

gl::Program compileAndTime(const std::string& vertex, const shadergen::ShaderSource& fragment,
                           double& seconds)
{
    const auto start = std::chrono::steady_clock::now();
    gl::Program program(vertex, fragment.text(), "the path tracer",
                        [&fragment](const std::string& log) { return fragment.explainLog(log); });
    seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return program;
}

}  // namespace

shadergen::ShaderSource assemblePathTracerSource(const shadergen::SceneShaderCode& code, const fs::path& shaderDirectory)
{
    const fs::path modules = shaderDirectory / "modules";
    shadergen::ShaderSource source;
    source.add("<preamble: features of the scene>", kVersion + code.defines);
    auto module = [&](const char* name) { source.addFile(modules / name, shaderDirectory); };

    const bool specialized = shadergen::specializesShapes(code.variant);
    module("constants.glsl");
    module("work_counters.glsl");
    module("rng.glsl");
    module("sampler.glsl");
    module("sampling.glsl");
    module("sdf_primitives.glsl");
    module("csg_operators.glsl");
    module("scene_data.glsl");
    module("ray_culling.glsl");
    module("exact_shapes.glsl");
    if (code.features.transforms)
        module("shape_transforms.glsl");
    if (!code.userSdfFiles.empty()) {
        module("user_sdf_api.glsl");
        for (const fs::path& file : code.userSdfFiles)
            source.addFile(file, shaderDirectory);
    }
    source.add(specialized ? "<generated: the scene's distance functions>"
                           : "<generated: user SDF dispatch>",
               code.sceneFunctions);
    if (!specialized)
        module("shape_interpreter.glsl");
    module("sphere_tracing.glsl");
    module("camera.glsl");
    module("fresnel.glsl");
    module("pigments.glsl");
    source.add("<generated: pigmentColor over the pigment kinds>", shadergen::pigmentDispatcher());
    module("materials.glsl");
    source.add("<generated: the BSDF dispatchers over the materials>", shadergen::materialDispatchers());
    module("ray_queries.glsl");
    if (code.exactGeometry) {
        source.add("<generated: the scene's exact intersections>", code.exactFunctions);
        module("ray_queries_exact.glsl");
    } else {
        module("ray_queries_traced.glsl");
    }
    module("environment.glsl");
    module("lights.glsl");
    source.add("<generated: the dispatchers over the light kinds>",
               shadergen::lightDispatchers());
    module("direct_lighting.glsl");
    module("integrator.glsl");
    module("path_tracer_main.glsl");
    return source;
}

std::string fullscreenVertexSource(const fs::path& shaderDirectory)
{
    return kVersion + shadergen::readTextFile(shaderDirectory / "modules" / "fullscreen.vert");
}

PathTracerProgram::PathTracerProgram(const shadergen::ShaderSource& fragment, const fs::path& shaderDirectory)
    : program_(compileAndTime(fullscreenVertexSource(shaderDirectory), fragment, compileSeconds_))
{
}

}  // namespace render
