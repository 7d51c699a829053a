#pragma once
#include <glm/glm.hpp>

namespace scene {

// A similarity transform: world = rotation * (scale * local) + translation.
struct Transform {
    glm::mat3 rotation{1.0f};
    glm::vec3 translation{0.0f};
    float scale = 1.0f;
};

// The transform that applies `inner` first, then `outer`.
Transform compose(const Transform& outer, const Transform& inner);
glm::vec3 applyTransform(const Transform& transform, const glm::vec3& local);
// A plane dot(n, x) + w = 0 (unit n) of a shape's local space, in world space: n' = R n,
// w' = s w - dot(n', T).
glm::vec4 applyTransformToPlane(const Transform& transform, const glm::vec4& localPlane);

}  // namespace scene
