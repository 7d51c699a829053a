#include "scene/Scene.h"

namespace scene {

bool sameCamera(const Camera& a, const Camera& b)
{
    return a.eye == b.eye && a.target == b.target && a.up == b.up &&
           a.verticalFieldOfViewDegrees == b.verticalFieldOfViewDegrees;
}

CameraFrame cameraFrame(const Camera& camera)
{
    // In double: target - eye, and its squared length, can overflow a float for points the
    // format accepts (a far target), though the direction is well defined.
    const glm::dvec3 forward =
        glm::normalize(glm::dvec3(camera.target) - glm::dvec3(camera.eye));
    const glm::dvec3 right = glm::normalize(glm::cross(forward, glm::dvec3(camera.up)));
    CameraFrame frame;
    frame.forward = glm::vec3(forward);
    frame.right = glm::vec3(right);
    frame.trueUp = glm::vec3(glm::cross(right, forward));
    return frame;
}

MaterialKind Finish::material() const
{
    if (transmission > 0.0f)
        return MaterialKind::Dielectric;
    if (reflection > 0.0f)
        return MaterialKind::Mirror;
    if (phongExponent > 0.0f)
        return MaterialKind::BlinnPhong;
    return MaterialKind::Lambertian;
}

bool Finish::isEmissive() const
{
    return emission.r > 0.0f || emission.g > 0.0f || emission.b > 0.0f;
}

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
    return glm::vec4(normal, transform.scale * localPlane.w - glm::dot(normal, transform.translation));
}

std::vector<SphereLight> sphereLights(const Scene& scene)
{
    std::vector<SphereLight> lights;
    for (std::size_t i = 0; i < scene.objects.size(); ++i) {
        const SceneObject& object = scene.objects[i];
        const auto* sphere = std::get_if<Sphere>(&object.shape.geometry);
        if (sphere == nullptr || !scene.finishes[object.finish].isEmissive())
            continue;
        SphereLight light;
        light.object = static_cast<int>(i);
        light.center = sphere->center;
        light.radius = sphere->radius;
        if (object.shape.transform) {
            light.center = applyTransform(*object.shape.transform, sphere->center);
            light.radius = object.shape.transform->scale * sphere->radius;
        }
        light.radiance = scene.finishes[object.finish].emission;
        lights.push_back(light);
    }
    return lights;
}

}  // namespace scene
