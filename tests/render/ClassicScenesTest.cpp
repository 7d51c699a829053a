// Every classic scene renders without a single NaN, infinite or negative sample (the
// renderer discards and counts them: one would otherwise stay in a pixel's mean forever).
#include "support/RenderRun.h"
#include "support/TestPaths.h"

#include <gtest/gtest.h>

#include <cmath>

namespace render_tests {
namespace {

using namespace testing_support;

class ClassicScene : public ::testing::TestWithParam<int> {};

TEST_P(ClassicScene, RendersWithoutNanOrInfiniteSamples)
{
    const auto path = sourceDirectory() / "scenes" / ("scene" + std::to_string(GetParam()) + ".in");
    const RenderedImage image = renderScene(loadScene(path), 64, 48, 8, settingsWithSeed(1));
    EXPECT_EQ(image.discardedSamples, 0u)
        << path.string() << ": samples discarded as NaN, infinite or negative at 64x48, 8 spp";
    int nonFinite = 0;
    for (float value : image.radiance.pixels)
        nonFinite += std::isfinite(value) ? 0 : 1;
    EXPECT_EQ(nonFinite, 0) << path.string() << ": non-finite values in the image";
}

INSTANTIATE_TEST_SUITE_P(Scene, ClassicScene, ::testing::Range(1, 8),
                         [](const ::testing::TestParamInfo<int>& info) {
                             return "scene" + std::to_string(info.param);
                         });

}  // namespace
}  // namespace render_tests
