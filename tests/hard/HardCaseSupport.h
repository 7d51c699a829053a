#pragma once
// Rendering and measuring for the torture suite: scenes given as text, rendered headless
// through OSMesa with the real shader, read back as linear radiance with per-pixel statistics.
#include "io/Image.h"
#include "settings/RenderSettings.h"
#include "support/RenderRun.h"

#include <cstdint>
#include <string>

namespace hard {

struct RenderOutput {
    io::Image radiance;    // linear RGB, top row first
    io::Image statistics;  // per pixel: samples, samples discarded, variance of the mean
    std::uint64_t discarded = 0;
};

struct RenderRequest {
    std::string sceneText;
    int width = 64;
    int height = 48;
    int samplesPerPixel = 16;
    settings::RenderSettings settings;
};

// Renders in this process's OSMesa context (made on first use). Scene files named in the
// text (textures, user SDFs) are looked up in tests/hard/.
RenderOutput render(const RenderRequest& request);

// Reads tests/hard/scenes/NAME.
std::string sceneFile(const std::string& name);

// Number of pixels (any channel) that are NaN or infinite.
int nonFinitePixels(const io::Image& image);
// Mean over pixels of the channel average.
double meanRadiance(const io::Image& image);
double maxRadiance(const io::Image& image);

// Two renders of one scene agree within Monte Carlo noise: the image is cut into blocks,
// each block's mean radiance differs between the renders by z standard errors (from the
// variances both renders report), and the largest |z| must stay below the threshold that a
// true null hypothesis exceeds with probability 1e-3 over all blocks (Bonferroni). Returns
// an explanation when they do not agree, empty when they do.
std::string disagreementWithinNoise(const RenderOutput& a, const RenderOutput& b,
                                    int blockSize = 8);

// The render as the suite's noise-aware comparator reads it (support/ImageComparison.h:
// compareImages, the test the regression and render tests use).
testing_support::RenderedImage renderedImage(const RenderOutput& output);

// Upper quantile of the standard normal distribution: P(Z > z) = p.
double normalUpperQuantile(double p);

}  // namespace hard
