#pragma once
// Accumulations whose noise is known, for the tests of what is estimated from them.
#include "film/Accumulation.h"

namespace interaction_tests {

// Sets the pixel's second moments so that its samples kept have variance `sampleVariance`
// (s^2 = M2 / (n - 1), every channel).
inline void setSampleVariance(film::Accumulation& accumulation, int x, int y, float sampleVariance)
{
    const float kept = accumulation.samplesKept(x, y);
    for (int c = 0; c < 3; ++c)
        accumulation.moments.at(x, y, c) = sampleVariance * (kept - 1.0f);
}

// Every pixel: `samples` samples kept of mean `radiance` (every channel), of variance
// `sampleVariance`.
inline film::Accumulation accumulationOf(int width, int height, float radiance, float samples,
                                         float sampleVariance)
{
    film::Accumulation accumulation(width, height);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            for (int c = 0; c < 3; ++c)
                accumulation.estimate.at(x, y, c) = radiance;
            accumulation.estimate.at(x, y, 3) = samples;
            setSampleVariance(accumulation, x, y, sampleVariance);
        }
    return accumulation;
}

}  // namespace interaction_tests
