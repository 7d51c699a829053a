#pragma once
// The general shader's scene (`--no-specialize`): every object's shape as a program of
// instructions, run by shape_interpreter.glsl, and the generated switches that interpreter
// calls: over the primitive kinds, the CSG operators and the scene's user SDFs.
#include "scene/Scene.h"
#include "shadergen/ShapeCompiler.h"

#include <glm/glm.hpp>

#include <string>
#include <vector>

namespace shadergen {

struct InterpretedScene {
    std::vector<int> objectProgramStart;  // per object
    std::vector<glm::vec4> objectBounds;  // per object, radius < 0 for none
    std::string functions;                // callUserSdf, primitiveDistance, combine
};

// Appends each object's program, ended by Opcode::End, through `compiler`. `onlyKindsUsed`:
// the switches over the primitive kinds have a branch for the scene's kinds alone (a shader
// whose features are specialised: half the general shader's compile for spheres on a
// plane); otherwise for every kind.
InterpretedScene interpretedScene(const scene::Scene& scene, ShapeCompiler& compiler,
                                  bool onlyKindsUsed = false);

}  // namespace shadergen
