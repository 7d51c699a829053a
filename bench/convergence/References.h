#pragma once
// bench_convergence's converged references: rendered once with the default settings and a
// fixed seed, and cached under a key made of everything that decides their pixels.
#include "convergence/ImageErrors.h"
#include "scene/Scene.h"
#include "settings/RenderSettings.h"

#include <cstdint>
#include <filesystem>
#include <string>

namespace convergence {

// "%g": how the CSVs and the cache key write a setting's value.
std::string formatNumber(double value);

// Every setting that decides the image, as text: part of the reference's cache key.
std::string describeSettings(const settings::RenderSettings& settings);

// The scene file's name without its extension.
std::string sceneName(const std::filesystem::path& path);

struct Reference {
    io::Image image;
    io::Image halfImage;           // the same run at half the samples, for its noise
    ImageError noise;              // what noise alone leaves in `image`
    double brightnessNoise = 0.0;  // of its sum over the image, relative to the sum
    int samplesPerPixel = 0;
    double renderSeconds = 0.0;
    double compileSeconds = 0.0;
    double warmUpSeconds = 0.0;
    std::uint64_t discardedSamples = 0;
    bool fromCache = false;
    std::string key;
};

struct ReferenceOptions {
    int samplesPerPixel = 4096;
    std::uint64_t seed = 1;
    std::filesystem::path cacheDirectory;
    bool refresh = false;
};

// The reference of `scene` at this size, from the cache or rendered (and then cached).
Reference obtainReference(const scene::Scene& scene, int width, int height,
                          const ReferenceOptions& options);

}  // namespace convergence
