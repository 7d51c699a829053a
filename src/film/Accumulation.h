#pragma once
// What a progressive render has gathered in each pixel, on the CPU: the two accumulation
// targets (render/AccumulationTargets.h) read back, top row first, or read from a file.
//   estimate  rgb: mean radiance of the samples kept, a: samples kept
//   moments   rgb: sum of squared deviations from that mean (Welford's M2), a: samples
//             discarded (NaN, infinite or negative)
// A pixel's next sample index is its kept plus discarded count (shaders/modules/sampler.glsl),
// so an accumulation is all a render needs to go on.
#include "io/Image.h"

#include <vector>

namespace film {

struct Accumulation {
    io::Image estimate;
    io::Image moments;

    Accumulation() = default;
    // Every pixel without a sample.
    Accumulation(int width, int height);

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
// in double precision, rounded to float once at the end.
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
