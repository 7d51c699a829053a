#pragma once
#include "io/Image.h"

#include <optional>

namespace render {

// How far the running estimate still is from the converged image, judged from its own
// noise: the relative root-mean-square error
//
//     sqrt( mean over pixels and channels of Var[mean] )  /  mean over pixels and channels of radiance
//
// where Var[mean] = s^2 / n is each pixel's variance of its mean (the sample variance over
// its n samples). It is the expected RMS distance to the converged image, relative to the
// image's brightness; it falls as 1 / sqrt(n). It sees only the noise that the samples
// show: paths too rare to have been drawn yet, and bias, are not in it.
//
// `radiance`: linear RGB (ProgressiveRenderer::radiance). `statistics`: per pixel r = samples,
// b = variance of the mean, channel-averaged (ProgressiveRenderer::sampleStatistics).
// Pixels with fewer than two samples (whose variance is not known yet: the first frame, or a
// pixel whose every sample was discarded) are left out. Nothing when no pixel is left, when
// the image is black, or when the two images differ in size.
std::optional<double> relativeRmsError(const io::Image& radiance, const io::Image& statistics);

}  // namespace render
