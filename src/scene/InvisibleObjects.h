#pragma once
#include "scene/Scene.h"

namespace scene {

// True for an object light passes as if it were not there: a clear (white, solid pigment)
// dielectric of index exactly 1 that does not emit. Between equal indices there is no
// interface: no reflection, no refraction, no tint.
bool isInvisible(const Scene& scene, const SceneObject& object);

// The scene without its invisible objects: exactly the same image, without tracing the
// surfaces of objects that do nothing (and without the contact problems of rays stepping
// through them where they touch other objects).
Scene dropInvisibleObjects(const Scene& scene);

}  // namespace scene
