#include "film/ConvergenceEstimate.h"

#include <cmath>
#include <vector>

namespace film {

namespace {

// The variance of the pixel's mean; negative where it is not known.
double varianceOfMean(const Accumulation& accumulation, int x, int y)
{
    const double kept = accumulation.samplesKept(x, y);
    return kept >= 2.0 ? accumulation.sampleVariance(x, y) / kept : -1.0;
}

}  // namespace

std::optional<ErrorEstimate> estimateRelativeError(const Accumulation& accumulation)
{
    const int width = accumulation.width();
    const int height = accumulation.height();
    if (width <= 0 || height <= 0)
        return std::nullopt;
    double varianceSum = 0.0;
    double radianceSum = 0.0;
    double neighbourDifferenceSquares = 0.0;
    long pixels = 0;
    long neighbourPairs = 0;
    std::vector<double> row(static_cast<std::size_t>(width));
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const double variance = varianceOfMean(accumulation, x, y);
            row[x] = variance;
            if (variance < 0.0)
                continue;
            varianceSum += variance;
            radianceSum += accumulation.meanRadiance(x, y);
            ++pixels;
            if (x > 0 && row[x - 1] >= 0.0) {
                const double difference = variance - row[x - 1];
                neighbourDifferenceSquares += difference * difference;
                ++neighbourPairs;
            }
        }
    if (pixels == 0)
        return std::nullopt;
    ErrorEstimate estimate;
    estimate.meanRadiance = radianceSum / static_cast<double>(pixels);
    const double meanVariance = varianceSum / static_cast<double>(pixels);
    if (!(estimate.meanRadiance > 0.0))
        return estimate;  // black everywhere: samples are never negative, so no noise either
    estimate.relativeError = std::sqrt(meanVariance) / estimate.meanRadiance;
    if (meanVariance > 0.0) {
        const double perPixelVariance = neighbourPairs > 0
                                            ? 0.5 * neighbourDifferenceSquares / neighbourPairs
                                            : meanVariance * meanVariance;
        const double varianceRelativeError =
            std::sqrt(perPixelVariance / static_cast<double>(pixels)) / meanVariance;
        const double meanRelativeError =
            estimate.relativeError / std::sqrt(static_cast<double>(pixels));
        estimate.uncertainty =
            estimate.relativeError * std::hypot(0.5 * varianceRelativeError, meanRelativeError);
    }
    return estimate;
}

}  // namespace film
