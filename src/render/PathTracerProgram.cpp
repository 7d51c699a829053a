#include "render/PathTracerProgram.h"

#include "render/SceneUniforms.h"
#include "shadergen/KindDispatchers.h"
#include "shadergen/UniformBlock.h"

#include <chrono>
#include <stdexcept>
#include <utility>
#include <vector>

namespace render {

namespace fs = std::filesystem;
using settings::PathKernel;

namespace {

const char* const kFragmentVersion = "#version 330 core\n";
const char* const kComputeVersion = "#version 430 core\n";

// The compute kernel's work group: 8 x 8 pixels, two 32-wide warps on NVIDIA, a square so
// that neighbouring paths, which tend to take alike branches, share it.
constexpr int kComputeGroupWidth = 8;
constexpr int kComputeGroupHeight = 8;

std::string computePreamble()
{
    return std::string(kComputeVersion) + "#define COMPUTE_GROUP_WIDTH " +
           std::to_string(kComputeGroupWidth) + "\n" + "#define COMPUTE_GROUP_HEIGHT " +
           std::to_string(kComputeGroupHeight) + "\n";
}

gl::Program compileAndTime(PathKernel kernel, const shadergen::ShaderSource& source,
                           const fs::path& shaderDirectory, double& seconds)
{
    const auto start = std::chrono::steady_clock::now();
    const auto explain = [&source](const std::string& log) { return source.explainLog(log); };
    gl::Program program = kernel == PathKernel::Compute
                              ? gl::Program::compute(source.text(), "the path tracer", explain)
                              : gl::Program(fullscreenVertexSource(shaderDirectory), source.text(),
                                            "the path tracer", explain);
    seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return program;
}

int groupsCovering(int pixels, int groupSide)
{
    return (pixels + groupSide - 1) / groupSide;
}

}  // namespace

shadergen::ShaderSource assemblePathTracerSource(const shadergen::SceneShaderCode& code,
                                                 const fs::path& shaderDirectory, PathKernel kernel)
{
    if (kernel == PathKernel::Automatic)
        throw std::invalid_argument("assemblePathTracerSource needs a kernel chosen");
    const fs::path modules = shaderDirectory / "modules";
    const bool compute = kernel == PathKernel::Compute;
    // The pieces after the preamble and the uniforms, in order; the uniforms are written
    // for the modules among them.
    std::vector<std::pair<std::string, std::string>> pieces;
    std::vector<std::string> moduleNames;
    auto module = [&](const char* name) {
        moduleNames.push_back(name);
        pieces.emplace_back("", (modules / name).string());
    };
    auto file = [&](const fs::path& path) { pieces.emplace_back("", path.string()); };
    auto generated = [&](std::string name, std::string text) {
        pieces.emplace_back(std::move(name), std::move(text));
    };

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
        for (const fs::path& userFile : code.userSdfFiles)
            file(userFile);
    }
    generated(specialized ? "<generated: the scene's distance functions>"
                          : "<generated: user SDF dispatch>",
              code.sceneFunctions);
    if (!specialized)
        module("shape_interpreter.glsl");
    module("sphere_tracing.glsl");
    module("camera.glsl");
    module("fresnel.glsl");
    module("ggx_albedo_table.glsl");
    module("microfacet.glsl");
    module("pigments.glsl");
    generated("<generated: pigmentColor over the pigment kinds>", shadergen::pigmentDispatcher());
    module("materials.glsl");
    generated("<generated: the BSDF dispatchers over the materials>",
              shadergen::materialDispatchers());
    module("ray_queries.glsl");
    if (code.exactGeometry) {
        module("exact_csg.glsl");
        generated("<generated: the scene's exact intersections>", code.exactFunctions);
        module("ray_queries_exact.glsl");
    } else {
        module("ray_queries_traced.glsl");
    }
    module("environment.glsl");
    module("lights.glsl");
    generated("<generated: the dispatchers over the light kinds>", shadergen::lightDispatchers());
    module("direct_lighting.glsl");
    module("integrator.glsl");
    module("path_tracer_main.glsl");
    module(compute ? "compute_kernel.glsl" : "fragment_kernel.glsl");

    shadergen::ShaderSource source;
    source.add("<preamble: features of the scene>",
               (compute ? computePreamble() : std::string(kFragmentVersion)) + code.defines);
    source.add("<generated: the uniforms, read once per pixel>",
               shadergen::uniformBlock(pathTracerUniformDeclarations(), moduleNames));
    for (const auto& [name, text] : pieces) {
        if (name.empty())
            source.addFile(text, shaderDirectory);
        else
            source.add(name, text);
    }
    return source;
}

std::string fullscreenVertexSource(const fs::path& shaderDirectory)
{
    return kFragmentVersion +
           shadergen::readTextFile(shaderDirectory / "modules" / "fullscreen.vert");
}

PathTracerProgram::PathTracerProgram(const shadergen::ShaderSource& source, PathKernel kernel,
                                     const fs::path& shaderDirectory)
    : kernel_(kernel),
      program_(compileAndTime(kernel, source, shaderDirectory, compileSeconds_)),
      uniforms_(program_, shadergen::declaredUniforms(source))
{
}

void PathTracerProgram::trace(const AccumulationTargets::Set& destination,
                              const PixelRegion& region, int imageWidth, int imageHeight,
                              const gl::VertexArray& triangle)
{
    if (kernel_ == PathKernel::Compute) {
        uniforms_.set("uRegion", glm::ivec4(region.x, region.y, region.width, region.height));
        glBindImageTexture(0, destination.estimate.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
        glBindImageTexture(1, destination.moments.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
        if (destination.albedoDepth) {
            glBindImageTexture(2, destination.albedoDepth->id(), 0, GL_FALSE, 0, GL_WRITE_ONLY,
                               GL_RGBA32F);
            glBindImageTexture(3, destination.normalCoverage->id(), 0, GL_FALSE, 0, GL_WRITE_ONLY,
                               GL_RGBA32F);
        }
        glDispatchCompute(static_cast<GLuint>(groupsCovering(region.width, kComputeGroupWidth)),
                          static_cast<GLuint>(groupsCovering(region.height, kComputeGroupHeight)),
                          1);
        // Image stores are not ordered with what reads the targets next: the next frame's
        // texel fetches, the tone map's, clears and read-backs through framebuffers.
        glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_FRAMEBUFFER_BARRIER_BIT |
                        GL_TEXTURE_UPDATE_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
        return;
    }
    destination.framebuffer.bindForDrawing();
    // The viewport stays the whole image so gl_FragCoord is the pixel; the scissor picks
    // the region.
    glViewport(0, 0, imageWidth, imageHeight);
    glEnable(GL_SCISSOR_TEST);
    glScissor(region.x, region.y, region.width, region.height);
    triangle.drawFullscreenTriangle();
    glDisable(GL_SCISSOR_TEST);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

}  // namespace render
