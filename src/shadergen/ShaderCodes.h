#pragma once
// The integer codes the shaders share with the host, as #defines generated from the tables
// that define them: the kinds of primitive, CSG operator, material, pigment, environment and
// light (scene/Primitives.h, CsgOperators.h, Materials.h, Pigments.h, Environments.h,
// Lights.h), the shape interpreter's opcodes, and the settings' choices (settings/Choices.h:
// SAMPLER_*, FRESNEL_*, MASKING_*). No shader module writes a code as a number.
#include <string>

namespace shadergen {

// The instructions of the general shader's shape programs (shape_interpreter.glsl).
enum class Opcode { End, Primitive, PushFrame, PopFrame, Combine };

// "#define NAME CODE" lines, one per code.
std::string shaderCodeDefines();

}  // namespace shadergen
