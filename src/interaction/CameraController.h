#pragma once
#include "scene/Scene.h"
#include "scene/SceneBounds.h"

#include <glm/glm.hpp>

#include <optional>

namespace interaction {

// Camera navigation in the window, in plain values: drags, wheel steps and held keys in,
// a scene::Camera out. The up vector stays the scene file's (the horizon never rolls).
// The camera orbits about, and dollies towards, a pivot on the scene: the surface under the
// window's centre (a ray query against the objects' bounds, scene::nearestBoundHit), or,
// where that ray meets nothing, the point of it nearest the centre of the scene's bounds.
// A scene file's look-at point may lie behind a wall; the pivot never does, and it becomes
// the camera's target (the view does not change: it lies on the view's centre ray). The eye
// stays out of the objects' bounds while it orbits and dollies. Distances moved without a
// pivot to refer to (flying) follow the scene's size.
class CameraController {
public:
    // `home`: the scene file's camera; `scene`: the scene, whose objects the pivot and the
    // eye's clearance are found among.
    CameraController(const scene::Camera& home, const scene::Scene& scene);
    // Without a scene: nothing to meet, so the camera orbits about the target. `sceneRadius`:
    // the radius of the scene's bounds (scene::computeSceneBounds).
    CameraController(const scene::Camera& home, float sceneRadius);

    const scene::Camera& camera() const { return camera_; }
    const scene::Camera& home() const { return home_; }

    // The point the next orbit turns about and the next dolly moves towards.
    glm::vec3 pivot() const;

    // Left drag. A drag the height of the viewport turns the eye half a turn around the
    // pivot: right turns it to the left about the up vector (the scene turns with the
    // mouse), down raises it towards the up vector. The eye stops short of looking straight
    // along the up vector, where the view would flip, and short of a wall (a bound) between
    // the pivot and where the drag would take it; the distance is kept for the rest of the
    // drag, so the eye comes back out once the wall is passed.
    void orbit(glm::vec2 dragPixels, float viewportHeightPixels);
    // Right or middle drag: eye and target move across the view so that a point at the
    // target's distance stays under the mouse.
    void pan(glm::vec2 dragPixels, float viewportHeightPixels);
    // Wheel: each step up takes the eye 15% of its distance towards the pivot (down: away,
    // short of a wall behind). The eye never reaches the pivot.
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
    void setHome(const scene::Camera& home, const scene::Scene& scene, bool replaceCurrent);
    void setHome(const scene::Camera& home, float sceneRadius, bool replaceCurrent);

    // Speeds and limits, in scene radii per second and in fractions.
    static constexpr float kFlySpeed = 0.5f;
    static constexpr float kFastFactor = 5.0f;
    static constexpr float kDollyStep = 0.15f;
    // The eye stays at most this fraction of the way from the pivot to a bound behind it.
    static constexpr float kClearance = 0.9f;

private:
    // The pivot under the window's centre, which becomes the target.
    void pickPivot();
    // How far from the pivot the eye may go in the unit direction `away`: `wanted`, or less
    // where a bound is nearer.
    float clearDistance(const glm::vec3& away, float wanted) const;

    scene::Camera home_;
    scene::Camera camera_;
    scene::SceneBounds bounds_;
    scene::ObjectBounds objects_;
    bool followsTarget_ = false;  // made without a scene
    // Kept while only orbits move the camera: the pivot, and the distance the eye keeps
    // from it where no bound is nearer.
    std::optional<glm::vec3> pivot_;
    float orbitDistance_ = 0.0f;
};

}  // namespace interaction
