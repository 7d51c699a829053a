// Long accumulations do not drift: the estimate is a running mean in float32, which does
// not lose the low digits of new samples the way a growing float32 sum does.
#include "hard/HardCaseSupport.h"

#include <gtest/gtest.h>

#include <cmath>

namespace {

// The camera sees only a constant environment: every sample is exactly the same value, so
// the mean must be that value to float precision after 100 000 samples. (A float32 running
// sum of 100 000 copies of 0.1 is off by about 1e-3 relative.)
TEST(LongAccumulation, HundredThousandSamplesOfConstantRadianceStayExact)
{
    hard::RenderRequest request;
    request.sceneText = "environment 0.1 0.2 0.3\n0 0 0\n0 0 -1\n0 1 0\n40\n0\n0\n0\n0\n";
    request.width = 4;
    request.height = 4;
    request.samplesPerPixel = 100000;
    request.settings.samplesPerFrame = 5000;
    const hard::RenderOutput output = hard::render(request);
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 4; ++x) {
            EXPECT_EQ(output.statistics.at(x, y, 0), 100000.0f);
            EXPECT_NEAR(output.radiance.at(x, y, 0), 0.1f, 1e-4 * 0.1);
            EXPECT_NEAR(output.radiance.at(x, y, 2), 0.3f, 1e-4 * 0.3);
        }
}

// A Lambertian floor of albedo 1 under the format's sky: its radiance is the cosine-weighted
// average of 0.5 (0.7, 0.8, 1) (1 - 0.5 y), which is 0.5 (0.7, 0.8, 1) (1 - 1/3) since the
// mean of y under cosine weighting is 2/3. Each sample is random; 100 000 of them must land
// within their standard error of that truth.
TEST(LongAccumulation, HundredThousandNoisySamplesConvergeToTheTruth)
{
    hard::RenderRequest request;
    request.sceneText = "environment sky\n0 1 0\n0 0 0\n0 0 -1\n10\n0\n1\nsolid 1 1 1\n1\n"
                        "0 0 0 0 0 0 0\n1\n0 0 polyhedron 1 0 1 0 0\n";
    request.width = 4;
    request.height = 4;
    request.samplesPerPixel = 100000;
    request.settings.samplesPerFrame = 5000;
    const hard::RenderOutput output = hard::render(request);
    const double truth = 0.5 * 1.0 * (2.0 / 3.0);
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 4; ++x) {
            const double standardError = std::sqrt(output.statistics.at(x, y, 2));
            EXPECT_NEAR(output.radiance.at(x, y, 2), truth, 5.0 * standardError + 1e-6)
                << "pixel (" << x << ", " << y << ")";
        }
}

// One frame of 64 samples per pixel and 64 frames of one sample draw the same random
// numbers in the same order and update the same running mean: the images are identical.
TEST(LongAccumulation, ManyFramesEqualOneFrameOfAsManySamples)
{
    hard::RenderRequest request;
    request.sceneText = hard::sceneFile("cornell.in");
    request.samplesPerPixel = 64;
    request.settings.samplesPerFrame = 1;
    const hard::RenderOutput frames = hard::render(request);
    request.settings.samplesPerFrame = 64;
    const hard::RenderOutput single = hard::render(request);
    ASSERT_EQ(frames.radiance.pixels.size(), single.radiance.pixels.size());
    for (std::size_t i = 0; i < frames.radiance.pixels.size(); ++i)
        ASSERT_EQ(frames.radiance.pixels[i], single.radiance.pixels[i]) << "value " << i;
}

}  // namespace
