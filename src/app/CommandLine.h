#pragma once
#include "render/RenderSettings.h"

#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>

namespace app {

enum class Action { Render, Help, Version, PrintFeatures, PrintShader };

struct CommandLine {
    Action action = Action::Render;
    std::filesystem::path scene;
    int width = 640;
    int height = 480;
    std::optional<double> seconds;   // timed render
    std::optional<int> samplesPerPixel;
    std::optional<std::filesystem::path> output;
    std::optional<std::filesystem::path> statisticsOutput;
    bool headless = false;
    // --samples-per-frame was given: keep it; otherwise the render picks it (RenderCommand).
    bool samplesPerFrameGiven = false;
    bool quiet = false;
    render::RenderSettings settings;

    // A render that ends by itself and writes a file (as opposed to a window kept open).
    bool isBatch() const { return seconds.has_value() || samplesPerPixel.has_value(); }
    // Where the picture goes: --output, else <scene name>.ppm in the current folder.
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
