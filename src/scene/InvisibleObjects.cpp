#include "scene/InvisibleObjects.h"

namespace scene {

bool isInvisible(const Scene& scene, const SceneObject& object)
{
    const Finish& finish = scene.finishes[object.finish];
    const Pigment& pigment = scene.pigments[object.pigment];
    return finish.material() == MaterialKind::Dielectric && finish.ior == 1.0f &&
           !finish.isEmissive() && pigment.kind == PigmentKind::Solid &&
           pigment.color == glm::vec3(1.0f);
}

Scene dropInvisibleObjects(const Scene& scene)
{
    Scene visible = scene;
    visible.objects.clear();
    for (const SceneObject& object : scene.objects)
        if (!isInvisible(scene, object))
            visible.objects.push_back(object);
    return visible;
}

}  // namespace scene
