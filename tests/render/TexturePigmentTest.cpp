// The texmap pigment against its definition (docs/SCENE_FORMAT.md): the image projected
// along each axis, blended by the normal's components. A flat Lambertian wall alone under a
// constant environment of radiance 1 shows its albedo, so each pixel's expected value is the
// blend computed here on the CPU from the camera and the image: left half red, right half
// green, which tells the projections apart.
#include "support/PinholeCamera.h"
#include "support/RenderRun.h"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <sstream>

namespace render_tests {
namespace {

using namespace testing_support;

constexpr int kWidth = 64;
constexpr int kHeight = 48;

// The wall's unit normal (1, 3, 0) / sqrt(10): the projection along x weighs 1/4, the one
// along y 3/4, the one along z nothing. The wall passes through the origin; the camera looks
// at it head on from 3 units away.
const glm::dvec3 kNormal = glm::normalize(glm::dvec3(1.0, 3.0, 0.0));

scene::Scene texturedWall()
{
    const glm::dvec3 eye = 3.0 * kNormal;
    std::ostringstream text;
    text.precision(17);
    text << "environment 1 1 1\n"
         << eye.x << " " << eye.y << " " << eye.z << "\n0 0 0\n0 0 1\n40\n0\n"
         << "1\ntexmap red_green_halves.ppm 1\n1\n0 0 0  0 0 0 0\n1\n0 0 polyhedron 1\n"
         << kNormal.x << " " << kNormal.y << " " << kNormal.z << " 0\n";
    return sceneFromText(text.str());
}

// The image along one projection's first coordinate s (one copy per unit): red where
// frac(s) < 1/2, green above; -1 within a margin of the halves' edges, where filtering blends
// them.
int half(double s)
{
    const double inTile = s - std::floor(s);
    const double margin = 0.1;
    if (inTile > margin && inTile < 0.5 - margin)
        return 0;
    if (inTile > 0.5 + margin && inTile < 1.0 - margin)
        return 1;
    return -1;
}

// Which halves the wall point seen along `direction` takes in the projections along x
// (coordinates y, z) and along y (x, z): 2 * along-x + along-y, or -1 near an edge.
int halvesSeen(const PinholeCamera& camera, const glm::dvec3& direction)
{
    const double t = -glm::dot(kNormal, camera.eye()) / glm::dot(kNormal, direction);
    const glm::dvec3 point = camera.eye() + t * direction;
    const int alongX = half(point.y);
    const int alongY = half(point.x);
    return alongX < 0 || alongY < 0 ? -1 : 2 * alongX + alongY;
}

TEST(TexturePigment, TriplanarWallShowsItsProjectionsBlendedByTheNormal)
{
    const scene::Scene scene = texturedWall();
    const PinholeCamera camera(scene.camera, kWidth, kHeight);
    const RenderedImage image = renderScene(scene, kWidth, kHeight, 64, settingsWithSeed(5));

    // Red is (1, 0, 0) and green (0, 1, 0) once decoded; the blend is 1/4 of the colour along
    // x and 3/4 of the colour along y.
    const double weightAlongX = 0.25;
    std::map<int, int> pixelsOfClass;
    std::map<int, glm::dvec3> sumOfClass;
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x) {
            const int seen = halvesSeen(camera, camera.direction(x + 0.5, y + 0.5));
            if (seen < 0 || !camera.wholePixel(x, y, [&](const glm::dvec3& direction) {
                    return halvesSeen(camera, direction) == seen;
                }))
                continue;
            const bool greenAlongX = seen / 2 == 1;
            const bool greenAlongY = seen % 2 == 1;
            const double expectedGreen =
                weightAlongX * greenAlongX + (1.0 - weightAlongX) * greenAlongY;
            const glm::dvec3 expected(1.0 - expectedGreen, expectedGreen, 0.0);
            const glm::dvec3 rendered(image.radiance.at(x, y, 0), image.radiance.at(x, y, 1),
                                      image.radiance.at(x, y, 2));
            // 64 samples, whose projections the sampler stratifies: a pixel is near its mean.
            EXPECT_NEAR(rendered.r, expected.r, 0.08) << "pixel (" << x << ", " << y << ")";
            EXPECT_NEAR(rendered.g, expected.g, 0.08) << "pixel (" << x << ", " << y << ")";
            EXPECT_NEAR(rendered.b, 0.0, 1e-6) << "pixel (" << x << ", " << y << ")";
            ++pixelsOfClass[seen];
            sumOfClass[seen] += rendered - expected;
        }
    // All four pairings of halves were seen, and each class is right on average.
    ASSERT_EQ(pixelsOfClass.size(), 4u);
    for (const auto& [seen, pixels] : pixelsOfClass) {
        ASSERT_GE(pixels, 20) << "class " << seen;
        const glm::dvec3 meanError = sumOfClass[seen] / static_cast<double>(pixels);
        EXPECT_NEAR(meanError.r, 0.0, 0.01) << "class " << seen << ", " << pixels << " pixels";
        EXPECT_NEAR(meanError.g, 0.0, 0.01) << "class " << seen << ", " << pixels << " pixels";
    }
}

}  // namespace
}  // namespace render_tests
