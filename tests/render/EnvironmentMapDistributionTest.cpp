// The environment map's distribution, built on the host (render/EnvironmentMap.h), and its
// reading from files: no GL. The shader's sampling of it is tested against its pdf in
// tests/sampling/SamplingChiSquareTest.cpp.
#include "render/EnvironmentMap.h"
#include "scene/SceneParser.h"
#include "support/EnvironmentMapImages.h"
#include "support/TestPaths.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <limits>

namespace render_tests {
namespace {

using namespace testing_support;

constexpr double kPi = 3.14159265358979323846;

double totalProbability(const render::EnvironmentMap& map)
{
    double total = 0.0;
    for (int row = 0; row < map.height; ++row)
        for (int column = 0; column < map.width; ++column)
            total += map.texelProbability(column, row);
    return total;
}

double density(const render::EnvironmentMap& map, int column, int row)
{
    return map.texels[4 * (static_cast<std::size_t>(row) * map.width + column) + 3];
}

TEST(EnvironmentMapDistribution, AConstantMapIsSampledUniformlyOverTheSphere)
{
    const render::EnvironmentMap map =
        render::buildEnvironmentMap(constantEnvironmentMap(32, 16, glm::vec3(2.0f)));
    EXPECT_NEAR(totalProbability(map), 1.0, 1e-6);
    for (int row = 0; row < map.height; ++row)
        for (int column = 0; column < map.width; ++column)
            ASSERT_NEAR(density(map, column, row) * 4.0 * kPi, 1.0, 1e-4)
                << "texel (" << column << ", " << row
                << "): a map of one radiance should be sampled with density 1 / (4 pi), "
                   "not more at the poles, where its rows are squeezed";
    for (int channel = 0; channel < 3; ++channel)
        EXPECT_NEAR(map.integral[channel], 4.0 * kPi * 2.0, 1e-9)
            << "the radiance integrated over the sphere";
}

// Each texel's probability is its density times its solid angle, and they add up to 1.
TEST(EnvironmentMapDistribution, DensitiesAreTheProbabilitiesOverTheSolidAngles)
{
    const render::EnvironmentMap map =
        render::buildEnvironmentMap(skyWithSunEnvironmentMap(64, 32));
    EXPECT_NEAR(totalProbability(map), 1.0, 1e-6);
    double total = 0.0;
    for (int row = 0; row < map.height; ++row)
        for (int column = 0; column < map.width; ++column) {
            const double probability = map.texelProbability(column, row);
            total += density(map, column, row) * map.texelSolidAngle(row);
            ASSERT_NEAR(density(map, column, row) * map.texelSolidAngle(row), probability,
                        1e-6 * probability + 1e-12);
        }
    EXPECT_NEAR(total, 1.0, 1e-5);
}

// One bright texel in a black map: the bilinear filter lights its eight neighbours too
// (weights 3/4 for a texel's own span, 1/8 for each neighbour's, along each axis), so those
// and no others have a density, in those proportions times their solid angles.
TEST(EnvironmentMapDistribution, ABrightTexelAndTheNeighboursTheFilterLightsHoldItAll)
{
    constexpr int kColumn = 0;  // on the left edge: its left neighbours wrap round
    constexpr int kRow = 5;
    const render::EnvironmentMap map = render::buildEnvironmentMap(
        patchEnvironmentMap(16, 8, kColumn, kRow, 1, 1, glm::vec3(3.0f, 1.0f, 0.0f)));
    const double weights[3] = {0.125, 0.75, 0.125};
    double expectedTotal = 0.0;
    for (int dr = -1; dr <= 1; ++dr)
        for (int dc = -1; dc <= 1; ++dc)
            expectedTotal += weights[dr + 1] * weights[dc + 1] * map.texelSolidAngle(kRow + dr);
    for (int row = 0; row < map.height; ++row)
        for (int column = 0; column < map.width; ++column) {
            const int dr = row - kRow;
            const int dc = (column - kColumn + map.width + 1) % map.width - 1;
            const bool neighbour = std::abs(dr) <= 1 && std::abs(dc) <= 1;
            const double expected = neighbour ? weights[dr + 1] * weights[dc + 1] *
                                                    map.texelSolidAngle(row) / expectedTotal
                                              : 0.0;
            EXPECT_NEAR(map.texelProbability(column, row), expected, 1e-6)
                << "texel (" << column << ", " << row << ")";
        }
}

TEST(EnvironmentMapDistribution, NegativeValuesCountAsBlackAndGreyImagesAsWhiteLight)
{
    io::Image grey(4, 2, 1);
    for (float& value : grey.pixels)
        value = 0.5f;
    grey.at(1, 1, 0) = -3.0f;
    const render::EnvironmentMap map = render::buildEnvironmentMap(grey);
    EXPECT_EQ(map.texels[0], 0.5f);
    EXPECT_EQ(map.texels[1], 0.5f);
    EXPECT_EQ(map.texels[2], 0.5f);
    EXPECT_EQ(map.texels[4 * 5], 0.0f) << "a negative value (lossy compression leaves some)";
}

TEST(EnvironmentMapDistribution, AValueThatIsNotFiniteIsRefusedWithItsPlace)
{
    io::Image image = constantEnvironmentMap(4, 2, glm::vec3(1.0f));
    image.at(3, 1, 2) = std::numeric_limits<float>::quiet_NaN();
    try {
        render::buildEnvironmentMap(image);
        FAIL() << "a NaN in the map should be refused";
    } catch (const std::runtime_error& error) {
        EXPECT_NE(std::string(error.what()).find("column 3, row 1"), std::string::npos)
            << error.what();
    }
}

// --- files ----------------------------------------------------------------------------

TEST(EnvironmentMapFile, OpenExrAndRadianceHdrReadAlike)
{
    const io::Image image = skyWithSunEnvironmentMap(32, 16);
    const TemporaryImageFile exr(image, ".exr");
    const TemporaryImageFile hdr(image, ".hdr");
    const render::EnvironmentMap fromExr = render::loadEnvironmentMap(exr.path());
    const render::EnvironmentMap fromHdr = render::loadEnvironmentMap(hdr.path());
    ASSERT_EQ(fromExr.width, 32);
    ASSERT_EQ(fromHdr.width, 32);
    ASSERT_EQ(fromExr.height, 16);
    ASSERT_EQ(fromHdr.height, 16);
    for (std::size_t i = 0; i < fromExr.texels.size(); ++i)
        // RGBE keeps 8 bits of mantissa per channel beside a shared exponent: within 1 % of
        // the brightest channel.
        ASSERT_NEAR(fromHdr.texels[i], fromExr.texels[i],
                    0.01 * fromExr.texels[i - i % 4] + 0.01 * fromExr.texels[i - i % 4 + 1] + 1e-6)
            << "value " << i;
}

scene::Scene sceneWithMap(const std::string& file)
{
    const scene::FileLookup lookup(testScenesDirectory(), scene::FileLookup::dataDirectory());
    return scene::parseSceneText("0 0 5\n0 0 0\n0 1 0\n45\n0\n0\n0\n0\n\n\nenvironment map " +
                                     file + " intensity 2\n",
                                 "written-in-test.in", lookup);
}

std::string errorOf(const scene::Scene& scene)
{
    try {
        render::loadSceneEnvironmentMap(scene);
    } catch (const std::runtime_error& error) {
        return error.what();
    }
    return "";
}

TEST(EnvironmentMapFile, AnUnreadableMapIsASceneErrorWithFileLineAndTheLibrarysReason)
{
    const std::filesystem::path garbage =
        std::filesystem::temp_directory_path() / "raytracer-test-not-an-image.exr";
    {
        std::ofstream file(garbage);
        file << "not an image";
    }
    const std::string message = errorOf(sceneWithMap(garbage.string()));
    std::filesystem::remove(garbage);
    EXPECT_EQ(
        message.rfind("written-in-test.in:11: environment map '" + garbage.string() + "': ", 0), 0u)
        << message;
    EXPECT_NE(message.find("is not an OpenEXR file"), std::string::npos)
        << "the library's reason: " << message;
}

TEST(EnvironmentMapFile, AMapLargerThanTheLimitIsRefusedBeforeItsPixelsAreRead)
{
    const TemporaryImageFile wide(io::Image(render::kMaxEnvironmentMapWidth + 1, 1, 3), ".exr");
    const std::string message = errorOf(sceneWithMap(wide.path().string()));
    EXPECT_NE(message.find("at most 8192x4096"), std::string::npos) << message;
}

TEST(EnvironmentMapFile, ASceneWithoutAMapHasNone)
{
    const scene::FileLookup lookup(testScenesDirectory(), scene::FileLookup::dataDirectory());
    EXPECT_EQ(render::loadSceneEnvironmentMap(scene::parseSceneText(
                  "environment 1 1 1\n0 0 5\n0 0 0\n0 1 0\n45\n0\n0\n0\n0\n", "x.in", lookup)),
              nullptr);
}

}  // namespace
}  // namespace render_tests
