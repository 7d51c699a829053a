#pragma once
#include "gl/Shader.h"
#include "shadergen/SceneShaderGenerator.h"
#include "shadergen/ShaderSource.h"

#include <filesystem>
#include <string>

namespace render {

// Assembles the path-tracing fragment shader for a scene from the modules in
// shaders/modules/ (only those its features need), the scene's user SDF files and the
// generated scene code; see assemblePathTracerSource for the order.
shadergen::ShaderSource assemblePathTracerSource(const shadergen::SceneShaderCode& code,
                                      const std::filesystem::path& shaderDirectory);

// The vertex shader every pass uses: one triangle over the viewport.
std::string fullscreenVertexSource(const std::filesystem::path& shaderDirectory);

// The compiled path-tracing program with the source it came from.
class PathTracerProgram {
public:
    // `fragment` as render/ScenePreparation assembles it.
    PathTracerProgram(const shadergen::ShaderSource& fragment, const std::filesystem::path& shaderDirectory);

    const gl::Program& program() const { return program_; }
    double compileSeconds() const { return compileSeconds_; }

private:
    // Declared first: the program's initialiser measures into it.
    double compileSeconds_ = 0.0;
    gl::Program program_;
};

}  // namespace render
