#pragma once
#include "film/AdaptiveSampling.h"
#include "settings/RenderSettings.h"

#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace app {

enum class Action { Render, Help, Version, PrintFeatures, PrintShader, Info, Merge };

// raytracer merge OUT.exr IN.exr... [--png FILE] [--stats-output FILE]
struct MergeRequest {
    std::filesystem::path output;  // .exr
    std::vector<std::filesystem::path> inputs;
    std::optional<std::filesystem::path> picture;  // --png: the tone-mapped picture too
    std::optional<std::filesystem::path> statisticsOutput;
};

struct CommandLine {
    Action action = Action::Render;
    std::filesystem::path scene;
    int width = 640;
    int height = 480;
    std::optional<double> seconds;   // timed render
    std::optional<int> samplesPerPixel;
    // --target-error E: stop once the estimated relative RMSE is E (film/AdaptiveSampling.h
    // holds it with --min-spp and --adaptive-tile); --uniform-sampling: every pixel alike.
    std::optional<double> targetError;
    film::AdaptiveSampling adaptiveSampling;
    bool uniformSampling = false;
    std::optional<std::filesystem::path> output;
    std::optional<std::filesystem::path> statisticsOutput;
    bool headless = false;
    // --samples-per-frame was given: keep it; otherwise the render picks it (RenderCommand).
    bool samplesPerFrameGiven = false;
    bool quiet = false;
    settings::RenderSettings settings;
    // WIDTH HEIGHT and --seed were given (a resumed render takes the file's otherwise).
    bool sizeGiven = false;
    bool seedGiven = false;
    // --resume FILE: go on from the render FILE holds.
    std::optional<std::filesystem::path> resume;

    std::filesystem::path infoFile;  // raytracer info FILE
    MergeRequest merge;              // raytracer merge ...

    // A render that ends by itself and writes a file (as opposed to a window kept open).
    bool isBatch() const
    {
        return seconds.has_value() || samplesPerPixel.has_value() || targetError.has_value();
    }
    // Where the picture goes: --output, else the file resumed, else <scene name>.ppm in the
    // current folder.
    std::filesystem::path outputPath() const;
};

// A command line that cannot be run; what() is the message for the user.
class UsageError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

CommandLine parseCommandLine(int argc, const char* const argv[]);
std::string usageText();

}  // namespace app
