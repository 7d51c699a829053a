#pragma once
// The path tracer's uniforms as the shader declares them, written from their descriptions
// (settings/Options.def for the settings, render/SceneUniforms.cpp for the scene's values,
// shadergen/SceneRecords.h for the record arrays) into one generated piece of the shader
// that precedes every module. The modules declare none of these themselves.
//
// Read once per pixel. llvmpipe reads a uniform with one load for all pixels of a SIMD group
// only where every pixel of the group is known to run (outside every branch and loop that
// some pixel may have left); elsewhere it gathers it pixel by pixel, with a bounds check, as
// if its index varied. Nearly all of a path's work runs inside such loops, so every uniform
// it read there was gathered at every use. So main() first calls readUniformsOnce(), which
// copies each uniform uX into a global gX, and the modules read gX (scene 6: 1.16x for the
// shape parameters alone, scene 1: 1.11x for its light's record; docs/PERFORMANCE.md).
// Copies of arrays are made element by element (a whole-array assignment is propagated back
// to the uniform by the compiler); arrays read at indices that vary are left alone, as their
// copies would be gathered too: the shape parameters are copied only where the generated
// code reads them at constant indices (SHAPE_PARAMETERS names the array to read), a record
// table only where it holds one record (its RECORD macro names the array).
#include <string>
#include <vector>

namespace shadergen {

// One uniform that is not an array: its copy is what the modules read.
struct UniformDeclaration {
    std::string glslType;    // "float", "vec3", ...
    std::string name;        // "uHitTolerance"
    std::string copy;        // "gHitTolerance"
    std::string module;      // the module that reads it: declared where that module is used
    std::string guard = "";  // a define it is declared under (#if guard); empty: none
};

// The settings the shader reads (settings/Options.def's rows with .uniform).
std::vector<UniformDeclaration> settingUniformDeclarations();

// The piece for a shader of `modules` (file names, "sphere_tracing.glsl"): the declarations
// of `scalars` whose module is among them, the shape parameters, the record tables and
// their accessors, and readUniformsOnce(). With the general shader's interpreter among the
// modules, the shape parameters and the object records are read from buffer textures.
std::string uniformBlock(const std::vector<UniformDeclaration>& scalars,
                         const std::vector<std::string>& modules);

}  // namespace shadergen
