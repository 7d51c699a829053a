#include "convergence/ImageErrors.h"

#include "film/ToneCurve.h"

#include <cmath>
#include <stdexcept>

namespace convergence {

namespace {

// Displayed value of one channel of linear radiance, on the 0..255 scale, unrounded: the
// display's tone curve (film/ToneCurve.h) in double at the default exposure.
double displayValue(double radiance)
{
    return 255.0 * film::displayValue(radiance, film::ToneCurve::kDefaultExposure);
}

void requireSameShape(const io::Image& a, const io::Image& b)
{
    if (a.width != b.width || a.height != b.height || a.channels != b.channels)
        throw std::runtime_error("images of different sizes compared");
}

}  // namespace

// Sum of `image` over every pixel and channel relative to the reference's, minus 1: a bias
// that darkens or brightens the image as a whole (paths cut short, light leaking) shows here
// clearly even when the per-pixel error is mostly noise, which averages out of the sum.
double brightnessBias(const io::Image& image, const io::Image& reference)
{
    requireSameShape(image, reference);
    double sum = 0.0;
    double referenceSum = 0.0;
    for (std::size_t i = 0; i < image.pixels.size(); ++i) {
        sum += image.pixels[i];
        referenceSum += reference.pixels[i];
    }
    return referenceSum > 0.0 ? sum / referenceSum - 1.0 : 0.0;
}

// Standard deviation of brightnessBias's image sum from noise, relative to `referenceSum`,
// from the renderer's per-pixel variance of the mean (sampleStatistics, channel b). That
// variance is the channels' average, and the channels' covariance is not kept: the
// channels are taken as fully correlated, which can only overstate the noise.
double brightnessNoise(const io::Image& statistics, double referenceSum)
{
    double variance = 0.0;
    for (int y = 0; y < statistics.height; ++y)
        for (int x = 0; x < statistics.width; ++x)
            variance += 9.0 * statistics.at(x, y, 2);
    return referenceSum > 0.0 ? std::sqrt(variance) / referenceSum : 0.0;
}

double imageSum(const io::Image& image)
{
    double sum = 0.0;
    for (float value : image.pixels)
        sum += value;
    return sum;
}

// Error of `image` against `reference`.
ImageError errorAgainst(const io::Image& image, const io::Image& reference)
{
    requireSameShape(image, reference);
    double relativeSum = 0.0;
    double toneSum = 0.0;
    for (std::size_t i = 0; i < image.pixels.size(); ++i) {
        const double x = image.pixels[i];
        const double r = reference.pixels[i];
        relativeSum += (x - r) * (x - r) / (r * r + kRelativeMseEpsilon);
        const double displayed = displayValue(x) - displayValue(r);
        toneSum += displayed * displayed;
    }
    const double count = static_cast<double>(image.pixels.size());
    return {relativeSum / count, std::sqrt(toneSum / count)};
}

// The error that noise alone puts in `full`, the mean of n samples, from `half`, the mean of
// the first n/2 of them (see the top of this file), weighted like errorAgainst(reference).
// For the tone-mapped image it holds to first order in the noise (the tone map's slope is
// taken as constant over the noise's spread).
ImageError noiseOfMean(const io::Image& half, const io::Image& full, const io::Image& reference)
{
    requireSameShape(half, full);
    requireSameShape(full, reference);
    double relativeSum = 0.0;
    double toneSum = 0.0;
    for (std::size_t i = 0; i < full.pixels.size(); ++i) {
        const double difference = static_cast<double>(full.pixels[i]) - half.pixels[i];
        const double r = reference.pixels[i];
        relativeSum += difference * difference / (r * r + kRelativeMseEpsilon);
        const double displayed = displayValue(full.pixels[i]) - displayValue(half.pixels[i]);
        toneSum += displayed * displayed;
    }
    const double count = static_cast<double>(full.pixels.size());
    return {relativeSum / count, std::sqrt(toneSum / count)};
}

}  // namespace convergence
