#pragma once
// The scene format's camera on the CPU, for closed-form expectations of the render tests and
// the torture suite: pixel (i, j) covers uv = ((2 (i, j) - (w, h)) / h) tan(fovy / 2) with
// row 0 at the bottom (GL), and the renderer jitters each sample uniformly inside it. Images
// are read back top row first, so picture row y is GL row h - 1 - y.
#include "scene/Scene.h"

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>

namespace testing_support {

class PinholeCamera {
public:
    PinholeCamera(const scene::Camera& camera, int width, int height)
        : eye_(camera.eye),
          frame_(scene::cameraFrame(camera)),
          tanHalfFovy_(
              std::tan(glm::radians(static_cast<double>(camera.verticalFieldOfViewDegrees)) / 2.0)),
          width_(width),
          height_(height)
    {
    }

    glm::dvec3 eye() const { return eye_; }

    // The unit direction through film point (fx, fy) of picture coordinates: x to the
    // right, y down from the top edge, in pixels.
    glm::dvec3 direction(double fx, double fy) const
    {
        const double glY = height_ - fy;
        const double u = (2.0 * fx - width_) / height_ * tanHalfFovy_;
        const double v = (2.0 * glY - height_) / height_ * tanHalfFovy_;
        return glm::normalize(u * glm::dvec3(frame_.right) + v * glm::dvec3(frame_.trueUp) +
                              glm::dvec3(frame_.forward));
    }

    // The mean of f(direction) over picture pixel (x, y), by the midpoint rule on a
    // `subdivisions`^2 grid: what the renderer's uniform jitter converges to.
    template <typename Function>
    double pixelAverage(int x, int y, int subdivisions, Function f) const
    {
        double sum = 0.0;
        for (int a = 0; a < subdivisions; ++a)
            for (int b = 0; b < subdivisions; ++b)
                sum += f(direction(x + (a + 0.5) / subdivisions, y + (b + 0.5) / subdivisions));
        return sum / (subdivisions * subdivisions);
    }

    // True when the four corners and the centre of pixel (x, y) all satisfy `test`.
    template <typename Test>
    bool wholePixel(int x, int y, Test test) const
    {
        return test(direction(x, y)) && test(direction(x + 1, y)) && test(direction(x, y + 1)) &&
               test(direction(x + 1, y + 1)) && test(direction(x + 0.5, y + 0.5));
    }

private:
    glm::dvec3 eye_;
    scene::CameraFrame frame_;
    double tanHalfFovy_;
    int width_;
    int height_;
};

// Distance from `point` to the line through `origin` along unit `direction`, measured on
// the segment's forward side (points behind the origin are measured to the origin).
inline double distanceToRay(const glm::dvec3& point, const glm::dvec3& origin,
                            const glm::dvec3& direction)
{
    const glm::dvec3 toPoint = point - origin;
    const double along = std::max(0.0, glm::dot(toPoint, direction));
    return glm::length(toPoint - along * direction);
}

// Distance along the unit ray (origin, direction) to the sphere's near side, or -1.
inline double raySphere(const glm::dvec3& origin, const glm::dvec3& direction,
                        const glm::dvec3& center, double radius)
{
    const glm::dvec3 toCenter = center - origin;
    const double along = glm::dot(toCenter, direction);
    const double squaredMiss = glm::dot(toCenter, toCenter) - along * along;
    if (squaredMiss > radius * radius || along <= 0.0)
        return -1.0;
    return along - std::sqrt(radius * radius - squaredMiss);
}

// The distance along the ray (unit direction) to where it enters the axis-aligned box, or -1
// where it misses (slab method).
inline double rayBox(const glm::dvec3& origin, const glm::dvec3& direction,
                     const glm::dvec3& center, const glm::dvec3& halfExtents)
{
    double enter = -1e300, exit = 1e300;
    for (int axis = 0; axis < 3; ++axis) {
        const double low = center[axis] - halfExtents[axis] - origin[axis];
        const double high = center[axis] + halfExtents[axis] - origin[axis];
        if (direction[axis] == 0.0) {
            if (low > 0.0 || high < 0.0)
                return -1.0;
            continue;
        }
        const double t0 = low / direction[axis], t1 = high / direction[axis];
        enter = std::max(enter, std::min(t0, t1));
        exit = std::min(exit, std::max(t0, t1));
    }
    return enter <= exit && enter > 0.0 ? enter : -1.0;
}

}  // namespace testing_support
