#pragma once
#include "film/Accumulation.h"

#include <optional>

namespace film {

// How far the running estimate still is from the converged image, judged from its own
// noise: the relative root-mean-square error
//
//     E = sqrt( mean over pixels and channels of Var[mean] )  /  mean over pixels and channels of radiance
//
// where Var[mean] = s^2 / n is each pixel's variance of its mean (the sample variance over
// its n samples). E is the expected RMS distance to the converged image, relative to the
// image's brightness: the same metric as a rel RMSE against a reference, sqrt(mean((x -
// ref)^2)) / mean(ref), less the reference's own noise. It falls as 1 / sqrt(n). It sees
// only the noise the samples show: paths too rare to have been drawn yet, and bias, are not
// in it. With Sobol points (the default sampler) the true error of smooth pixels falls
// faster than s^2 / n says, so E is then an upper estimate (docs/ACCURACY.md measures by how
// much).
struct ErrorEstimate {
    double relativeError = 0.0;
    // One standard deviation of relativeError itself, from how much the per-pixel variances
    // scatter (see estimateRelativeError).
    double uncertainty = 0.0;
    double meanRadiance = 0.0;
    // relativeError plus two standard deviations: what a render to a target stops on.
    double upperBound() const { return relativeError + 2.0 * uncertainty; }
};

// E from an accumulation, with its uncertainty. Each pixel's s^2 / n is an unbiased but noisy
// estimate of its variance of the mean, and heavy-tailed where rare bright paths are: one
// firefly multiplies it. Half the mean squared difference between horizontally neighbouring
// pixels' s^2 / n bounds the variance of one pixel's (exactly, where neighbours share their
// true variance; from above, where the image changes between them), so the image-wide mean
// has a standard error of sqrt(that / pixels); the delta method carries it to E (a relative
// error of the variance halves in its square root), and the mean radiance's own standard
// error (E / sqrt(pixels), relative) is added in quadrature.
// Pixels with fewer than two samples kept (the first frame, or every sample discarded) are
// left out. Nothing when no pixel is left or the size is zero; an image that is black
// everywhere, noise included, has E = 0.
std::optional<ErrorEstimate> estimateRelativeError(const Accumulation& accumulation);

}  // namespace film
