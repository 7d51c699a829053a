#pragma once
// bench_convergence's errors of an image against a reference, over every pixel and colour
// channel (see the top of bench/convergence.cpp for what each one means).
#include "io/Image.h"

namespace convergence {

// The relative MSE's eps, in units of radiance squared. Without it, pixels whose reference is
// black (a red wall's green channel) would divide by zero, and nearly black ones (shadowed
// corners, where a sample's relative spread is largest) would outweigh everything a viewer
// sees. 0.01, the value common in the denoising literature, makes the error absolute below a
// radiance of 0.1 and relative above. Under the display's tone map radiance 0.1 is level 105
// of 255, so the darker part of the picture counts less than relatively; the tone RMSE,
// which weighs every displayed level alike, covers it.
constexpr double kRelativeMseEpsilon = 0.01;

struct ImageError {
    double relativeMse = 0.0;
    double toneMappedRmse = 0.0;
};

// Sum of `image` over every pixel and channel relative to the reference's, minus 1: a bias
// that darkens or brightens the image as a whole (paths cut short, light leaking) shows here
// clearly even when the per-pixel error is mostly noise, which averages out of the sum.
double brightnessBias(const io::Image& image, const io::Image& reference);

// Standard deviation of brightnessBias's image sum from noise, relative to `referenceSum`,
// from the renderer's per-pixel variance of the mean (sampleStatistics, channel b).
double brightnessNoise(const io::Image& statistics, double referenceSum);

double imageSum(const io::Image& image);

// Relative MSE and tone-mapped RMSE of `image` against `reference`.
ImageError errorAgainst(const io::Image& image, const io::Image& reference);

// The error that noise alone puts in `full`, the mean of n samples, from `half`, the mean of
// the first n/2 of them, weighted like errorAgainst(reference).
ImageError noiseOfMean(const io::Image& half, const io::Image& full, const io::Image& reference);

}  // namespace convergence
