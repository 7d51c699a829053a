#pragma once
// What a progressive render has gathered in each pixel, on the CPU: the two accumulation
// targets (render/AccumulationTargets.h) read back, top row first, or read from a file.
//   estimate  rgb: mean radiance of the samples kept, a: samples kept
//   moments   rgb: sum of squared deviations from that mean (Welford's M2), a: samples
//             discarded (NaN, infinite or negative)
// A pixel's next sample index is its kept plus discarded count (shaders/modules/sampler.glsl),
// so an accumulation is all a render needs to go on.
// With feature buffers (--feature-buffers, docs/DENOISING.md), each the mean over the samples
// kept, of what each sample's camera path met first:
//   albedoDepth     rgb: the albedo of the first surface that is not a perfect mirror or
//                   glass (tinted by those passed through; the environment's radiance,
//                   clamped to 1, where the path escapes), a: the camera ray's distance to
//                   its first hit, the mean over the samples whose camera ray hit something
//   normalCoverage  rgb: that surface's world-space normal (0 where none), a: the fraction
//                   of samples whose camera ray hit something (its depth's weight)
// Both empty (width 0) in a render without them.
#include "io/Image.h"

#include <cstdint>
#include <vector>

namespace film {

// The most samples a pixel holds: counts are 32-bit floats (on the GPU and in the file),
// which hold every whole number up to 2^24 exactly.
inline constexpr std::int64_t kLargestSampleCount = std::int64_t(1) << 24;

struct Accumulation {
    io::Image estimate;
    io::Image moments;
    io::Image albedoDepth;
    io::Image normalCoverage;

    Accumulation() = default;
    // Every pixel without a sample.
    Accumulation(int width, int height);

    bool hasFeatures() const { return albedoDepth.width > 0; }
    // Gives every pixel zero features (no sample kept), making hasFeatures() true.
    void addEmptyFeatures();
    int width() const { return estimate.width; }
    int height() const { return estimate.height; }
    float samplesKept(int x, int y) const { return estimate.at(x, y, 3); }
    float samplesDiscarded(int x, int y) const { return moments.at(x, y, 3); }
    // Kept and discarded: the samples the pixel has taken, the index of its next.
    float samplesTaken(int x, int y) const { return samplesKept(x, y) + samplesDiscarded(x, y); }
    // The pixel's mean radiance, averaged over the channels.
    double meanRadiance(int x, int y) const
    {
        return (static_cast<double>(estimate.at(x, y, 0)) + estimate.at(x, y, 1) +
                estimate.at(x, y, 2)) /
               3.0;
    }
    // The variance of one sample, s^2 = M2 / (n - 1), averaged over the channels; 0 below two
    // samples kept, where it is not known.
    double sampleVariance(int x, int y) const;
};

// The accumulation that holds every sample of `parts` (same size; throws
// std::invalid_argument otherwise), pixel by pixel, as if one render had taken them all:
// counts add, and means and second moments combine exactly by the pairwise formula of Chan,
// Golub and LeVeque ("Updating formulae and a pairwise algorithm for computing sample
// variances", 1979):
//   n = na + nb,  d = mean_b - mean_a,  mean = mean_a + d nb / n,  M2 = M2a + M2b + d^2 na nb / n
// in double precision, rounded to float once at the end. Feature means combine weighted by
// the samples kept (depth by the samples that hit), where every part has them; the result
// has none where one part has none.
Accumulation combineAccumulations(const std::vector<const Accumulation*>& parts);

// Linear radiance, RGB.
io::Image meanRadiance(const Accumulation& accumulation);

// Per pixel: samples kept, samples discarded, variance of the mean radiance (the channel
// average of M2 / (n (n - 1)); 0 below two samples). The statistics file holds these.
io::Image sampleStatistics(const Accumulation& accumulation);

// The fewest and the most samples (kept and discarded) a pixel holds.
struct SampleCountSpan {
    int fewest = 0;
    int most = 0;
};
SampleCountSpan samplesTakenSpan(const Accumulation& accumulation);

// Samples (kept and discarded) over the whole image.
double samplesTakenInAll(const Accumulation& accumulation);

}  // namespace film
