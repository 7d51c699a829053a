#pragma once
// The noise-aware comparison of a render with a reference (tests/README.md derives it).
//
// Both images are Monte Carlo estimates of one expected image. Pixels are grouped in square
// blocks; for each block the difference of the block sums is divided by its standard
// deviation, estimated from both images' per-pixel sample variances pooled (under the
// hypothesis being tested they estimate the same variance). Each block's z^2 is capped, and
// the capped sum over blocks is compared with a bound that a render agreeing with the
// reference exceeds with probability below `falsePositiveRate`, whatever the shape of the
// sample distribution (Bernstein's inequality; fireflies make it far from normal).
//
// Four quantities are tested: the mean of the three channels, whose variance the renderer's
// statistics bound directly, and each channel on its own, with the looser bound
// Var(channel) <= 3 * (mean of the three channel variances).
#include "support/RenderRun.h"

#include <string>
#include <vector>

namespace testing_support {

struct ComparisonSettings {
    int blockSize = 2;
    // A block's z^2 counts at most this much: |z| = 4, which a block without a regression
    // reaches by chance with probability 6e-5 when its mean is normal. Beyond it, one
    // firefly's block could outweigh the rest of the image.
    double zSquaredCap = 16.0;
    // Probability that a render agreeing with the reference fails (an upper bound).
    double falsePositiveRate = 1e-4;
};

struct BlockStatistic {
    std::string quantity;
    double cappedSum = 0.0;  // sum over blocks of min(z^2, cap)
    double threshold = 0.0;
    bool passed() const { return cappedSum <= threshold; }
};

struct Comparison {
    int blocksX = 0;
    int blocksY = 0;
    std::vector<BlockStatistic> statistics;
    // Signed z of the channel mean per block, row-major, top row first (for pictures).
    std::vector<double> channelMeanZ;
    int nonFiniteTestPixels = 0;
    int pixelsWithoutSamples = 0;

    bool passed() const;
    // One line per quantity: the statistic, its threshold, and the verdict.
    std::string describe() const;
};

// The bound on the sum over `blocks` of min(z^2, cap) that is exceeded with probability at
// most `falsePositiveRate` when every block has E[z^2] <= 1 (tests/README.md).
double cappedZSquaredThreshold(int blocks, double cap, double falsePositiveRate);

// `test` against `reference`, which must have the same size. Throws std::invalid_argument
// otherwise.
Comparison compareImages(const RenderedImage& test, const RenderedImage& reference,
                         const ComparisonSettings& settings = {});

}  // namespace testing_support
