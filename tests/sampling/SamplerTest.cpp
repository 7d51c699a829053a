// The sampler of shaders/modules/sampler.glsl, run on the GPU with the renderer's own GLSL:
// it draws Sobol's points, every power-of-two prefix of a pixel's samples is stratified,
// and across pixels every sample is uniform and independent of the others (which is what
// keeps every estimate unbiased at any sample count).
#include "sampling/ShaderSampler.h"
#include "support/ChiSquare.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <sstream>
#include <vector>

namespace sampling_tests {
namespace {

using testing_support::chiSquareTest;

// The first two dimensions of the Sobol sequence from their definition: generator matrices
// from the direction numbers v_k = 2^31 >> k (dimension 1, van der Corput) and
// v_0 = 2^31, v_k = v_{k-1} ^ (v_{k-1} >> 1) (dimension 2, primitive polynomial x + 1),
// point i the xor of v_k over the bits k set in i (Bratley and Fox 1988; Joe and Kuo 2008).
glm::dvec2 sobolFromDirectionNumbers(std::uint32_t index)
{
    std::uint32_t first = 0, second = 0;
    std::uint32_t v = 1u << 31;
    for (int k = 0; k < 32; ++k) {
        if (index & (1u << k)) {
            first ^= (1u << 31) >> k;
            second ^= v;
        }
        v ^= v >> 1;
    }
    // The shader's 24-bit fraction: the top 24 bits.
    return glm::dvec2((first >> 8) / 16777216.0, (second >> 8) / 16777216.0);
}

TEST(Sampler, UnscrambledPointsAreTheFirstTwoSobolDimensions)
{
    const ShaderSampler sampler;
    const int count = 4096;
    const std::vector<glm::vec2> points = sampler.unscrambledSobol(count);
    for (int i = 0; i < count; ++i) {
        const glm::dvec2 expected = sobolFromDirectionNumbers(static_cast<std::uint32_t>(i));
        ASSERT_EQ(points[i].x, expected.x) << "point " << i << ", first dimension";
        ASSERT_EQ(points[i].y, expected.y) << "point " << i << ", second dimension";
    }
}

// The elementary intervals of base 2 with volume 2^-m: [a 2^-j, (a + 1) 2^-j) x
// [b 2^-(m-j), (b + 1) 2^-(m-j)). A (0, m, 2)-net has exactly one point in each.
bool isNet(const std::vector<glm::dvec2>& points, int m)
{
    const int n = 1 << m;
    for (int j = 0; j <= m; ++j) {
        std::vector<int> occupied(n, 0);
        for (const glm::dvec2& p : points) {
            const int a = static_cast<int>(p.x * (1 << j));
            const int b = static_cast<int>(p.y * (1 << (m - j)));
            if (++occupied[(a << (m - j)) + b] > 1)
                return false;
        }
    }
    return true;
}

TEST(Sampler, EveryPowerOfTwoPrefixOfAPixelsSamplesIsStratifiedInEachDecision)
{
    const ShaderSampler sampler;
    for (int dimension : {0, 1, 4, 9, 20}) {
        for (std::uint64_t seed : {1ull, 77ull}) {
            SamplerChoice choice;
            choice.onePixelSequence = true;
            choice.dimension = dimension;
            const std::vector<glm::vec3> numbers = sampler.samplerNumbers(1024, 1, seed, choice);
            for (int m = 1; m <= 10; ++m) {
                std::vector<glm::dvec2> prefix;
                std::vector<double> firsts;
                for (int i = 0; i < (1 << m); ++i) {
                    prefix.emplace_back(numbers[i].x, numbers[i].y);
                    firsts.push_back(numbers[i].z);
                }
                EXPECT_TRUE(isNet(prefix, m))
                    << "the first " << (1 << m) << " samples of dimension " << dimension
                    << " (seed " << seed << ") are not a (0, " << m << ", 2)-net";
                // The 1D decisions: one sample in each of the 2^m equal intervals.
                std::vector<int> intervals(1 << m, 0);
                bool stratified = true;
                for (double u : firsts)
                    stratified = stratified && ++intervals[static_cast<int>(u * (1 << m))] == 1;
                EXPECT_TRUE(stratified) << "the first " << (1 << m) << " 1D samples of dimension "
                                        << dimension << " (seed " << seed << ") are not stratified";
            }
        }
    }
}

// 512 x 512 pixels, each its own draw at one sample index.
constexpr int kSide = 512;

std::vector<glm::vec3> acrossPixels(const ShaderSampler& sampler, bool sobol, int index,
                                    int dimension, std::uint64_t seed)
{
    SamplerChoice choice;
    choice.sobol = sobol;
    choice.sampleIndex = index;
    choice.dimension = dimension;
    return sampler.samplerNumbers(kSide, kSide, seed, choice);
}

TEST(Sampler, EverySampleIsUniformOverTheSquareAcrossPixels)
{
    const ShaderSampler sampler;
    constexpr int kBins = 16;
    for (bool sobol : {true, false})
        for (int index : {0, 1, 2, 3, 7, 100, 1023}) {
            const std::vector<glm::vec3> numbers = acrossPixels(sampler, sobol, index, 4, 5);
            std::vector<double> observed(kBins * kBins + kBins, 0.0);
            for (const glm::vec3& u : numbers) {
                ASSERT_TRUE(u.x >= 0.0f && u.x < 1.0f && u.y >= 0.0f && u.y < 1.0f && u.z >= 0.0f &&
                            u.z < 1.0f);
                observed[static_cast<int>(u.x * kBins) * kBins + static_cast<int>(u.y * kBins)] +=
                    1;
                observed[kBins * kBins + static_cast<int>(u.z * kBins)] += 1;
            }
            // The 2D cells and, apart, the 1D intervals: two histograms of n samples each.
            const double n = static_cast<double>(numbers.size());
            std::vector<double> expected(kBins * kBins, n / (kBins * kBins));
            expected.insert(expected.end(), kBins, n / kBins);
            const auto result = chiSquareTest(observed, expected, 1e-4);
            EXPECT_TRUE(result.passed) << (sobol ? "sobol" : "independent") << " sample " << index
                                       << " is not uniform across pixels: " << result.describe();
        }
}

// Pearson's correlation of two sequences.
double correlation(const std::vector<double>& a, const std::vector<double>& b)
{
    double ma = 0.0, mb = 0.0;
    for (std::size_t i = 0; i < a.size(); ++i) {
        ma += a[i];
        mb += b[i];
    }
    ma /= a.size();
    mb /= b.size();
    double sab = 0.0, saa = 0.0, sbb = 0.0;
    for (std::size_t i = 0; i < a.size(); ++i) {
        sab += (a[i] - ma) * (b[i] - mb);
        saa += (a[i] - ma) * (a[i] - ma);
        sbb += (b[i] - mb) * (b[i] - mb);
    }
    return sab / std::sqrt(saa * sbb);
}

// (A pixel's own samples are correlated on purpose: stratified points repel each other.)
TEST(Sampler, DecisionsPixelsAndSeedsAreUncorrelated)
{
    const ShaderSampler sampler;
    // Under independence a correlation of n = 262144 pairs has standard deviation 1/sqrt(n),
    // about 0.002; 0.01 is five of them.
    const double limit = 0.01;
    const auto a = acrossPixels(sampler, true, 3, 4, 5);
    const auto b = acrossPixels(sampler, true, 3, 6, 5);  // another decision
    const auto c = acrossPixels(sampler, true, 3, 4, 6);  // another seed
    std::vector<double> ax, ay, bx, cx, neighbourX;
    for (int y = 0; y < kSide; ++y)
        for (int x = 0; x + 1 < kSide; ++x) {
            const int i = y * kSide + x;
            ax.push_back(a[i].x);
            ay.push_back(a[i].y);
            bx.push_back(b[i].x);
            cx.push_back(c[i].x);
            neighbourX.push_back(a[i + 1].x);
        }
    EXPECT_LT(std::abs(correlation(ax, ay)), limit) << "the two coordinates of one sample";
    EXPECT_LT(std::abs(correlation(ax, bx)), limit) << "two decisions of one sample";
    EXPECT_LT(std::abs(correlation(ax, cx)), limit) << "one decision under two seeds";
    EXPECT_LT(std::abs(correlation(ax, neighbourX)), limit) << "neighbouring pixels";
}

}  // namespace
}  // namespace sampling_tests
