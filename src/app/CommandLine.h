#pragma once
#include "film/AdaptiveSampling.h"
#include "film/RenderMetadata.h"
#include "platform/ContextFactory.h"
#include "scene/Scene.h"
#include "settings/OptionDescription.h"
#include "settings/RenderSettings.h"

#include <filesystem>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace app {

enum class Action { Render, Help, Version, PrintFeatures, PrintShader, Info, Merge, Denoise };

// raytracer merge OUT.exr IN.exr... [--png FILE] [--stats-output FILE]
struct MergeRequest {
    std::filesystem::path output;  // .exr
    std::vector<std::filesystem::path> inputs;
    std::optional<std::filesystem::path> picture;  // --png: the tone-mapped picture too
    std::optional<std::filesystem::path> statisticsOutput;
};

// raytracer denoise IN.exr OUT
struct DenoiseRequest {
    std::filesystem::path input;   // an .exr with feature buffers (--feature-buffers)
    std::filesystem::path output;  // .exr, .pfm, .hdr or a picture format
};

// What the command line asks for. Its options, and the render settings among them, are the
// rows of settings/Options.def: parseCommandLine, usageText and the defaults --help states
// all come from there (a field's default is the one written here).
struct CommandLine {
    Action action = Action::Render;
    std::filesystem::path scene;
    int width = 640;
    int height = 480;
    std::optional<double> seconds;  // timed render
    std::optional<int> samplesPerPixel;
    // --target-error E: stop once the estimated relative RMSE is E (film/AdaptiveSampling.h
    // holds it with --min-spp and --adaptive-tile); --uniform-sampling: every pixel alike.
    std::optional<double> targetError;
    film::AdaptiveSampling adaptiveSampling;
    bool uniformSampling = false;
    std::optional<std::filesystem::path> output;
    std::optional<std::filesystem::path> statisticsOutput;
    bool headless = false;
    // --denoise: each output also written denoised, beside it (app/Denoising.h).
    bool denoise = false;
    // --gl KIND: which OpenGL renders (auto: a window where there is a display and the render
    // is not headless, else EGL, else OSMesa); --gl-device N: the Nth GPU EGL lists, and no
    // other (it implies --gl gpu).
    platform::ContextKind gl = platform::ContextKind::Automatic;
    std::optional<int> glDevice;
    // --quiet: nothing on standard output; --summary-json FILE: the summary as JSON too.
    bool quiet = false;
    std::optional<std::filesystem::path> summaryJson;
    // --strict: a warning (a scene that can emit no light) is an error.
    bool strict = false;
    // --camera: replaces the scene file's camera once the scene is read.
    std::optional<scene::Camera> camera;
    // --crop: the pixels traced, of WIDTH x HEIGHT.
    std::optional<film::PixelCrop> crop;
    settings::RenderSettings settings;
    // WIDTH HEIGHT were given (a resumed render takes the file's otherwise).
    bool sizeGiven = false;
    // --resume FILE: go on from the render FILE holds.
    std::optional<std::filesystem::path> resume;
    // The options given, by their table names ("--seed", "--output" for -o): a resumed render
    // takes the file's seed unless --seed was given, a render picks its samples per frame
    // unless --samples-per-frame was.
    std::set<std::string> optionsGiven;

    std::filesystem::path infoFile;  // raytracer info FILE
    MergeRequest merge;              // raytracer merge ...
    DenoiseRequest denoising;        // raytracer denoise ...

    // A render that ends by itself and writes a file (as opposed to a window kept open).
    bool isBatch() const
    {
        return seconds.has_value() || samplesPerPixel.has_value() || targetError.has_value();
    }
    // Where the picture goes: --output, else the file resumed, else <scene name>.ppm in the
    // current folder.
    std::filesystem::path outputPath() const;
    bool given(const std::string& flag) const { return optionsGiven.count(flag) != 0; }
};

// A command line that cannot be run; what() is the message for the user.
using settings::UsageError;

// Options are written `--name value` or `--name=value`, each once; an unknown one is refused
// with the known one nearest to it in spelling (within two edits), if any.
CommandLine parseCommandLine(int argc, const char* const argv[]);
std::string usageText();

}  // namespace app
