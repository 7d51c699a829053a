#pragma once
#include "scene/Scene.h"

#include <optional>
#include <vector>

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

// The objects as the window's camera meets them, for ray queries on the host (the camera
// controller's pivot, and the eye kept out of walls): each polyhedron (floors, walls) as its
// half-spaces exactly, every other finite shape as its bounding sphere. A CSG union is its
// children; an intersection or difference whose bound is infinite is a child that holds it
// (the first of an intersection, the first operand of a difference). Infinite shapes that
// are not polyhedra (cones, user SDFs without a bounding radius) are left out.
struct ObjectBounds {
    std::vector<ShapeBound> spheres;  // world space, all finite
    // Each polyhedron's world-space planes (unit normal, a·p + d <= 0 solid), whose union
    // is the solid.
    std::vector<std::vector<glm::vec4>> halfSpaceUnions;
};

ObjectBounds objectBounds(const Scene& scene);

// How far along the ray (`direction` of unit length) it first enters a bound from outside
// it; none when it enters none. A bound the origin lies in (within a small tolerance) is
// passed through: the surface under an eye that stands in a bounding sphere is not that
// sphere, and a ray leaving a floor at the floor is not blocked by it.
std::optional<float> nearestBoundHit(const ObjectBounds& bounds, const glm::vec3& origin,
                                     const glm::vec3& direction);

}  // namespace scene
