#pragma once
// The shaders' dispatchers over material and pigment kinds, generated from the kinds' tables
// (scene/Materials.h, scene/Pigments.h), so that a new kind is a row there and its GLSL
// functions, never a case kept in step by hand. Each kind other than the fallback (the
// first row, in every shader) is compiled in only where its feature switch is 1.
#include <string>

namespace shadergen {

// isDeltaMaterial, bsdfEvaluate, bsdfPdf and bsdfSample over every material: GLSL to follow
// shaders/modules/materials.glsl, which defines each material's functions.
std::string materialDispatchers();

// pigmentColor over every pigment kind: GLSL to follow shaders/modules/pigments.glsl.
std::string pigmentDispatcher();

}  // namespace shadergen
