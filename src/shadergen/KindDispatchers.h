#pragma once
// The shaders' dispatchers over material, pigment and light kinds, generated from the kinds'
// tables (scene/Materials.h, scene/Pigments.h, scene/Lights.h), so that a new kind is a row
// there and its GLSL functions, never a case kept in step by hand. Each kind other than a
// fallback (the first row of materials and pigments, in every shader) is compiled in only
// where its feature switch is 1.
#include <string>

namespace shadergen {

// isDeltaMaterial, bsdfEvaluate, bsdfPdf and bsdfSample over every material: GLSL to follow
// shaders/modules/materials.glsl, which defines each material's functions.
std::string materialDispatchers();

// pigmentColor over every pigment kind: GLSL to follow shaders/modules/pigments.glsl.
std::string pigmentDispatcher();

// lightSample over every light kind and lightPdf over those that are no delta: GLSL to follow
// shaders/modules/lights.glsl, which defines each kind's functions.
std::string lightDispatchers();

}  // namespace shadergen
