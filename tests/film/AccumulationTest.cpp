// Combining accumulations (film/Accumulation.h): the result must be the accumulation of
// all the samples, whatever way they were split, to float precision.
#include "film/Accumulation.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <random>
#include <vector>

namespace scale_out_tests {
namespace {

// What the shader does per sample (shaders/modules/path_tracer_main.glsl), in float.
void accumulateSample(film::Accumulation& accumulation, int x, int y, const float value[3])
{
    const float count = accumulation.estimate.at(x, y, 3) + 1.0f;
    for (int c = 0; c < 3; ++c) {
        const float deviation = value[c] - accumulation.estimate.at(x, y, c);
        accumulation.estimate.at(x, y, c) += deviation / count;
        accumulation.moments.at(x, y, c) +=
            deviation * (value[c] - accumulation.estimate.at(x, y, c));
    }
    accumulation.estimate.at(x, y, 3) = count;
}

// Samples of a path tracer's kind: mostly small, now and then a bright one.
struct Samples {
    std::vector<std::array<float, 3>> values;
};

Samples heavyTailedSamples(std::mt19937& random, int count)
{
    std::uniform_real_distribution<float> uniform(0.0f, 1.0f);
    Samples samples;
    for (int i = 0; i < count; ++i) {
        const float boost = uniform(random) < 0.02f ? 50.0f : 1.0f;
        samples.values.push_back({boost * uniform(random), boost * uniform(random) * 0.5f,
                                  boost * uniform(random) * 2.0f});
    }
    return samples;
}

// Exact mean and sum of squared deviations of one channel, in long double.
void exactMoments(const std::vector<std::array<float, 3>>& values, int channel, double& mean,
                  double& sumSquares)
{
    long double sum = 0.0L;
    for (const auto& value : values)
        sum += value[channel];
    const long double m = values.empty() ? 0.0L : sum / values.size();
    long double squares = 0.0L;
    for (const auto& value : values)
        squares += (value[channel] - m) * (value[channel] - m);
    mean = static_cast<double>(m);
    sumSquares = static_cast<double>(squares);
}

constexpr int kWidth = 8;
constexpr int kHeight = 6;

// One accumulation per part: part p of every pixel's samples accumulated as the shader
// accumulates them.
std::vector<film::Accumulation> accumulateInParts(const std::vector<std::vector<Samples>>& samples,
                                                  int parts)
{
    std::vector<film::Accumulation> accumulations(parts, film::Accumulation(kWidth, kHeight));
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x)
            for (int part = 0; part < parts; ++part)
                for (const auto& value : samples[y * kWidth + x][part].values)
                    accumulateSample(accumulations[part], x, y, value.data());
    return accumulations;
}

class CombinedAccumulation : public ::testing::Test {
protected:
    void SetUp() override
    {
        std::mt19937 random(2024);
        samples_.resize(kWidth * kHeight);
        for (int pixel = 0; pixel < kWidth * kHeight; ++pixel) {
            // Part sizes 0, 1, a few, many, depending on the pixel.
            const int sizes[3] = {pixel % 3, 1 + pixel % 5, 40 + 7 * (pixel % 11)};
            for (int size : sizes)
                samples_[pixel].push_back(heavyTailedSamples(random, size));
        }
        parts_ = accumulateInParts(samples_, 3);
    }

    std::vector<std::vector<Samples>> samples_;  // per pixel, per part
    std::vector<film::Accumulation> parts_;
};

TEST_F(CombinedAccumulation, HoldsTheMeanSecondMomentAndCountOfAllTheSamples)
{
    const film::Accumulation combined =
        film::combineAccumulations({&parts_[0], &parts_[1], &parts_[2]});
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x) {
            std::vector<std::array<float, 3>> all;
            for (const Samples& part : samples_[y * kWidth + x])
                all.insert(all.end(), part.values.begin(), part.values.end());
            EXPECT_EQ(combined.samplesKept(x, y), static_cast<float>(all.size()));
            for (int c = 0; c < 3; ++c) {
                double mean = 0.0;
                double sumSquares = 0.0;
                exactMoments(all, c, mean, sumSquares);
                // The parts' own float rounding, not the combination, sets the tolerance.
                EXPECT_NEAR(combined.estimate.at(x, y, c), mean, 1e-5 * std::abs(mean) + 1e-7)
                    << "pixel " << x << "," << y << " channel " << c;
                EXPECT_NEAR(combined.moments.at(x, y, c), sumSquares, 1e-4 * sumSquares + 1e-6)
                    << "pixel " << x << "," << y << " channel " << c;
            }
        }
}

