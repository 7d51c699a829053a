// The scene files the project ships beside the classic ones: every example of the format
// reference (scenes/examples/) and every seed-figure scene (scenes/fig*.in) renders, and a
// solid written in the file's CSG syntax renders as the same solid written as a user SDF.
#include "support/ImageComparison.h"
#include "support/RenderRun.h"
#include "support/TestPaths.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

namespace render_tests {
namespace {

using namespace testing_support;
namespace fs = std::filesystem;

std::vector<std::string> shippedScenes()
{
    std::vector<std::string> names;
    for (const auto& entry : fs::directory_iterator(sourceDirectory() / "scenes" / "examples"))
        if (entry.path().extension() == ".in")
            names.push_back("examples/" + entry.path().filename().string());
    for (const auto& entry : fs::directory_iterator(sourceDirectory() / "scenes"))
        if (entry.path().extension() == ".in" && entry.path().filename().string().rfind("fig", 0) == 0)
            names.push_back(entry.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
}

class ShippedScene : public ::testing::TestWithParam<std::string> {};

TEST_P(ShippedScene, RendersFiniteAndNotBlack)
{
    const fs::path path = sourceDirectory() / "scenes" / GetParam();
    const RenderedImage image = renderScene(loadScene(path), 48, 36, 4, settingsWithSeed(1));
    EXPECT_EQ(image.discardedSamples, 0u) << path.string();
    double sum = 0.0;
    int nonFinite = 0;
    for (float value : image.radiance.pixels) {
        nonFinite += std::isfinite(value) ? 0 : 1;
        sum += value;
    }
    EXPECT_EQ(nonFinite, 0) << path.string();
    EXPECT_GT(sum, 0.0) << path.string() << " renders black";
}

INSTANTIATE_TEST_SUITE_P(Scenes, ShippedScene, ::testing::ValuesIn(shippedScenes()),
                         [](const ::testing::TestParamInfo<std::string>& info) {
                             std::string name = info.param;
                             for (char& c : name)
                                 if (!std::isalnum(static_cast<unsigned char>(c)))
                                     c = '_';
                             return name;
                         });

// The pairs are the seed's CSG solid (figures 4 and 12) written both ways; independent seeds,
// so the noise-aware comparison of the regression tests applies.
class CsgSyntaxTwin : public ::testing::TestWithParam<std::string> {};

TEST_P(CsgSyntaxTwin, RendersAsTheUserSdfItReplaces)
{
    const fs::path scenes = sourceDirectory() / "scenes";
    const std::string name = GetParam();
    const RenderedImage csg =
        renderScene(loadScene(scenes / (name + ".in")), 64, 48, 64, settingsWithSeed(11));
    const RenderedImage user = renderScene(loadScene(scenes / (name + "-usersdf.in")), 64, 48,
                                           64, settingsWithSeed(12));
    const Comparison comparison = compareImages(csg, user);
    EXPECT_TRUE(comparison.passed()) << name << " in CSG syntax against its user-SDF twin:\n"
                                     << comparison.describe();
}

INSTANTIATE_TEST_SUITE_P(Figures, CsgSyntaxTwin,
                         ::testing::Values("fig04-csg-solid", "fig12-csg-diffuse"),
                         [](const ::testing::TestParamInfo<std::string>& info) {
                             return info.param.substr(0, 5);
                         });

}  // namespace
}  // namespace render_tests
