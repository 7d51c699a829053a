// Environment maps through the renderer: the furnace, a small bright patch against the closed
// form of the small distant light it stands for, the orientation the scene format states, and
// the bilinear filter camera rays see. The maps are made here (support/EnvironmentMapImages)
// and written to temporary files, as a user's would be read.
#include "support/EnvironmentMapImages.h"
#include "support/PinholeCamera.h"
#include "support/RenderRun.h"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <sstream>

namespace render_tests {
namespace {

using namespace testing_support;

constexpr double kPi = 3.14159265358979323846;

std::string mapLine(const TemporaryImageFile& map, const std::string& options = "")
{
    return "environment map " + map.path().string() + " " + options + "\n";
}

// Per pixel: how far the estimate lies from `expected`, in the estimate's own standard errors
// (from the renderer's per-pixel variance), over the pixels `select` picks.
struct Agreement {
    double worstZ = 0.0;
    int worstX = -1;
    int worstY = -1;
    double mean = 0.0;  // of the pixels' channel means
    double meanStandardError = 0.0;
    int pixels = 0;
    std::string describe() const
    {
        std::ostringstream text;
        text << pixels << " pixels, mean " << mean << " +- " << meanStandardError
             << ", worst pixel (" << worstX << ", " << worstY << ") at " << worstZ
             << " standard errors";
        return text.str();
    }
};

template <typename Select>
Agreement agreementWith(const RenderedImage& image, double expected, Select select)
{
    Agreement agreement;
    double variance = 0.0;
    for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < image.width(); ++x) {
            if (!select(x, y))
                continue;
            ++agreement.pixels;
            const double value = channelMean(image.radiance, x, y);
            const double standardError = std::sqrt(image.varianceOfMean(x, y)) + 1e-7;
            const double z = std::abs(value - expected) / standardError;
            if (!(z <= agreement.worstZ)) {
                agreement.worstZ = z;
                agreement.worstX = x;
                agreement.worstY = y;
            }
            agreement.mean += value;
            variance += image.varianceOfMean(x, y);
        }
    if (agreement.pixels > 0) {
        agreement.mean /= agreement.pixels;
        agreement.meanStandardError = std::sqrt(variance) / agreement.pixels;
    }
    return agreement;
}

// --- the furnace ------------------------------------------------------------------------

// Under a map of radiance 1 everywhere, sampled by its distribution and by the BSDF and
// combined by MIS, a white Lambertian sphere reflects all it receives: it vanishes, every
// pixel 1 within its noise. Both builds of the shader's environment: built in, and read from
// a uniform (the window's, which can switch it off). (The general shader, whose light code is
// the same, takes two minutes to compile here: it was checked by hand.)
class EnvironmentMapFurnace : public ::testing::TestWithParam<int> {};

TEST_P(EnvironmentMapFurnace, WhiteLambertianSphereVanishes)
{
    const TemporaryImageFile map(constantEnvironmentMap(32, 16, glm::vec3(1.0f)), ".exr");
    const scene::Scene scene =
        sceneFromText(mapLine(map) + "0 0 4\n0 0 0\n0 1 0\n40\n0\n1 solid 1 1 1\n"
                                     "1\n0 0 0 0 0 0 0\n1\n0 0 sphere 0 0 0 1\n");
    settings::RenderSettings settings = settingsWithSeed(7);
    settings.switchableEnvironment = GetParam() == 1;
    const RenderedImage image = renderScene(scene, 64, 48, 32, settings);
    const PinholeCamera camera(scene.camera, 64, 48);
    const Agreement sphere = agreementWith(image, 1.0, [&](int x, int y) {
        return camera.wholePixel(x, y, [&](const glm::dvec3& d) {
            return raySphere(camera.eye(), d, glm::dvec3(0.0), 0.97) > 0.0;
        });
    });
    ASSERT_GT(sphere.pixels, 300);
    std::cout << "white sphere under a map of radiance 1: " << sphere.describe() << "\n";
    EXPECT_LT(sphere.worstZ, 5.0) << "every pixel of the sphere should read 1; "
                                  << sphere.describe();
    EXPECT_NEAR(sphere.mean, 1.0, 4.0 * sphere.meanStandardError + 1e-4) << sphere.describe();
    EXPECT_EQ(image.discardedSamples, 0u);
    const Agreement background = agreementWith(image, 1.0, [&](int x, int y) {
        return camera.wholePixel(x, y, [&](const glm::dvec3& d) {
            return raySphere(camera.eye(), d, glm::dvec3(0.0), 1.03) < 0.0;
        });
    });
    ASSERT_GT(background.pixels, 300);
    EXPECT_NEAR(background.mean, 1.0, 1e-6) << "the background is the map itself";
}

std::string shaderName(const ::testing::TestParamInfo<int>& info)
{
    const char* const names[] = {"built_in", "from_uniform"};
    return names[info.param];
}

INSTANTIATE_TEST_SUITE_P(Environment, EnvironmentMapFurnace, ::testing::Values(0, 1), shaderName);

// --- a small bright patch: a small distant light ----------------------------------------

// A map black but for 2 x 2 texels of radiance L, 45 degrees up, over a white Lambertian
// plane of albedo a: each point of the plane receives E = L times the integral of cos(theta)
// over the patch's solid angle, and shows a E / pi, for the patch is far. Over a texel of
// longitude width dphi between polar angles theta0 and theta1 that integral is
// dphi (sin^2 theta1 - sin^2 theta0) / 2. The bilinear filter spreads the patch over its
// neighbours without changing its total, to first order. Every pixel must agree: with light
// sampling and MIS, and with light sampling alone (the density covers every direction the
// filtered map lights, so nothing is missed).
class SmallPatch : public ::testing::TestWithParam<bool> {};

TEST_P(SmallPatch, PlaneMatchesTheClosedFormOfTheEquivalentSmallDistantLight)
{
    constexpr int kMapWidth = 256;
    constexpr int kMapHeight = 128;
    constexpr int kFirstColumn = 150;
    constexpr int kFirstRow = 31;  // theta from 43.6 to 45 degrees, and the next row
    constexpr float kRadiance = 2000.0f;
    constexpr double kAlbedo = 0.5;
    const TemporaryImageFile map(patchEnvironmentMap(kMapWidth, kMapHeight, kFirstColumn, kFirstRow,
                                                     2, 2, glm::vec3(kRadiance)),
                                 ".exr");
    double irradiance = 0.0;
    const double columnWidth = 2.0 * kPi / kMapWidth;
    for (int row = kFirstRow; row < kFirstRow + 2; ++row) {
        const double sin0 = std::sin(kPi * row / kMapHeight);
        const double sin1 = std::sin(kPi * (row + 1) / kMapHeight);
        irradiance += 2.0 * kRadiance * columnWidth * (sin1 * sin1 - sin0 * sin0) / 2.0;
    }
    const double expected = kAlbedo / kPi * irradiance;

    const scene::Scene scene =
        sceneFromText(mapLine(map) + "0 3 0\n0 0 0\n0 0 -1\n40\n0\n1 solid 0.5 0.5 0.5\n"
                                     "1\n0 0 0 0 0 0 0\n1\n0 0 polyhedron 1 0 1 0 0\n");
    settings::RenderSettings settings = settingsWithSeed(11);
    settings.multipleImportanceSampling = GetParam();
    const RenderedImage image = renderScene(scene, 48, 36, 32, settings);
    const Agreement plane = agreementWith(image, expected, [](int, int) { return true; });
    std::cout << "plane under a small bright patch, expected " << expected << ": "
              << plane.describe() << "\n";
    EXPECT_LT(plane.worstZ, 5.0) << "every pixel of the plane should read a E / pi = " << expected
                                 << "; " << plane.describe();
    EXPECT_NEAR(plane.mean, expected, 0.01 * expected)
        << "the plane should read a E / pi = " << expected << "; " << plane.describe();
}

INSTANTIATE_TEST_SUITE_P(Mis, SmallPatch, ::testing::Bool(),
                         [](const ::testing::TestParamInfo<bool>& info) {
                             return std::string(info.param ? "light_and_bsdf_sampling"
                                                           : "light_sampling_alone");
                         });

// --- orientation --------------------------------------------------------------------------

// A map of one colour per octant of directions (support/EnvironmentMapImages.h: red says
// x > 0, green y > 0, blue z > 0), made from the convention docs/SCENE_FORMAT.md states, seen
// by a narrow camera at the origin looking into the middle of each octant: every pixel shows
// that octant's colour (the texels around are of that colour too, so the filter blends
// nothing in; a turn of -30 degrees keeps them 15 degrees from the octant's edges). Turned by `rotate`, the map's directions turn about +y by the
// right-hand rule, so what the camera sees in world direction d is the map's colour at the
// direction turned back.
class Orientation : public ::testing::TestWithParam<float> {};

TEST_P(Orientation, EachOctantOfDirectionsShowsItsColour)
{
    const float degrees = GetParam();
    const TemporaryImageFile map(octantEnvironmentMap(64, 32), ".exr");
    const glm::dmat3 turnBack(
        glm::rotate(glm::dmat4(1.0), glm::radians(-static_cast<double>(degrees)), {0, 1, 0}));
    for (int octant = 0; octant < 8; ++octant) {
        const glm::dvec3 look((octant & 1) ? 1.0 : -1.0, (octant & 2) ? 1.0 : -1.0,
                              (octant & 4) ? 1.0 : -1.0);
        std::ostringstream text;
        text << mapLine(map, "rotate " + std::to_string(degrees)) << "0 0 0\n"
             << look.x << " " << look.y << " " << look.z << "\n0 1 0\n4\n0\n1 solid 1 1 1\n"
             << "1\n0 0 0 0 0 0 1\n0\n";
        const RenderedImage image =
            renderScene(sceneFromText(text.str()), 16, 12, 1, settingsWithSeed(1));
        const glm::vec3 expected = octantColour(turnBack * look);
        for (int y = 0; y < image.height(); ++y)
            for (int x = 0; x < image.width(); ++x)
                for (int c = 0; c < 3; ++c)
                    ASSERT_NEAR(image.radiance.at(x, y, c), expected[c], 1e-4)
                        << "looking towards (" << look.x << ", " << look.y << ", " << look.z
                        << ") with the map turned " << degrees << " degrees, pixel (" << x << ", "
                        << y << ") channel " << c;
    }
}

std::string rotationName(const ::testing::TestParamInfo<float>& info)
{
    const char* const names[] = {"unturned", "quarter_turn", "half_turn", "minus_30_degrees"};
    return names[info.index];
}

INSTANTIATE_TEST_SUITE_P(Rotation, Orientation, ::testing::Values(0.0f, 90.0f, 180.0f, -30.0f),
                         rotationName);

// The statement itself, texel by texel: a map black but for its middle column's texel at the
// equator is seen straight ahead along -z, and nowhere else around the horizon.
TEST(Orientation, TheMiddleColumnFacesMinusZ)
{
    const TemporaryImageFile map(patchEnvironmentMap(8, 4, 4, 1, 1, 2, glm::vec3(1.0f)), ".exr");
    auto seen = [&](const glm::dvec3& look) {
        std::ostringstream text;
        text << mapLine(map) << "0 0 0\n"
             << look.x << " " << look.y << " " << look.z
             << "\n0 1 0\n0.05\n0\n1 solid 1 1 1\n1\n0 0 0 0 0 0 1\n0\n";
        const RenderedImage image =
            renderScene(sceneFromText(text.str()), 4, 4, 1, settingsWithSeed(1));
        return channelMean(image.radiance, 2, 2);
    };
    // Texel column 4 spans u from 0.5 to 0.625, so its centre faces 22.5 degrees from -z
    // towards +x, at the equator.
    const double angle = glm::radians(22.5);
    EXPECT_NEAR(seen({std::sin(angle), 0.0, -std::cos(angle)}), 1.0, 1e-2);
    EXPECT_NEAR(seen({-std::sin(angle), 0.0, -std::cos(angle)}), 0.0, 1e-2);
    EXPECT_NEAR(seen({std::sin(angle), 0.0, std::cos(angle)}), 0.0, 1e-2);
    EXPECT_NEAR(seen({std::cos(angle), 0.0, std::sin(angle)}), 0.0, 1e-2);
}

// --- filtering ----------------------------------------------------------------------------

// Camera rays see the map filtered bilinearly: halfway between the centres of a texel of 1
// and its neighbour of 0, the background is 0.5; at a texel's centre it is the texel. (The GL
// may round a filter's weights to 1/256: hence 1 % where weights are not 0 or 1.)
TEST(EnvironmentMapFilter, CameraRaysSeeTheMapBilinearlyFiltered)
{
    // Texel (4, 1) is 1, every other one 0: columns of 45 degrees, rows of 45 degrees.
    const TemporaryImageFile map(patchEnvironmentMap(8, 4, 4, 1, 1, 1, glm::vec3(1.0f)), ".exr");
    auto seen = [&](double u, double v) {
        const glm::dvec3 look = environmentMapDirection(u, v);
        std::ostringstream text;
        text.precision(17);
        text << mapLine(map) << "0 0 0\n"
             << look.x << " " << look.y << " " << look.z
             << "\n0 1 0\n0.05\n0\n1 solid 1 1 1\n1\n0 0 0 0 0 0 1\n0\n";
        const RenderedImage image =
            renderScene(sceneFromText(text.str()), 4, 4, 1, settingsWithSeed(1));
        return channelMean(image.radiance, 2, 2);
    };
    EXPECT_NEAR(seen(4.5 / 8, 1.5 / 4), 1.0, 1e-3) << "the texel's centre";
    EXPECT_NEAR(seen(5.0 / 8, 1.5 / 4), 0.5, 1e-2) << "halfway to the next column's centre";
    EXPECT_NEAR(seen(4.5 / 8, 2.0 / 4), 0.5, 1e-2) << "halfway to the next row's centre";
    EXPECT_NEAR(seen(4.75 / 8, 1.75 / 4), 0.75 * 0.75, 1e-2) << "a quarter of the way to both";
}

}  // namespace
}  // namespace render_tests
