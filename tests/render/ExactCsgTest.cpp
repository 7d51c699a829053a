// CSG solids met exactly by --exact-geometry (shadergen/ExactCsgIntersection.h), the reference
// the marched CSG solids of every render are judged against: where the walk over the leaves'
// crossings finds the solid (silhouettes and holes, against the CPU's own sphere tracing of
// the solid's exact distance in double precision), and which way its normals point (a solid
// that a CSG block cuts shades as the same solid written as one shape, with the same seed).
#include "support/CsgSolids.h"
#include "support/PinholeCamera.h"
#include "support/RenderRun.h"

#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>

namespace render_tests {
namespace {

using namespace testing_support;

constexpr int kWidth = 64;
constexpr int kHeight = 48;

// Whether the ray meets the solid, by sphere tracing its exact distance in double precision.
template <typename Solid>
bool meets(const Solid& solid, const glm::dvec3& origin, const glm::dvec3& direction)
{
    return sphereTracedCrossing(solid, origin, direction) >= 0.0;
}

std::string blackSolidAgainstTheSky(const std::string& camera, const std::string& solid)
{
    return camera + "0\n1\nsolid 0 0 0\n1\n0 0 0 0 0 0 0\n1\n0 0 " + solid + "\n";
}

// Pixels every ray of which meets the solid are black, pixels none of whose rays does see the
// sky (at least 0.2 in every direction).
template <typename Solid>
void expectExactSilhouette(const std::string& sceneText, const Solid& solid)
{
    const scene::Scene scene = sceneFromText(sceneText);
    settings::RenderSettings settings = settingsWithSeed(3);
    settings.exactGeometry = true;
    const RenderedImage image = renderScene(scene, kWidth, kHeight, 8, settings);
    const PinholeCamera camera(scene.camera, kWidth, kHeight);
    int inside = 0;
    int outside = 0;
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x) {
            const float value = channelMean(image.radiance, x, y);
            if (camera.wholePixel(x, y,
                                  [&](glm::dvec3 d) { return meets(solid, camera.eye(), d); })) {
                ++inside;
                EXPECT_LT(value, 1e-6f) << "pixel (" << x << ", " << y << ") is on the solid";
            } else if (camera.wholePixel(
                           x, y, [&](glm::dvec3 d) { return !meets(solid, camera.eye(), d); })) {
                ++outside;
                EXPECT_GT(value, 0.2f) << "pixel (" << x << ", " << y << ") sees the sky";
            }
        }
    EXPECT_GT(inside, kWidth * kHeight / 10);
    EXPECT_GT(outside, kWidth * kHeight / 10);
}

TEST(ExactCsg, ADrilledAndScoopedBoxIsMetWithinItsSilhouetteAndSeenThroughItsHole)
{
    // From the front, a little above: the scoop and the hole both show.
    expectExactSilhouette(
        blackSolidAgainstTheSky("0 1.2 3.6\n0 0.5 0\n0 1 0\n45\n", DrilledScoopedBox::kShape),
        DrilledScoopedBox{});
}

TEST(ExactCsg, AnIntersectionUnderATransformIsMetWithinItsSilhouette)
{
    const glm::dmat3 turn(glm::rotate(glm::dmat4(1.0), glm::radians(30.0), glm::dvec3(0, 1, 0)));
    expectExactSilhouette(blackSolidAgainstTheSky(
                              "2.5 1.8 3\n0 0 0\n0 1 0\n45\n",
                              "rotate 0 1 0 30 intersection { sphere 0 0 0 1.3  box 0 0 0 1 1 1 }"),
                          RoundedCube{glm::dvec3(0.0), glm::transpose(turn)});
}

// A lit grey solid on a floor, seen under a point light and the sky: every face's normal
// decides its shading.
std::string litSolidOnAFloor(const std::string& solid)
{
    return "0 2 4.5\n0 0.5 0\n0 1 0\n40\n1\n2 4 3  20 20 20\n2\nsolid 0.8 0.8 0.8\n"
           "solid 0.7 0.4 0.3\n1\n0 0 0 0 0 0 0\n2\n0 0 polyhedron 1 0 1 0 0\n1 0 " +
           solid + "\n";
}

// Renders both scenes exactly with one seed: the same samples meet the same surfaces, so the
// images agree to rounding wherever the two descriptions are one solid.
void expectSameImage(const std::string& written, const std::string& cut)
{
    settings::RenderSettings settings = settingsWithSeed(5);
    settings.exactGeometry = true;
    const RenderedImage a = renderScene(sceneFromText(written), kWidth, kHeight, 16, settings);
    const RenderedImage b = renderScene(sceneFromText(cut), kWidth, kHeight, 16, settings);
    double sum = 0.0;
    int differing = 0;
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x) {
            const double va = channelMean(a.radiance, x, y);
            const double vb = channelMean(b.radiance, x, y);
            sum += va;
            if (std::abs(va - vb) > 1e-3 * std::max(va, 0.05))
                ++differing;
        }
    EXPECT_GT(sum / (kWidth * kHeight), 0.05) << "the images are lit";
    // A sample that rounding sends past an edge on one side only changes one pixel or two.
    EXPECT_LE(differing, 2) << differing << " pixels differ between\n"
                            << written << "\nand\n"
                            << cut;
}

TEST(ExactCsg, ABoxCutByAnotherShadesAsTheBoxThatIsLeft)
{
    // The top of what is left is the cutting box's bottom face, whose normal is turned out.
    expectSameImage(
        litSolidOnAFloor("translate 0.2 0 -0.1 rotate 0 1 0 35 box 0 0.4 0  0.8 0.4 0.6"),
        litSolidOnAFloor("translate 0.2 0 -0.1 rotate 0 1 0 35 difference {\n"
                         "  box 0 0.6 0  0.8 0.6 0.6\n  box 0 1.3 0  1 0.5 1\n}"));
}

TEST(ExactCsg, AnIntersectionOfTwoBoxesShadesAsTheirCommonBox)
{
    expectSameImage(
        litSolidOnAFloor("rotate 0 1 0 -20 box 0 0.5 0  0.5 0.5 0.5"),
        litSolidOnAFloor("rotate 0 1 0 -20 intersection {\n"
                         "  box 0.3 0.5 0  0.8 0.5 0.5\n"
                         "  union { box -0.2 0.5 0  0.7 0.6 0.5  sphere 5 5 5 0.1 }\n}"));
}

}  // namespace
}  // namespace render_tests
