#pragma once
#include "scene/Scene.h"

namespace scene {

// A sphere holding the camera, every point light, every finite shape and a point of every
// infinite one (the point of each plane nearest the camera, each cone's apex). Tolerances
// that must follow the scene's scale (hit distance floor, far distance) derive from it.
struct SceneBounds {
    glm::vec3 center{0.0f};
    float radius = 1.0f;

    // Rays that travel this far without a hit see the environment: far enough that planes
    // meet the horizon, near enough that the step limit is not spent on empty space.
    float farDistance() const { return 100.0f * radius; }
    // The smallest hit tolerance: well above float32 rounding at the scene's size.
    float minimumHitDistance() const;
};

SceneBounds computeSceneBounds(const Scene& scene);

// Bounding sphere of one shape in world space (ShapeBound: scene/Primitives.h); infinite
// shapes (planes, cones) have none.
ShapeBound boundShape(const Shape& shape);

}  // namespace scene
