#pragma once
// The specialised shader's scene, written from its plan (shadergen/SceneShaderPlan.h): the
// objects' distance functions, the union of the objects in full and culled forms, the exact
// intersection of the objects met exactly, and the per-ray culling.
#include "shadergen/SceneShaderPlan.h"

#include <string>

namespace shadergen {

// `shapeFunctions`: the objects' distance functions the plan names.
std::string specializedSceneFunctions(const ScenePlan& plan, const std::string& shapeFunctions);

}  // namespace shadergen
