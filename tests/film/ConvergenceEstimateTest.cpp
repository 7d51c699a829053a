// film::estimateRelativeError: the remaining relative error estimated from the per-pixel
// variance of the mean, and its uncertainty, on accumulations whose answer is known.
#include "film/ConvergenceEstimate.h"

#include "film/AccumulationBuilders.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace interaction_tests {
namespace {

// Every pixel as accumulationOf, its variance of the mean s^2 / n `varianceOfMean`.
film::Accumulation uniformAccumulation(int width, int height, float radiance, float samples,
                                       float varianceOfMean)
{
    return accumulationOf(width, height, radiance, samples, varianceOfMean * samples);
}

void setVarianceOfMean(film::Accumulation& accumulation, int x, int y, float varianceOfMean)
{
    setSampleVariance(accumulation, x, y, varianceOfMean * accumulation.samplesKept(x, y));
}

TEST(RelativeErrorEstimate, IsTheRootMeanVarianceOverTheMeanRadiance)
{
    // sqrt(0.04) / 2 = 0.1
    const auto estimate = film::estimateRelativeError(uniformAccumulation(4, 3, 2.0f, 16, 0.04f));
    ASSERT_TRUE(estimate);
    EXPECT_NEAR(estimate->relativeError, 0.1, 1e-6);
    EXPECT_NEAR(estimate->meanRadiance, 2.0, 1e-6);
}

TEST(RelativeErrorEstimate, AveragesVarianceAndRadianceOverPixelsAndChannels)
{
    film::Accumulation accumulation = uniformAccumulation(2, 1, 0.0f, 8, 0.0f);
    accumulation.estimate.at(0, 0, 0) = 1.0f;
    accumulation.estimate.at(0, 0, 1) = 2.0f;
    accumulation.estimate.at(0, 0, 2) = 3.0f;  // mean over both pixels and channels: 1
    setVarianceOfMean(accumulation, 0, 0, 0.02f);
    setVarianceOfMean(accumulation, 1, 0, 0.06f);  // mean variance 0.04
    EXPECT_NEAR(film::estimateRelativeError(accumulation)->relativeError, 0.2, 1e-6);
}

TEST(RelativeErrorEstimate, LeavesOutPixelsWhoseVarianceIsNotKnownYet)
{
    film::Accumulation accumulation = uniformAccumulation(2, 1, 2.0f, 8, 0.04f);
    accumulation.estimate.at(1, 0, 3) = 1.0f;  // one sample: no variance
    for (int c = 0; c < 3; ++c) {
        accumulation.estimate.at(1, 0, c) = 100.0f;
        accumulation.moments.at(1, 0, c) = 0.0f;
    }
    EXPECT_NEAR(film::estimateRelativeError(accumulation)->relativeError, 0.1, 1e-6);
}

TEST(RelativeErrorEstimate, IsUnknownWithoutSamples)
{
    EXPECT_FALSE(film::estimateRelativeError(uniformAccumulation(2, 2, 1.0f, 1, 0.0f)));
    EXPECT_FALSE(film::estimateRelativeError(film::Accumulation(0, 0)));
}

TEST(RelativeErrorEstimate, IsZeroForAnImageBlackEverywhere)
{
    const auto estimate = film::estimateRelativeError(uniformAccumulation(2, 2, 0.0f, 8, 0.0f));
    ASSERT_TRUE(estimate);
    EXPECT_EQ(estimate->relativeError, 0.0);
    EXPECT_EQ(estimate->uncertainty, 0.0);
}

// Variances alternating 0.02 and 0.06 along rows: neighbours differ by 0.04, so one pixel's
// variance scatters by 0.5 * 0.04^2 = 0.0008 in variance; over 100 pixels the mean 0.04 is
// known to sqrt(0.0008 / 100) = 0.00283, 7.07 % of it, 3.54 % of E = 0.1 after the square
// root; the mean radiance adds E / sqrt(100) = 10 % in quadrature: 0.1 * 3.67 %.
TEST(RelativeErrorEstimate, UncertaintyFollowsTheScatterOfPixelVariances)
{
    film::Accumulation accumulation = uniformAccumulation(10, 10, 2.0f, 16, 0.0f);
    for (int y = 0; y < 10; ++y)
        for (int x = 0; x < 10; ++x)
            setVarianceOfMean(accumulation, x, y, x % 2 == 0 ? 0.02f : 0.06f);
    const auto estimate = film::estimateRelativeError(accumulation);
    ASSERT_TRUE(estimate);
    EXPECT_NEAR(estimate->relativeError, 0.1, 1e-6);
    EXPECT_NEAR(estimate->uncertainty, 0.1 * std::hypot(0.5 * 0.0707107, 0.01), 1e-5);
    EXPECT_NEAR(estimate->upperBound(), estimate->relativeError + 2.0 * estimate->uncertainty,
                1e-12);
}

// Accumulations built from heavy-tailed samples (exponential, as the radiance of a diffuse
// path is nearer to than a Gaussian) of a known mean: the error of each image against that
// mean lies within the estimate's two standard deviations, plus the error's own spread,
// in nearly every trial.
TEST(RelativeErrorEstimate, CoversTheTrueErrorOfHeavyTailedSamples)
{
    std::mt19937 random(7);
    constexpr int kWidth = 32;
    constexpr int kHeight = 24;
    constexpr int kSamples = 16;
    constexpr int kTrials = 40;
    int covered = 0;
    for (int trial = 0; trial < kTrials; ++trial) {
        film::Accumulation accumulation(kWidth, kHeight);
        double squaredError = 0.0;
        double meanSum = 0.0;
        for (int y = 0; y < kHeight; ++y)
            for (int x = 0; x < kWidth; ++x) {
                // Brightness varying over the image, as a scene's does.
                const double trueMean = 0.5 + 2.0 * x / kWidth;
                std::exponential_distribution<double> sample(1.0 / trueMean);
                for (int c = 0; c < 3; ++c) {
                    double mean = 0.0;
                    double sumSquares = 0.0;
                    for (int n = 1; n <= kSamples; ++n) {
                        const double value = sample(random);
                        const double deviation = value - mean;
                        mean += deviation / n;
                        sumSquares += deviation * (value - mean);
                    }
                    accumulation.estimate.at(x, y, c) = static_cast<float>(mean);
                    accumulation.moments.at(x, y, c) = static_cast<float>(sumSquares);
                    squaredError += (mean - trueMean) * (mean - trueMean);
                    meanSum += trueMean;
                }
                accumulation.estimate.at(x, y, 3) = kSamples;
            }
        const double pixelsAndChannels = 3.0 * kWidth * kHeight;
        const double trueError =
            std::sqrt(squaredError / pixelsAndChannels) / (meanSum / pixelsAndChannels);
        const auto estimate = film::estimateRelativeError(accumulation);
        ASSERT_TRUE(estimate);
        // The squared error of 3 x 768 independent values scatters by about
        // sqrt(2 / 2304) of itself (more for these tails): 3 % in E; 4 % allowed.
        const double spread = std::hypot(2.0 * estimate->uncertainty, 0.04 * trueError);
        if (std::abs(trueError - estimate->relativeError) <= spread)
            ++covered;
    }
    EXPECT_GE(covered, kTrials * 9 / 10);
}

}  // namespace
}  // namespace interaction_tests
