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

CameraController::CameraController(const scene::Camera& home, float sceneRadius)
    : home_(home), camera_(home), sceneRadius_(std::max(sceneRadius, 1e-6f))
{
}

void CameraController::orbit(glm::vec2 dragPixels, float viewportHeightPixels)
{
    const glm::vec3 up = unitOrZero(camera_.up);
    const glm::vec3 offset = camera_.eye - camera_.target;
    const float distance = glm::length(offset);
    // No drag, no change: rebuilding the eye from its angles would round it differently.
    if (dragPixels == glm::vec2(0.0f) || distance <= 0.0f || up == glm::vec3(0.0f))
        return;
    const float radiansPerPixel = kPi / std::max(viewportHeightPixels, 1.0f);
    const float yaw = -dragPixels.x * radiansPerPixel;
    const float pitch = dragPixels.y * radiansPerPixel;

    // The offset from the target in spherical terms about the up vector.
    const float elevation =
        std::asin(std::clamp(glm::dot(offset / distance, up), -1.0f, 1.0f));
    glm::vec3 horizontal = unitOrZero(offset - glm::dot(offset, up) * up);
    if (horizontal == glm::vec3(0.0f))
        horizontal = perpendicularTo(up);
    horizontal = glm::angleAxis(yaw, up) * horizontal;
    const float newElevation = std::clamp(elevation + pitch, -kMaxElevation, kMaxElevation);
    camera_.eye = camera_.target + distance * (std::cos(newElevation) * horizontal +
                                               std::sin(newElevation) * up);
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
}

void CameraController::dolly(float wheelSteps)
{
    const glm::vec3 offset = camera_.eye - camera_.target;
    const float distance = glm::length(offset);
    if (distance <= 0.0f || wheelSteps == 0.0f)
        return;
    const float newDistance =
        std::max(distance * std::pow(1.0f - kDollyStep, wheelSteps), 1e-4f * sceneRadius_);
    camera_.eye = camera_.target + offset * (newDistance / distance);
}

void CameraController::fly(glm::vec3 direction, float seconds, bool fast)
{
    if (direction == glm::vec3(0.0f) || seconds <= 0.0f)
        return;
    const scene::CameraFrame frame = scene::cameraFrame(camera_);
    const glm::vec3 up = unitOrZero(camera_.up);
    const glm::vec3 along =
        direction.x * frame.right + direction.y * up + direction.z * frame.forward;
    const float speed = kFlySpeed * sceneRadius_ * (fast ? kFastFactor : 1.0f);
    const glm::vec3 move = unitOrZero(along) * speed * seconds;
    camera_.eye += move;
    camera_.target += move;
}

void CameraController::returnHome()
{
    camera_ = home_;
}

void CameraController::setHome(const scene::Camera& home, float sceneRadius, bool replaceCurrent)
{
    home_ = home;
    sceneRadius_ = std::max(sceneRadius, 1e-6f);
    if (replaceCurrent)
        camera_ = home;
}

}  // namespace interaction
