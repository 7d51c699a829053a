#pragma once
// The general shader's scene data in buffer textures, on texture units 7 to 11: everything of
// the scene's that grows with its objects (shape parameters, shape programs, object records,
// the hierarchy over the objects), which uniform arrays cannot hold beyond a few thousand
// vec4s (the link fails: "too many fragment shader default uniform block components").
// shape_interpreter.glsl says what each holds.
#include "gl/TextureBuffer.h"
#include "render/SceneUniforms.h"
#include "shadergen/SceneShaderGenerator.h"

#include <cstddef>

namespace render {

class ProgramUniforms;

class SceneDataBuffers {
public:
    static constexpr int kShapeParametersUnit = 7;
    static constexpr int kShapeProgramUnit = 8;
    static constexpr int kObjectRecordsUnit = 9;
    static constexpr int kHierarchyBoxesUnit = 10;
    static constexpr int kHierarchyLinksUnit = 11;

    SceneDataBuffers(const SceneUniforms& uniforms, const shadergen::SceneShaderCode& code);

    void bind() const;
    // Points the shader's samplers at their units (the program in use).
    static void setSamplers(ProgramUniforms& program);
    // What they take on the GPU.
    std::size_t bytes() const;

private:
    gl::TextureBuffer shapeParameters_;
    gl::TextureBuffer shapeProgram_;
    gl::TextureBuffer objectRecords_;
    gl::TextureBuffer hierarchyBoxes_;
    gl::TextureBuffer hierarchyLinks_;
};

}  // namespace render
