#include "app/InfoCommand.h"

#include "app/RenderCommand.h"
#include "film/RenderFileChecks.h"
#include "film/RenderMetadata.h"
#include "io/ImageFile.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <limits>
#include <stdexcept>

namespace app {

namespace {

void printLine(const std::string& label, const std::string& value)
{
    std::printf("%-33s %s\n", label.c_str(), value.c_str());
}

// "every pixel holds 64 samples (none discarded)" or "pixels hold 31 to 32 samples, 3
// discarded in all", from the channels that count them, where the file has them.
std::string perPixelSamples(const io::ImageFileContents& file)
{
    const int kept = file.channelIndex("samples");
    const int discarded = file.channelIndex("samplesDiscarded");
    if (kept < 0 || discarded < 0)
        return "";
    double fewest = std::numeric_limits<double>::max();
    double most = 0.0;
    double discardedInAll = 0.0;
    for (int y = 0; y < file.image.height; ++y)
        for (int x = 0; x < file.image.width; ++x) {
            const double taken = file.image.at(x, y, kept) + file.image.at(x, y, discarded);
            fewest = std::min(fewest, taken);
            most = std::max(most, taken);
            discardedInAll += file.image.at(x, y, discarded);
        }
    char text[160];
    if (fewest == most)
        std::snprintf(text, sizeof text, "every pixel holds %.0f (%.0f discarded in all)", most,
                      discardedInAll);
    else
        std::snprintf(text, sizeof text, "pixels hold %.0f to %.0f (%.0f discarded in all)", fewest,
                      most, discardedInAll);
    return text;
}

}  // namespace

int runInfo(const std::filesystem::path& path)
{
    const io::ImageFileContents file = io::readImageFile(path);
    const std::optional<film::RenderMetadata> metadata =
        film::metadataFromAttributes(file.attributes, path.string());
    if (!metadata)
        throw std::runtime_error(path.string() + " holds no metadata of this program (" +
                                 file.format + "; PPM, PFM, HDR, JPEG and TIFF files hold none)");
    // What info says of the file is only what a render's file holds (merge and --resume refuse
    // the same).
    film::checkPixelValues(file, *metadata, path.string());
    film::checkPixelDigest(file, path.string());

    std::string channels;
    for (const std::string& name : file.channelNames)
        channels += (channels.empty() ? "" : " ") + name;
    printLine("file", path.string() + ": " + file.format + ", " + std::to_string(file.image.width) +
                          "x" + std::to_string(file.image.height));
    printLine("channels", channels);
    if (file.channelIndex("albedo.R") >= 0)
        printLine("feature buffers", "albedo.R/G/B (first-hit albedo), N.X/Y/Z (world-space "
                                     "normal), Z (camera distance), coverage");
    for (const io::ImageAttribute& attribute : file.attributes)
        if (attribute.name == "raytracer:denoised")
            printLine("denoised", attribute.value);
    printLine("scene", metadata->sceneFile);
    printLine("scene SHA-256", metadata->sceneSha256);
    printLine("camera", film::formatCamera(metadata->camera));
    if (metadata->crop)
        printLine("crop", film::formatCrop(*metadata->crop) + " (only these pixels traced)");
    std::string samples = std::to_string(metadata->samplesPerPixel) + " per pixel";
    const std::string pixels = perPixelSamples(file);
    if (!pixels.empty())
        samples += "; " + pixels;
    printLine("samples", samples);
    printLine("seeds", film::describeSeeds(metadata->sampleRanges));
    std::string ranges;
    for (const film::SampleRange& range : metadata->sampleRanges)
        ranges += (ranges.empty() ? "" : "; ") + film::describeSampleRange(range);
    printLine("sample ranges", ranges);
    char seconds[64];
    std::snprintf(seconds, sizeof seconds, "%.2f s%s", metadata->renderSeconds,
                  metadata->mergedFrom.empty() ? "" : " (summed over the renders merged)");
    printLine("render time", seconds);
    printLine("interrupted",
              metadata->interrupted.empty() ? "no" : "yes: " + metadata->interrupted);
    if (!metadata->mergedFrom.empty()) {
        std::string files;
        for (const std::string& name : metadata->mergedFrom)
            files += (files.empty() ? "" : ", ") + name;
        printLine("merged from", files);
    }
    auto recorded = [](const std::string& value) {
        return value.empty() ? std::string("not recorded (written before it was)") : value;
    };
    printLine("OpenGL context", recorded(metadata->glContext));
    printLine("OpenGL renderer", recorded(metadata->glRenderer));
    printLine("OpenGL version", recorded(metadata->glVersion));
    printLine("kernel", recorded(metadata->kernel));
    printLine("program", film::describeProgram(*metadata));
    for (const settings::SettingRow* setting : film::imageSettings())
        printLine(setting->description.metadataLabel,
                  setting->format(metadata->settings) + "  (" + setting->setBy() + ")");
    return kExitSuccess;
}

}  // namespace app
