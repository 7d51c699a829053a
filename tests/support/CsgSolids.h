#pragma once
// CSG solids on the CPU, in double precision, for the render tests' expectations: their exact
// distances (written from the primitives' formulas, not the renderer's code) and where a ray
// first meets them, by sphere tracing those distances.
#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>

namespace testing_support {

inline double boxDistance(const glm::dvec3& q, const glm::dvec3& halfExtents)
{
    const glm::dvec3 outside = glm::abs(q) - halfExtents;
    return glm::length(glm::max(outside, glm::dvec3(0.0))) +
           std::min(std::max(outside.x, std::max(outside.y, outside.z)), 0.0);
}

// A box resting on y = 0, scooped by a sphere from its top and drilled through along z by a
// cylinder, turned by `toLocal` (world to its frame) about the y axis: the scene's
//   rotate 0 1 0 A difference { box 0 0.6 0  1 0.6 0.7   sphere 0 1.4 0  0.8
//       translate -0.45 0.45 0 rotate 1 0 0 90 cylinder 0 0 0  0.25 1.5 }
struct DrilledScoopedBox {
    glm::dmat3 toLocal{1.0};

    static constexpr const char* kShape =
        "difference {\n box 0 0.6 0  1 0.6 0.7\n sphere 0 1.4 0  0.8\n"
        " translate -0.45 0.45 0 rotate 1 0 0 90 cylinder 0 0 0  0.25 1.5\n}";

    double distance(const glm::dvec3& world) const
    {
        const glm::dvec3 p = toLocal * world;
        const double box = boxDistance(p - glm::dvec3(0.0, 0.6, 0.0), {1.0, 0.6, 0.7});
        const double sphere = glm::length(p - glm::dvec3(0.0, 1.4, 0.0)) - 0.8;
        // The cylinder's axis, y in its own frame, is z in the box's.
        const glm::dvec3 q = p - glm::dvec3(-0.45, 0.45, 0.0);
        const double drill =
            std::max(glm::length(glm::dvec2(q.x, q.y)) - 0.25, std::abs(q.z) - 1.5);
        return std::max(box, std::max(-sphere, -drill));
    }
};

// The seed's rounded cube, a sphere of radius 1.3 and a cube of half-side 1 about `center`,
// turned by `toLocal` about that centre: intersection { sphere C 1.3  box C 1 1 1 }.
struct RoundedCube {
    glm::dvec3 center{0.0};
    glm::dmat3 toLocal{1.0};

    double distance(const glm::dvec3& world) const
    {
        const glm::dvec3 q = toLocal * (world - center);
        return std::max(glm::length(q) - 1.3, boxDistance(q, glm::dvec3(1.0)));
    }
};

// Where the ray (unit direction) first meets the solid within `limit`, by sphere tracing its
// exact distance; -1 where it does not.
template <typename Solid>
double sphereTracedCrossing(const Solid& solid, const glm::dvec3& origin,
                            const glm::dvec3& direction, double limit = 200.0)
{
    double t = 0.0;
    for (int step = 0; step < 100000 && t < limit; ++step) {
        const double d = solid.distance(origin + t * direction);
        if (d < 1e-9)
            return t;
        t += std::max(d, 1e-7);
    }
    return -1.0;
}

}  // namespace testing_support
