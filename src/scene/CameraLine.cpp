#include "scene/CameraLine.h"

#include <charconv>

namespace scene {

namespace {

// The shortest text that reads back as `value` (std::to_chars without a precision).
std::string shortest(float value)
{
    // -0 reads back as 0: the same camera, and one character shorter.
    if (value == 0.0f)
        value = 0.0f;
    char text[32];
    const auto [end, error] = std::to_chars(text, text + sizeof text, value);
    return error == std::errc() ? std::string(text, end) : std::string("0");
}

std::string threeNumbers(const glm::vec3& v)
{
    return shortest(v.x) + " " + shortest(v.y) + " " + shortest(v.z);
}

}  // namespace

std::string cameraLine(const Camera& camera)
{
    std::string line = threeNumbers(camera.eye) + "  " + threeNumbers(camera.target) + "  " +
                       threeNumbers(camera.up) + "  " + shortest(camera.verticalFieldOfViewDegrees);
    if (camera.lens)
        line += "  lens " + shortest(camera.lens->apertureRadius) + " " +
                shortest(camera.lens->focusDistance);
    return line;
}

}  // namespace scene
