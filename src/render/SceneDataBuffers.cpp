#include "render/SceneDataBuffers.h"

#include "render/ProgramUniforms.h"

#include <glm/glm.hpp>

#include <vector>

namespace render {

namespace {

// A buffer texture of `texels`, at least one texel (an empty buffer texture reads as
// incomplete on some drivers).
template <typename Texel>
gl::TextureBuffer upload(GLenum format, std::vector<Texel> texels)
{
    if (texels.empty())
        texels.emplace_back(0);
    return gl::TextureBuffer(format, texels.data(), texels.size(), sizeof(Texel));
}

std::vector<glm::vec4> boxesOf(const SceneUniforms& uniforms,
                               const shadergen::SceneShaderCode& code)
{
    // Per object its bounding sphere, then the nodes' corners (HIERARCHY_BOXES_START).
    std::vector<glm::vec4> boxes = code.objectBounds;
    boxes.insert(boxes.end(), uniforms.hierarchyBoxes.begin(), uniforms.hierarchyBoxes.end());
    return boxes;
}

}  // namespace

SceneDataBuffers::SceneDataBuffers(const SceneUniforms& uniforms,
                                   const shadergen::SceneShaderCode& code)
    : shapeParameters_(upload(GL_RGBA32F, code.shapeParameters)),
      shapeProgram_(upload(GL_RGBA32I, code.shapeProgram)),
      objectRecords_(upload(GL_RGBA32I, uniforms.objects)),
      hierarchyBoxes_(upload(GL_RGBA32F, boxesOf(uniforms, code))),
      hierarchyLinks_(upload(GL_RGBA32I, uniforms.hierarchyLinks))
{
}

void SceneDataBuffers::bind() const
{
    shapeParameters_.bind(kShapeParametersUnit);
    shapeProgram_.bind(kShapeProgramUnit);
    objectRecords_.bind(kObjectRecordsUnit);
    hierarchyBoxes_.bind(kHierarchyBoxesUnit);
    hierarchyLinks_.bind(kHierarchyLinksUnit);
}

void SceneDataBuffers::setSamplers(ProgramUniforms& program)
{
    program.set("uShapeParameterBuffer", kShapeParametersUnit);
    program.set("uShapeProgram", kShapeProgramUnit);
    program.set("uObjectRecords", kObjectRecordsUnit);
    program.set("uHierarchyBoxes", kHierarchyBoxesUnit);
    program.set("uHierarchyLinks", kHierarchyLinksUnit);
}

std::size_t SceneDataBuffers::bytes() const
{
    return shapeParameters_.bytes() + shapeProgram_.bytes() + objectRecords_.bytes() +
           hierarchyBoxes_.bytes() + hierarchyLinks_.bytes();
}

}  // namespace render
