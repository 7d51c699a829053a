#pragma once
// Environment maps the project makes itself, for its tests and examples (so that no test
// downloads anything): latitude-longitude images laid out as docs/SCENE_FORMAT.md says,
// written here from that text, independently of the shaders.
#include "io/Image.h"

#include <glm/glm.hpp>

#include <filesystem>
#include <string>

namespace testing_support {

// The unit direction, in the map's own frame, at image coordinates (u, v): u in [0, 1) from
// the left edge, v in [0, 1) from the top. The middle column faces -z, the column at three
// quarters +x, the top row +y: phi = 2 pi (u - 1/2), theta = pi v,
// d = (sin theta sin phi, cos theta, -sin theta cos phi).
glm::dvec3 environmentMapDirection(double u, double v);
// Its inverse.
glm::dvec2 environmentMapCoordinates(const glm::dvec3& direction);

// The same radiance everywhere.
io::Image constantEnvironmentMap(int width, int height, const glm::vec3& radiance);

// Each texel takes the colour octantColour gives its centre's direction.
io::Image octantEnvironmentMap(int width, int height);
// Channel c (x, y, z for r, g, b) is 1 where the direction's component c is positive, 0.2
// where it is negative: the colour says the octant.
glm::vec3 octantColour(const glm::dvec3& direction);

// Black but for a rectangle of texels of one radiance.
io::Image patchEnvironmentMap(int width, int height, int firstColumn, int firstRow, int columns,
                              int rows, const glm::vec3& radiance);

// A clear sky over dark ground with a sun: a gradient from a pale horizon to a blue zenith,
// and a disc of `sunRadiance` (each channel times a warm white) of `sunRadiusDegrees` at
// `sunElevationDegrees` above the horizon, at map column `sunU`. Texels the disc's edge
// crosses take the share of it they hold (4 x 4 points each).
struct SkyWithSun {
    double sunElevationDegrees = 35.0;
    double sunU = 0.625;  // between -z (0.5) and +x (0.75)
    double sunRadiusDegrees = 2.0;
    double sunRadiance = 3000.0;
};
io::Image skyWithSunEnvironmentMap(int width, int height, const SkyWithSun& sky = {});
// The sky's radiance without the sun, in a direction of the map's frame.
glm::vec3 skyRadiance(const glm::dvec3& direction);
// The sun's direction in the map's frame.
glm::dvec3 sunDirection(const SkyWithSun& sky);

// An image written to a file of its own in the system's temporary folder, removed again
// when this goes out of scope. `extension` names the format (".exr", ".hdr", ...).
class TemporaryImageFile {
public:
    TemporaryImageFile(const io::Image& image, const std::string& extension);
    ~TemporaryImageFile();
    TemporaryImageFile(const TemporaryImageFile&) = delete;
    TemporaryImageFile& operator=(const TemporaryImageFile&) = delete;

    const std::filesystem::path& path() const { return path_; }

private:
    std::filesystem::path path_;
};

}  // namespace testing_support
