#pragma once
#include "scene/Scene.h"

#include <glm/glm.hpp>

#include <string>
#include <vector>

namespace render {

// The GLSL of exactSceneIntersect for --exact-geometry (shaders/modules/ray_queries_exact.glsl):
// every object's first crossing in closed form, through the functions of
// shaders/modules/exact_shapes.glsl, with the numbers appended to `shapeParameters`.
// Spheres, polyhedra, boxes, capped cylinders and disks have one, under any transform; a
// scene with any other shape is refused with a message naming its file, line and shape.
std::string generateExactSceneIntersection(const scene::Scene& scene,
                                           std::vector<glm::vec4>& shapeParameters);

}  // namespace render
