#include "support/ImageComparison.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace testing_support {

namespace {

// The four quantities: the channel mean, then red, green and blue.
constexpr int kQuantities = 4;
const char* const kQuantityNames[kQuantities] = {"channel mean", "red", "green", "blue"};

// The running mean is float32: values that agree exactly in expectation may still differ by
// rounding, about 2^-24 per update. This floor, far above that and far below any noise,
// keeps a block with zero variance (a constant environment seen directly) from dividing
// rounding by zero.
constexpr double kRoundingFloor = 1.0 / (1 << 20);

double value(const RenderedImage& image, int quantity, int x, int y)
{
    if (quantity == 0)
        return channelMean(image.radiance, x, y);
    return image.radiance.at(x, y, quantity - 1);
}

}  // namespace

double cappedZSquaredThreshold(int blocks, double cap, double falsePositiveRate)
{
    // X_b = min(z_b^2, cap) lies in [0, cap] with E[X_b] <= 1, so Var(X_b) <= cap - 1, and
    // the blocks are independent (every pixel has its own random stream). Bernstein:
    //   P(sum X_b >= n + t) <= exp(-(t^2 / 2) / (n (cap - 1) + cap t / 3)).
    // Setting the right side to the false-positive rate and solving for t:
    const double logInverse = std::log(1.0 / falsePositiveRate);
    const double linear = logInverse * cap / 3.0;
    const double t = linear + std::sqrt(linear * linear + 2.0 * logInverse * blocks * (cap - 1.0));
    return blocks + t;
}

bool Comparison::passed() const
{
    if (nonFiniteTestPixels > 0 || pixelsWithoutSamples > 0)
        return false;
    return std::all_of(statistics.begin(), statistics.end(),
                       [](const BlockStatistic& statistic) { return statistic.passed(); });
}

std::string Comparison::describe() const
{
    std::string text;
    char line[256];
    const int blocks = blocksX * blocksY;
    for (const BlockStatistic& statistic : statistics) {
        std::snprintf(line, sizeof line,
                      "  %-12s sum of capped z^2 over %d blocks = %.1f (mean %.3f), threshold "
                      "%.1f (mean %.3f): %s\n",
                      statistic.quantity.c_str(), blocks, statistic.cappedSum,
                      statistic.cappedSum / blocks, statistic.threshold,
                      statistic.threshold / blocks, statistic.passed() ? "agrees" : "DIFFERS");
        text += line;
    }
    if (nonFiniteTestPixels > 0)
        text += "  the render has " + std::to_string(nonFiniteTestPixels) +
                " pixels that are NaN or infinite\n";
    if (pixelsWithoutSamples > 0)
        text += "  " + std::to_string(pixelsWithoutSamples) +
                " pixels have no valid sample in one of the images\n";
    return text;
}

Comparison compareImages(const RenderedImage& test, const RenderedImage& reference,
                         const ComparisonSettings& settings)
{
    if (test.width() != reference.width() || test.height() != reference.height())
        throw std::invalid_argument("cannot compare a " + std::to_string(test.width()) + "x" +
                                    std::to_string(test.height()) + " render with a " +
                                    std::to_string(reference.width()) + "x" +
                                    std::to_string(reference.height()) + " reference");

    const int width = test.width();
    const int height = test.height();
    const int block = settings.blockSize;
    Comparison comparison;
    comparison.blocksX = (width + block - 1) / block;
    comparison.blocksY = (height + block - 1) / block;
    const int blocks = comparison.blocksX * comparison.blocksY;

    std::vector<double> difference(static_cast<std::size_t>(blocks) * kQuantities, 0.0);
    std::vector<double> variance(static_cast<std::size_t>(blocks) * kQuantities, 0.0);

    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            bool finite = true;
            for (int c = 0; c < 3; ++c)
                finite = finite && std::isfinite(test.radiance.at(x, y, c));
            if (!finite) {
                ++comparison.nonFiniteTestPixels;
                continue;
            }
            const double testCount = test.samples(x, y);
            const double referenceCount = reference.samples(x, y);
            if (testCount < 1.0 || referenceCount < 1.0) {
                ++comparison.pixelsWithoutSamples;
                continue;
            }
            // Sums of squared deviations (channel means of them) back from the variances of
            // the means, pooled: one estimate of the per-sample variance from both images.
            const double testSquares =
                test.varianceOfMean(x, y) * testCount * std::max(testCount - 1.0, 0.0);
            const double referenceSquares = reference.varianceOfMean(x, y) * referenceCount *
                                            std::max(referenceCount - 1.0, 0.0);
            const double pooled =
                (testSquares + referenceSquares) / std::max(testCount + referenceCount - 2.0, 1.0);
            const double varianceOfDifference = pooled * (1.0 / testCount + 1.0 / referenceCount);

            const int b = (y / block) * comparison.blocksX + x / block;
            for (int q = 0; q < kQuantities; ++q) {
                const double a = value(test, q, x, y);
                const double r = value(reference, q, x, y);
                const double floor = kRoundingFloor * std::max(std::abs(a), std::abs(r));
                // The mean's variance is bounded by the channels' mean variance (Jensen); a
                // single channel's by three times it.
                const double bound = q == 0 ? varianceOfDifference : 3.0 * varianceOfDifference;
                difference[b * kQuantities + q] += a - r;
                variance[b * kQuantities + q] += bound + floor * floor;
            }
        }

    const double cap = settings.zSquaredCap;
    const double threshold =
        cappedZSquaredThreshold(blocks, cap, settings.falsePositiveRate / kQuantities);
    comparison.channelMeanZ.assign(blocks, 0.0);
    for (int q = 0; q < kQuantities; ++q) {
        BlockStatistic statistic;
        statistic.quantity = kQuantityNames[q];
        statistic.threshold = threshold;
        for (int b = 0; b < blocks; ++b) {
            const double d = difference[b * kQuantities + q];
            const double v = variance[b * kQuantities + q];
            double z = 0.0;
            if (v > 0.0)
                z = d / std::sqrt(v);
            else if (d != 0.0)
                z = d > 0.0 ? HUGE_VAL : -HUGE_VAL;
            statistic.cappedSum += std::min(z * z, cap);
            if (q == 0)
                comparison.channelMeanZ[b] = z;
        }
        comparison.statistics.push_back(statistic);
    }
    return comparison;
}

}  // namespace testing_support
