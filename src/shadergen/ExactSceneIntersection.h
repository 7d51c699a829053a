#pragma once
#include "scene/Scene.h"

#include <glm/glm.hpp>

#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace shadergen {

// Appends values to the shape parameters (uShapeParameters) and returns the first one's
// index.
using ShapeParameterAllocator = std::function<int(const std::vector<glm::vec4>&)>;

// The GLSL statements that replace `hit` by the first crossing of object `object`'s shape in
// (tMin, hit.t), in terms of `origin`, `direction` (unit), `tMin` and `hit` (ExactHit),
// through the functions of shaders/modules/exact_shapes.glsl, with the shape's numbers
// taken from `allocate`: for the primitives whose description has an exact intersection
// (scene/Primitives.h, within its limits) and user SDFs whose file declares an
// `// @intersect` function, under any transform; every other shape none (nullopt). Both the
// --exact-geometry reference and the sphere tracer, which meets the shapes with a closed
// form instead of marching them, are written from this one description.
std::optional<std::string> exactIntersectionStatements(const scene::Shape& shape,
                                                       std::size_t object,
                                                       const ShapeParameterAllocator& allocate);

// The GLSL of exactSceneIntersect for --exact-geometry (shaders/modules/ray_queries_exact.glsl):
// every object's first crossing in closed form, through the functions of
// shaders/modules/exact_shapes.glsl, with the numbers appended to `shapeParameters`.
// Every shape exactIntersectionStatements meets has one, and so has every sharp CSG block of
// such shapes (shadergen/ExactCsgIntersection.h); a scene with any other shape is refused
// with a message naming its file, line and shape.
std::string generateExactSceneIntersection(const scene::Scene& scene,
                                           std::vector<glm::vec4>& shapeParameters);

}  // namespace shadergen
