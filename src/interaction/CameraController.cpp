#include "interaction/CameraController.h"

#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <cmath>

namespace interaction {

namespace {

constexpr float kPi = 3.14159265358979f;
// The highest elevation above the up vector's plane an orbit reaches: 89 degrees.
constexpr float kMaxElevation = 89.0f * kPi / 180.0f;

glm::vec3 unitOrZero(const glm::vec3& v)
{
    const float length = glm::length(v);
    return length > 0.0f ? v / length : glm::vec3(0.0f);
}

// Any unit vector perpendicular to the unit vector `axis`.
glm::vec3 perpendicularTo(const glm::vec3& axis)
{
    const glm::vec3 other =
        std::abs(axis.x) < 0.9f ? glm::vec3(1.0f, 0.0f, 0.0f) : glm::vec3(0.0f, 1.0f, 0.0f);
    return glm::normalize(glm::cross(axis, other));
}

// World units per pixel at the target's distance: the view's height there is
// 2 d tan(fovy / 2).
float worldPerPixel(const scene::Camera& camera, float viewportHeightPixels)
{
    const float distance = glm::length(camera.target - camera.eye);
    const float tanHalfFovy = std::tan(0.5f * camera.verticalFieldOfViewDegrees * kPi / 180.0f);
    return 2.0f * distance * tanHalfFovy / std::max(viewportHeightPixels, 1.0f);
}

}  // namespace

CameraController::CameraController(const scene::Camera& home, const scene::Scene& scene)
    : home_(home), camera_(home)
{
    setHome(home, scene, true);
}

CameraController::CameraController(const scene::Camera& home, float sceneRadius)
    : home_(home), camera_(home)
{
    setHome(home, sceneRadius, true);
}

glm::vec3 CameraController::pivot() const
{
    if (pivot_)
        return *pivot_;
    CameraController picked = *this;
    picked.pickPivot();
    return *picked.pivot_;
}

void CameraController::pickPivot()
{
    const glm::vec3 forward = unitOrZero(camera_.target - camera_.eye);
    if (forward == glm::vec3(0.0f)) {
        pivot_ = camera_.target;
        orbitDistance_ = 0.0f;
        return;
    }
    float distance = 0.0f;
    if (followsTarget_)
        distance = glm::length(camera_.target - camera_.eye);
    else if (const std::optional<float> hit =
                 scene::nearestBoundHit(objects_, camera_.eye, forward))
        distance = *hit;
    else
        // Nothing under the centre: the point of the centre ray nearest the middle of the
        // scene, or, looking away from it, the target's distance.
        distance = glm::dot(bounds_.center - camera_.eye, forward);
    if (!(distance > 1e-4f * bounds_.radius))
        distance = glm::length(camera_.target - camera_.eye);
    pivot_ = camera_.eye + distance * forward;
    orbitDistance_ = distance;
    camera_.target = *pivot_;
}

float CameraController::clearDistance(const glm::vec3& away, float wanted) const
{
    const std::optional<float> hit = scene::nearestBoundHit(objects_, *pivot_, away);
    if (hit && kClearance * *hit < wanted)
        return std::max(kClearance * *hit, 1e-4f * bounds_.radius);
    return wanted;
}

void CameraController::orbit(glm::vec2 dragPixels, float viewportHeightPixels)
{
    const glm::vec3 up = unitOrZero(camera_.up);
    // No drag, no change: rebuilding the eye from its angles would round it differently.
    if (dragPixels == glm::vec2(0.0f) || up == glm::vec3(0.0f))
        return;
    if (!pivot_)
        pickPivot();
    const glm::vec3 offset = camera_.eye - *pivot_;
    const float distance = glm::length(offset);
    if (distance <= 0.0f || orbitDistance_ <= 0.0f)
        return;
    const float radiansPerPixel = kPi / std::max(viewportHeightPixels, 1.0f);
    const float yaw = -dragPixels.x * radiansPerPixel;
    const float pitch = dragPixels.y * radiansPerPixel;

    // The offset from the pivot in spherical terms about the up vector.
    const float elevation = std::asin(std::clamp(glm::dot(offset / distance, up), -1.0f, 1.0f));
    glm::vec3 horizontal = unitOrZero(offset - glm::dot(offset, up) * up);
    if (horizontal == glm::vec3(0.0f))
        horizontal = perpendicularTo(up);
    horizontal = glm::angleAxis(yaw, up) * horizontal;
    const float newElevation = std::clamp(elevation + pitch, -kMaxElevation, kMaxElevation);
    const glm::vec3 away = std::cos(newElevation) * horizontal + std::sin(newElevation) * up;
    camera_.eye = *pivot_ + clearDistance(away, orbitDistance_) * away;
    camera_.target = *pivot_;
}

void CameraController::pan(glm::vec2 dragPixels, float viewportHeightPixels)
{
    if (dragPixels == glm::vec2(0.0f))
        return;
    const scene::CameraFrame frame = scene::cameraFrame(camera_);
    const float scale = worldPerPixel(camera_, viewportHeightPixels);
    // The scene follows the mouse, so the camera moves the other way (screen y grows down).
    const glm::vec3 move = scale * (-dragPixels.x * frame.right + dragPixels.y * frame.trueUp);
    camera_.eye += move;
    camera_.target += move;
    pivot_.reset();
}

void CameraController::dolly(float wheelSteps)
{
    if (wheelSteps == 0.0f)
        return;
    pickPivot();
    const glm::vec3 offset = camera_.eye - *pivot_;
    const float distance = glm::length(offset);
    if (distance <= 0.0f)
        return;
    const glm::vec3 away = offset / distance;
    float newDistance =
        std::max(distance * std::pow(1.0f - kDollyStep, wheelSteps), 1e-4f * bounds_.radius);
    if (newDistance > distance)
        newDistance = std::max(clearDistance(away, newDistance), distance);
    camera_.eye = *pivot_ + newDistance * away;
    orbitDistance_ = newDistance;
}

void CameraController::fly(glm::vec3 direction, float seconds, bool fast)
{
    if (direction == glm::vec3(0.0f) || seconds <= 0.0f)
        return;
    const scene::CameraFrame frame = scene::cameraFrame(camera_);
    const glm::vec3 up = unitOrZero(camera_.up);
    const glm::vec3 along =
        direction.x * frame.right + direction.y * up + direction.z * frame.forward;
    const float speed = kFlySpeed * bounds_.radius * (fast ? kFastFactor : 1.0f);
    const glm::vec3 move = unitOrZero(along) * speed * seconds;
    camera_.eye += move;
    camera_.target += move;
    pivot_.reset();
}

void CameraController::returnHome()
{
    camera_ = home_;
    pivot_.reset();
}

void CameraController::setHome(const scene::Camera& home, const scene::Scene& scene,
                               bool replaceCurrent)
{
    bounds_ = scene::computeSceneBounds(scene);
    objects_ = scene::objectBounds(scene);
    followsTarget_ = false;
    home_ = home;
    if (replaceCurrent)
        camera_ = home;
    pivot_.reset();
}

void CameraController::setHome(const scene::Camera& home, float sceneRadius, bool replaceCurrent)
{
    // Nothing to meet: the pivot is the target.
    bounds_.center = home.target;
    bounds_.radius = std::max(sceneRadius, 1e-6f);
    objects_ = {};
    followsTarget_ = true;
    home_ = home;
    if (replaceCurrent)
        camera_ = home;
    pivot_.reset();
}

}  // namespace interaction
