#include "support/EnvironmentMapImages.h"

#include "io/ImageFile.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <unistd.h>

namespace testing_support {

namespace {

constexpr double kPi = 3.14159265358979323846;

void set(io::Image& image, int x, int y, const glm::vec3& value)
{
    for (int c = 0; c < 3; ++c)
        image.at(x, y, c) = value[c];
}

}  // namespace

glm::dvec3 environmentMapDirection(double u, double v)
{
    const double phi = 2.0 * kPi * (u - 0.5);
    const double theta = kPi * v;
    return {std::sin(theta) * std::sin(phi), std::cos(theta), -std::sin(theta) * std::cos(phi)};
}

glm::dvec2 environmentMapCoordinates(const glm::dvec3& direction)
{
    const glm::dvec3 d = glm::normalize(direction);
    double u = 0.5 + std::atan2(d.x, -d.z) / (2.0 * kPi);
    if (u >= 1.0)
        u -= 1.0;
    return {u, std::acos(std::clamp(d.y, -1.0, 1.0)) / kPi};
}

io::Image constantEnvironmentMap(int width, int height, const glm::vec3& radiance)
{
    io::Image image = io::Image(width, height, 3);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x)
            set(image, x, y, radiance);
    return image;
}

glm::vec3 octantColour(const glm::dvec3& direction)
{
    return {direction.x > 0.0 ? 1.0f : 0.2f, direction.y > 0.0 ? 1.0f : 0.2f,
            direction.z > 0.0 ? 1.0f : 0.2f};
}

io::Image octantEnvironmentMap(int width, int height)
{
    io::Image image = io::Image(width, height, 3);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x)
            set(image, x, y,
                octantColour(environmentMapDirection((x + 0.5) / width, (y + 0.5) / height)));
    return image;
}

io::Image patchEnvironmentMap(int width, int height, int firstColumn, int firstRow, int columns,
                              int rows, const glm::vec3& radiance)
{
    io::Image image = constantEnvironmentMap(width, height, glm::vec3(0.0f));
    for (int y = firstRow; y < firstRow + rows; ++y)
        for (int x = firstColumn; x < firstColumn + columns; ++x)
            set(image, x, y, radiance);
    return image;
}

glm::vec3 skyRadiance(const glm::dvec3& direction)
{
    if (direction.y < 0.0)
        return {0.14f, 0.12f, 0.10f};  // dry earth
    const float t = static_cast<float>(std::sqrt(direction.y));
    const glm::vec3 horizon(1.0f, 0.95f, 0.88f);
    const glm::vec3 zenith(0.25f, 0.42f, 0.85f);
    return horizon + (zenith - horizon) * t;
}

glm::dvec3 sunDirection(const SkyWithSun& sky)
{
    return environmentMapDirection(sky.sunU, 0.5 - sky.sunElevationDegrees / 180.0);
}

io::Image skyWithSunEnvironmentMap(int width, int height, const SkyWithSun& sky)
{
    const glm::dvec3 sun = sunDirection(sky);
    const double cosSunRadius = std::cos(sky.sunRadiusDegrees * kPi / 180.0);
    const glm::vec3 sunColour = static_cast<float>(sky.sunRadiance) * glm::vec3(1.0f, 0.96f, 0.88f);
    constexpr int kPoints = 4;
    io::Image image = io::Image(width, height, 3);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            glm::vec3 sum(0.0f);
            for (int j = 0; j < kPoints; ++j)
                for (int i = 0; i < kPoints; ++i) {
                    const glm::dvec3 d = environmentMapDirection(
                        (x + (i + 0.5) / kPoints) / width, (y + (j + 0.5) / kPoints) / height);
                    sum += glm::dot(d, sun) >= cosSunRadius ? sunColour : skyRadiance(d);
                }
            set(image, x, y, sum / static_cast<float>(kPoints * kPoints));
        }
    return image;
}

TemporaryImageFile::TemporaryImageFile(const io::Image& image, const std::string& extension)
{
    static std::atomic<int> counter{0};
    path_ = std::filesystem::temp_directory_path() /
            ("raytracer-test-map-" + std::to_string(::getpid()) + "-" + std::to_string(counter++) +
             extension);
    io::writeImage(path_, image);
}

TemporaryImageFile::~TemporaryImageFile()
{
    std::error_code ignored;
    std::filesystem::remove(path_, ignored);
}

}  // namespace testing_support
