#include "film/Accumulation.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace film {

Accumulation::Accumulation(int width, int height)
    : estimate(width, height, 4), moments(width, height, 4)
{
}

void Accumulation::addEmptyFeatures()
{
    albedoDepth = io::Image(width(), height(), 4);
    normalCoverage = io::Image(width(), height(), 4);
}

double Accumulation::sampleVariance(int x, int y) const
{
    const double kept = samplesKept(x, y);
    if (!(kept >= 2.0))
        return 0.0;
    const double sumSquares =
        (static_cast<double>(moments.at(x, y, 0)) + moments.at(x, y, 1) + moments.at(x, y, 2)) /
        3.0;
    return std::max(0.0, sumSquares / (kept - 1.0));
}

namespace {

// Means weighted by the samples kept; the depth by the samples that hit (kept x coverage).
void combineFeatures(const std::vector<const Accumulation*>& parts, int x, int y,
                     Accumulation& combined)
{
    double kept = 0.0;
    double hits = 0.0;
    double sums[8] = {};
    for (const Accumulation* part : parts) {
        const double partKept = part->samplesKept(x, y);
        const double partHits = partKept * part->normalCoverage.at(x, y, 3);
        kept += partKept;
        hits += partHits;
        for (int c = 0; c < 3; ++c) {
            sums[c] += partKept * part->albedoDepth.at(x, y, c);
            sums[4 + c] += partKept * part->normalCoverage.at(x, y, c);
        }
        sums[3] += partHits * part->albedoDepth.at(x, y, 3);
        sums[7] += partHits;
    }
    for (int c = 0; c < 3; ++c) {
        combined.albedoDepth.at(x, y, c) = kept > 0.0 ? static_cast<float>(sums[c] / kept) : 0.0f;
        combined.normalCoverage.at(x, y, c) =
            kept > 0.0 ? static_cast<float>(sums[4 + c] / kept) : 0.0f;
    }
    combined.albedoDepth.at(x, y, 3) = hits > 0.0 ? static_cast<float>(sums[3] / hits) : 0.0f;
    combined.normalCoverage.at(x, y, 3) = kept > 0.0 ? static_cast<float>(hits / kept) : 0.0f;
}

}  // namespace

Accumulation combineAccumulations(const std::vector<const Accumulation*>& parts)
{
    if (parts.empty())
        throw std::invalid_argument("no accumulation to combine");
    const int width = parts.front()->width();
    const int height = parts.front()->height();
    for (const Accumulation* part : parts)
        if (part->width() != width || part->height() != height)
            throw std::invalid_argument("accumulations of different sizes cannot be combined");

    Accumulation combined(width, height);
    const bool features = std::all_of(parts.begin(), parts.end(),
                                      [](const Accumulation* part) { return part->hasFeatures(); });
    if (features)
        combined.addEmptyFeatures();
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            double count = 0.0;
            double discarded = 0.0;
            double mean[3] = {0.0, 0.0, 0.0};
            double sumSquares[3] = {0.0, 0.0, 0.0};
            for (const Accumulation* part : parts) {
                discarded += part->samplesDiscarded(x, y);
                const double partCount = part->samplesKept(x, y);
                if (partCount <= 0.0)
                    continue;
                const double total = count + partCount;
                for (int c = 0; c < 3; ++c) {
                    const double delta = part->estimate.at(x, y, c) - mean[c];
                    mean[c] += delta * partCount / total;
                    sumSquares[c] +=
                        part->moments.at(x, y, c) + delta * delta * count * partCount / total;
                }
                count = total;
            }
            for (int c = 0; c < 3; ++c) {
                combined.estimate.at(x, y, c) = static_cast<float>(mean[c]);
                combined.moments.at(x, y, c) = static_cast<float>(sumSquares[c]);
            }
            combined.estimate.at(x, y, 3) = static_cast<float>(count);
            combined.moments.at(x, y, 3) = static_cast<float>(discarded);
            if (features)
                combineFeatures(parts, x, y, combined);
        }
    return combined;
}

io::Image meanRadiance(const Accumulation& accumulation)
{
    io::Image radiance(accumulation.width(), accumulation.height(), 3);
    for (int y = 0; y < radiance.height; ++y)
        for (int x = 0; x < radiance.width; ++x)
            for (int c = 0; c < 3; ++c)
                radiance.at(x, y, c) = accumulation.estimate.at(x, y, c);
    return radiance;
}

io::Image sampleStatistics(const Accumulation& accumulation)
{
    io::Image statistics(accumulation.width(), accumulation.height(), 3);
    for (int y = 0; y < statistics.height; ++y)
        for (int x = 0; x < statistics.width; ++x) {
            const float count = accumulation.samplesKept(x, y);
            const io::Image& moments = accumulation.moments;
            const float sumSquares =
                (moments.at(x, y, 0) + moments.at(x, y, 1) + moments.at(x, y, 2)) / 3.0f;
            statistics.at(x, y, 0) = count;
            statistics.at(x, y, 1) = accumulation.samplesDiscarded(x, y);
            statistics.at(x, y, 2) = count > 1.0f ? sumSquares / (count * (count - 1.0f)) : 0.0f;
        }
    return statistics;
}

SampleCountSpan samplesTakenSpan(const Accumulation& accumulation)
{
    if (accumulation.width() <= 0 || accumulation.height() <= 0)
        return {};
    float fewest = std::numeric_limits<float>::max();
    float most = 0.0f;
    for (int y = 0; y < accumulation.height(); ++y)
        for (int x = 0; x < accumulation.width(); ++x) {
            fewest = std::min(fewest, accumulation.samplesTaken(x, y));
            most = std::max(most, accumulation.samplesTaken(x, y));
        }
    return {static_cast<int>(std::lround(fewest)), static_cast<int>(std::lround(most))};
}

double samplesTakenInAll(const Accumulation& accumulation)
{
    double total = 0.0;
    for (int y = 0; y < accumulation.height(); ++y)
        for (int x = 0; x < accumulation.width(); ++x)
            total += accumulation.samplesTaken(x, y);
    return total;
}

}  // namespace film
