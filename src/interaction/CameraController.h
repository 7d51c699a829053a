#pragma once
#include "scene/Scene.h"

#include <glm/glm.hpp>

namespace interaction {

// Camera navigation in the window, in plain values: drags, wheel steps and held keys in,
// a scene::Camera out. The up vector stays the scene file's (the horizon never rolls), the
// target is what the camera orbits and dollies towards, and distances moved without a
// target to refer to (flying) follow the scene's size.
class CameraController {
public:
    // `home`: the scene file's camera. `sceneRadius`: the radius of the scene's bounds
    // (scene::computeSceneBounds).
    CameraController(const scene::Camera& home, float sceneRadius);

    const scene::Camera& camera() const { return camera_; }
    const scene::Camera& home() const { return home_; }

    // Left drag. A drag the height of the viewport turns the eye half a turn around the
    // target: right turns it to the left about the up vector (the scene turns with the
    // mouse), down raises it towards the up vector. The eye stops short of looking straight
    // along the up vector, where the view would flip.
    void orbit(glm::vec2 dragPixels, float viewportHeightPixels);
    // Right or middle drag: eye and target move across the view so that a point at the
    // target's distance stays under the mouse.
    void pan(glm::vec2 dragPixels, float viewportHeightPixels);
    // Wheel: each step up takes the eye 15% of its distance towards the target (down: away).
    // The eye never reaches the target.
    void dolly(float wheelSteps);
    // W A S D Q E: `direction` in the view's terms (x right, y along the up vector, z
    // forward), each component -1, 0 or 1, held for `seconds`. The speed is half the scene's
    // radius per second, five times that when `fast` (Shift).
    void fly(glm::vec3 direction, float seconds, bool fast);
    // R: back to the scene file's camera.
    void returnHome();

    // The scene file was read again. Its camera becomes home; the camera in use becomes it
    // too when `replaceCurrent` (the file's camera lines changed), else stays where the
    // user put it.
    void setHome(const scene::Camera& home, float sceneRadius, bool replaceCurrent);

    // Speeds and limits, in scene radii per second and in fractions.
    static constexpr float kFlySpeed = 0.5f;
    static constexpr float kFastFactor = 5.0f;
    static constexpr float kDollyStep = 0.15f;

private:
    scene::Camera home_;
    scene::Camera camera_;
    float sceneRadius_;
};

}  // namespace interaction
