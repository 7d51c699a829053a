#pragma once
// Rendering a scene in-process, in the GL context the test executable made (GlTestMain.cpp),
// and reading back what the regression and physics tests compare.
#include "film/Accumulation.h"
#include "io/Image.h"
#include "scene/Scene.h"
#include "settings/RenderSettings.h"

#include <cstdint>
#include <filesystem>
#include <string>

namespace testing_support {

// The Monte Carlo estimate of an image and what is known of its noise, as the renderer
// reports them (ProgressiveRenderer::radiance and ::sampleStatistics).
struct RenderedImage {
    io::Image radiance;    // linear RGB, top row first
    io::Image statistics;  // per pixel: samples, discarded samples, variance of the mean
    std::uint64_t discardedSamples = 0;
    film::Accumulation accumulation;

    int width() const { return radiance.width; }
    int height() const { return radiance.height; }
    float samples(int x, int y) const { return statistics.at(x, y, 0); }
    float varianceOfMean(int x, int y) const { return statistics.at(x, y, 2); }
};

// A scene file; texture and shader files are found as the program finds them.
scene::Scene loadScene(const std::filesystem::path& path);

// Scene text written in a test. Files it names are looked up in tests/scenes/, then in the
// project's textures/ and shaders/.
scene::Scene sceneFromText(const std::string& text, const std::string& name = "inline.in");

settings::RenderSettings settingsWithSeed(std::uint64_t seed);

// Renders exactly `samplesPerPixel` frames.
RenderedImage renderScene(const scene::Scene& scene, int width, int height, int samplesPerPixel,
                          const settings::RenderSettings& settings);

// Mean of the three channels, the quantity whose variance sampleStatistics() bounds.
float channelMean(const io::Image& image, int x, int y);

}  // namespace testing_support
