#pragma once
#include "gl/Shader.h"
#include "gl/VertexArray.h"
#include "render/AccumulationTargets.h"
#include "render/KernelChoice.h"
#include "render/ProgramUniforms.h"
#include "settings/PathKernel.h"
#include "shadergen/SceneShaderGenerator.h"
#include "shadergen/ShaderSource.h"

#include <filesystem>
#include <string>

namespace render {

// Assembles the path-tracing shader for a scene and a kernel (Fragment or Compute) from the
// modules in shaders/modules/ (only those its features need), the scene's user SDF files and
// the generated scene code, ending with the kernel's entry module; see
// assemblePathTracerSource for the order.
shadergen::ShaderSource
assemblePathTracerSource(const shadergen::SceneShaderCode& code,
                         const std::filesystem::path& shaderDirectory,
                         settings::PathKernel kernel = settings::PathKernel::Fragment);

// The vertex shader every pass uses: one triangle over the viewport.
std::string fullscreenVertexSource(const std::filesystem::path& shaderDirectory);

// A rectangle of pixels, from the image's lower-left corner.
struct PixelRegion {
    int x = 0;
    int y = 0;
    int width = 0;
    int height = 0;
};

// The compiled path-tracing program of one kernel, with the source it came from.
class PathTracerProgram {
public:
    // `source` as render/ScenePreparation assembles it for `kernel` (Fragment or Compute).
    PathTracerProgram(const shadergen::ShaderSource& source, settings::PathKernel kernel,
                      const std::filesystem::path& shaderDirectory);
    // uniforms() refers to program_: the two stay together.
    PathTracerProgram(const PathTracerProgram&) = delete;
    PathTracerProgram& operator=(const PathTracerProgram&) = delete;

    settings::PathKernel kernel() const { return kernel_; }
    const gl::Program& program() const { return program_; }
    // Its uniforms, set by name and checked against the source's declarations.
    ProgramUniforms& uniforms() { return uniforms_; }
    double compileSeconds() const { return compileSeconds_; }

    // Runs the program (in use, its uniforms set and its textures bound) over `region` of an
    // image of `imageWidth` x `imageHeight`, writing `destination`; the pixels outside the
    // region are left as they are. Returns once the GPU has been given the work (glFinish to
    // wait for it); what it wrote is then visible to textures, framebuffers and read-backs.
    void trace(const AccumulationTargets::Set& destination, const PixelRegion& region,
               int imageWidth, int imageHeight, const gl::VertexArray& triangle);

private:
    settings::PathKernel kernel_;
    // Declared before the program: the program's initialiser measures into it.
    double compileSeconds_ = 0.0;
    gl::Program program_;
    ProgramUniforms uniforms_;
};

}  // namespace render
