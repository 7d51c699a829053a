#pragma once
#include "scene/Scene.h"

#include <glm/glm.hpp>

#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace shadergen {

// Tori thinner than this (minor over major radius) are not met exactly: float32 leaves their
// quartic too few digits (roots off by up to half the minor radius at 0.002, and some missed;
// at most 1.7 % of it from 0.05 to 0.1, 0.7 % from 0.1 to 0.2, and none missed, over 3000
// rays from up to 200 sizes away). Shared with the general shader (shape_interpreter.glsl).
constexpr float kThinnestExactTorus = 0.1f;

// Appends values to the shape parameters (uShapeParameters) and returns the first one's
// index.
using ShapeParameterAllocator = std::function<int(const std::vector<glm::vec4>&)>;

// The GLSL statements that replace `hit` by the first crossing of object `object`'s shape in
// (tMin, hit.t), in terms of `origin`, `direction` (unit), `tMin` and `hit` (ExactHit),
// through the functions of shaders/modules/exact_shapes.glsl, with the shape's numbers
// taken from `allocate`. Spheres, polyhedra, boxes, capped cylinders, disks, infinite cones,
// tori no thinner than kThinnestExactTorus and user SDFs whose file declares an `// @intersect` function have one, under any
// transform; every other shape none (nullopt). Both the --exact-geometry reference
// and the sphere tracer, which meets the shapes with a closed form instead of marching them,
// are written from this one description.
std::optional<std::string> exactIntersectionStatements(const scene::Shape& shape,
                                                       std::size_t object,
                                                       const ShapeParameterAllocator& allocate);

// The GLSL of exactSceneIntersect for --exact-geometry (shaders/modules/ray_queries_exact.glsl):
// every object's first crossing in closed form, through the functions of
// shaders/modules/exact_shapes.glsl, with the numbers appended to `shapeParameters`.
// Every shape exactIntersectionStatements meets has one; a scene with any other shape is
// refused with a message naming its file, line and shape.
std::string generateExactSceneIntersection(const scene::Scene& scene,
                                           std::vector<glm::vec4>& shapeParameters);

}  // namespace shadergen