TEST_F(CombinedAccumulation, IsAssociativeToFloatPrecision)
{
    const film::Accumulation ab = film::combineAccumulations({&parts_[0], &parts_[1]});
    const film::Accumulation bc = film::combineAccumulations({&parts_[1], &parts_[2]});
    const film::Accumulation left = film::combineAccumulations({&ab, &parts_[2]});
    const film::Accumulation right = film::combineAccumulations({&parts_[0], &bc});
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x)
            for (int c = 0; c < 4; ++c) {
                const float a = left.estimate.at(x, y, c);
                const float b = right.estimate.at(x, y, c);
                EXPECT_NEAR(a, b, 4e-7f * std::abs(a)) << "estimate " << x << "," << y << "," << c;
                const float m = left.moments.at(x, y, c);
                const float n = right.moments.at(x, y, c);
                EXPECT_NEAR(m, n, 4e-7f * std::abs(m)) << "moments " << x << "," << y << "," << c;
            }
}

TEST(CombineAccumulations, AddsDiscardedCountsAndLeavesAPartWithoutSamplesOut)
{
    film::Accumulation some(1, 1);
    const float value[3] = {1.0f, 2.0f, 3.0f};
    accumulateSample(some, 0, 0, value);
    some.moments.at(0, 0, 3) = 2.0f;
    film::Accumulation onlyDiscarded(1, 1);
    onlyDiscarded.moments.at(0, 0, 3) = 5.0f;
    const film::Accumulation combined = film::combineAccumulations({&onlyDiscarded, &some});
    EXPECT_EQ(combined.samplesKept(0, 0), 1.0f);
    EXPECT_EQ(combined.samplesDiscarded(0, 0), 7.0f);
    EXPECT_EQ(combined.samplesTaken(0, 0), 8.0f);
    for (int c = 0; c < 3; ++c)
        EXPECT_EQ(combined.estimate.at(0, 0, c), value[c]);
}

TEST(CombineAccumulations, RefusesAccumulationsOfDifferentSizes)
{
    const film::Accumulation a(4, 3);
    const film::Accumulation b(3, 4);
    EXPECT_THROW(film::combineAccumulations({&a, &b}), std::invalid_argument);
}

// Feature means combine weighted by the samples kept, the camera distance by the samples
// whose camera ray hit (kept x coverage); a part without features leaves the result without.
TEST(CombinedFeatures, AreWeightedByTheSamplesKeptAndTheDepthByTheSamplesThatHit)
{
    film::Accumulation a(1, 1);
    film::Accumulation b(1, 1);
    a.addEmptyFeatures();
    b.addEmptyFeatures();
    a.estimate.at(0, 0, 3) = 3.0f;  // 3 samples, 1 of them hit at distance 2
    b.estimate.at(0, 0, 3) = 1.0f;  // 1 sample, hit at distance 5
    const float albedoA[3] = {0.2f, 0.4f, 0.6f};
    const float albedoB[3] = {1.0f, 0.0f, 0.0f};
    for (int c = 0; c < 3; ++c) {
        a.albedoDepth.at(0, 0, c) = albedoA[c];
        b.albedoDepth.at(0, 0, c) = albedoB[c];
    }
    a.normalCoverage.at(0, 0, 1) = 1.0f / 3.0f;  // the one hit's normal (0, 1, 0), over 3
    b.normalCoverage.at(0, 0, 0) = 1.0f;
    a.albedoDepth.at(0, 0, 3) = 2.0f;
    b.albedoDepth.at(0, 0, 3) = 5.0f;
    a.normalCoverage.at(0, 0, 3) = 1.0f / 3.0f;
    b.normalCoverage.at(0, 0, 3) = 1.0f;

    const film::Accumulation both = film::combineAccumulations({&a, &b});
    ASSERT_TRUE(both.hasFeatures());
    EXPECT_FLOAT_EQ(both.albedoDepth.at(0, 0, 0), 0.4f);  // (3 x 0.2 + 1) / 4
    EXPECT_FLOAT_EQ(both.albedoDepth.at(0, 0, 1), 0.3f);
    EXPECT_FLOAT_EQ(both.albedoDepth.at(0, 0, 2), 0.45f);
    EXPECT_FLOAT_EQ(both.normalCoverage.at(0, 0, 0), 0.25f);
    EXPECT_FLOAT_EQ(both.normalCoverage.at(0, 0, 1), 0.25f);
    EXPECT_FLOAT_EQ(both.normalCoverage.at(0, 0, 3), 0.5f);  // 2 hits of 4
    EXPECT_FLOAT_EQ(both.albedoDepth.at(0, 0, 3), 3.5f);     // (2 + 5) / 2

    const film::Accumulation without(1, 1);
    EXPECT_FALSE(film::combineAccumulations({&a, &without}).hasFeatures());
}

}  // namespace
}  // namespace scale_out_tests
