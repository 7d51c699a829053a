#pragma once
// Exact ray intersection of CSG solids whose operators are sharp (union, intersection,
// difference) and whose leaves have a closed form (shadergen/ExactSceneIntersection.h): the
// --exact-geometry reference for CSG solids, which every render marches. The surface of such
// a solid lies on its leaves' surfaces, so along a ray it can only be crossed where some leaf
// is; between two consecutive leaf crossings the ray is wholly inside the solid or wholly
// outside it. The crossing walk visits the leaves' crossings in order (each leaf's exact
// first crossing beyond the last one), classifies each stretch between them by the sign of
// the solid's distance at its middle, and stops at the first crossing where the class
// changes: the point-membership classification of ray casting for solids (Roth, "Ray casting
// for modeling solids", 1982), with each leaf's exact intersection in place of its span list.
// The normal is the crossed leaf's, turned to point out of the solid.
#include "scene/Scene.h"
#include "shadergen/ExactSceneIntersection.h"

#include <glm/glm.hpp>

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace shadergen {

struct ExactCsgCode {
    std::string functions;   // GLSL functions, to stand before exactSceneIntersect
    std::string statements;  // as exactIntersectionStatements's: they replace `hit`
};

// The GLSL that meets object `object`'s shape, a CSG solid (under any transforms), exactly:
// its crossing walk, its leaves' crossings and its inside test, with the numbers appended to
// `parameters`. nullopt where the shape is no CSG block, or where some node is a smoothed
// operator (whose surface lies on no leaf's) or some leaf has no closed form or no inside (a
// disk).
std::optional<ExactCsgCode> exactCsgIntersection(const scene::Shape& shape, std::size_t object,
                                                 std::vector<glm::vec4>& parameters);

}  // namespace shadergen
