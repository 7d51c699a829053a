#pragma once
// What the tables of kinds share (primitives, CSG operators, materials, pigments,
// environments): a kind's code is its place in its table, and the shaders know each code
// only by a #define generated from the table (shadergen/ShaderCodes.h), never by a number
// copied into GLSL.
#include <string>

namespace scene {

// The shaders' name for a kind: the prefix, then the identifier in capitals with words split
// by '_': ("MATERIAL_", "BlinnPhong") -> "MATERIAL_BLINN_PHONG".
std::string codeName(const std::string& prefix, const std::string& identifier);

}  // namespace scene
