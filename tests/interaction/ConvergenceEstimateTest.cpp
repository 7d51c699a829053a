// render::relativeRmsError: the remaining relative error estimated from the per-pixel
// variance of the mean, on images whose answer is known.
#include "render/ConvergenceEstimate.h"

#include <gtest/gtest.h>

namespace interaction_tests {
namespace {

io::Image filled(int width, int height, float value)
{
    io::Image image(width, height, 3);
    for (float& pixel : image.pixels)
        pixel = value;
    return image;
}

// Statistics images: r samples, g discarded, b variance of the mean.
io::Image statistics(int width, int height, float samples, float varianceOfMean)
{
    io::Image image(width, height, 3);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            image.at(x, y, 0) = samples;
            image.at(x, y, 1) = 0.0f;
            image.at(x, y, 2) = varianceOfMean;
        }
    return image;
}

TEST(RelativeRmsError, IsTheRootMeanVarianceOverTheMeanRadiance)
{
    // sqrt(0.04) / 2 = 0.1
    const auto error = render::relativeRmsError(filled(4, 3, 2.0f), statistics(4, 3, 16, 0.04f));
    ASSERT_TRUE(error);
    EXPECT_NEAR(*error, 0.1, 1e-6);
}

TEST(RelativeRmsError, AveragesVarianceAndRadianceOverPixelsAndChannels)
{
    io::Image radiance(2, 1, 3);
    radiance.pixels = {1, 2, 3, 0, 0, 0};  // mean 1
    io::Image stats = statistics(2, 1, 8, 0.0f);
    stats.at(0, 0, 2) = 0.02f;
    stats.at(1, 0, 2) = 0.06f;  // mean variance 0.04
    EXPECT_NEAR(*render::relativeRmsError(radiance, stats), 0.2, 1e-6);
}

TEST(RelativeRmsError, LeavesOutPixelsWhoseVarianceIsNotKnownYet)
{
    io::Image stats = statistics(2, 1, 8, 0.04f);
    stats.at(1, 0, 0) = 1.0f;  // one sample: no variance
    stats.at(1, 0, 2) = 0.0f;
    io::Image radiance = filled(2, 1, 2.0f);
    radiance.at(1, 0, 0) = radiance.at(1, 0, 1) = radiance.at(1, 0, 2) = 100.0f;
    EXPECT_NEAR(*render::relativeRmsError(radiance, stats), 0.1, 1e-6);
}

TEST(RelativeRmsError, IsUnknownWithoutSamplesOrLight)
{
    EXPECT_FALSE(render::relativeRmsError(filled(2, 2, 1.0f), statistics(2, 2, 1, 0.0f)));
    EXPECT_FALSE(render::relativeRmsError(filled(2, 2, 0.0f), statistics(2, 2, 8, 0.0f)));
    EXPECT_FALSE(render::relativeRmsError(filled(2, 2, 1.0f), statistics(3, 2, 8, 0.1f)));
}

}  // namespace
}  // namespace interaction_tests
