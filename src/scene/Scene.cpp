#include "scene/Scene.h"

namespace scene {

bool sameCamera(const Camera& a, const Camera& b)
{
    const bool sameLens = a.lens.has_value() == b.lens.has_value() &&
                          (!a.lens || (a.lens->apertureRadius == b.lens->apertureRadius &&
                                       a.lens->focusDistance == b.lens->focusDistance));
    return a.eye == b.eye && a.target == b.target && a.up == b.up &&
           a.verticalFieldOfViewDegrees == b.verticalFieldOfViewDegrees && sameLens;
}

CameraFrame cameraFrame(const Camera& camera)
{
    // In double: target - eye, and its squared length, can overflow a float for points the
    // format accepts (a far target), though the direction is well defined.
    const glm::dvec3 forward = glm::normalize(glm::dvec3(camera.target) - glm::dvec3(camera.eye));
    const glm::dvec3 right = glm::normalize(glm::cross(forward, glm::dvec3(camera.up)));
    CameraFrame frame;
    frame.forward = glm::vec3(forward);
    frame.right = glm::vec3(right);
    frame.trueUp = glm::vec3(glm::cross(right, forward));
    return frame;
}

MaterialKind Finish::material() const
{
    if (keywordMaterial)
        return *keywordMaterial;
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
