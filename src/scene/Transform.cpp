#include "scene/Transform.h"

namespace scene {

Transform compose(const Transform& outer, const Transform& inner)
{
    Transform result;
    result.rotation = outer.rotation * inner.rotation;
    result.scale = outer.scale * inner.scale;
    result.translation = applyTransform(outer, inner.translation);
    return result;
}

glm::vec3 applyTransform(const Transform& transform, const glm::vec3& local)
{
    return transform.rotation * (transform.scale * local) + transform.translation;
}

glm::vec4 applyTransformToPlane(const Transform& transform, const glm::vec4& localPlane)
{
    const glm::vec3 normal = transform.rotation * glm::vec3(localPlane);
    return glm::vec4(normal,
                     transform.scale * localPlane.w - glm::dot(normal, transform.translation));
}

}  // namespace scene
