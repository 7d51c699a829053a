#pragma once
// The general shader's scene data in buffer textures, on texture units 7 to 11: everything of
// the scene's that grows with its objects (shape parameters, shape programs, object records,
// the hierarchy over the objects), which uniform arrays cannot hold beyond a few thousand
// vec4s (the link fails: "too many fragment shader default uniform block components").
// shape_interpreter.glsl says what each holds.
#include "gl/TextureBuffer.h"
#include "render/SceneUniforms.h"
#include "render/TextureUnits.h"
#include "shadergen/SceneShaderGenerator.h"

#include <cstddef>

namespace render {

class ProgramUniforms;

class SceneDataBuffers {
public:
    static constexpr int kShapeParametersUnit = texture_units::kShapeParameters;
    static constexpr int kShapeProgramUnit = texture_units::kShapeProgram;
    static constexpr int kObjectRecordsUnit = texture_units::kObjectRecords;
    static constexpr int kHierarchyBoxesUnit = texture_units::kHierarchyBoxes;
    static constexpr int kHierarchyLinksUnit = texture_units::kHierarchyLinks;

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
