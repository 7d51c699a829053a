#pragma once
// What an output file says of itself (in its header: OpenImageIO attributes, prefixed
// "raytracer:", in EXR and PNG files): what it shows, how it was made and which samples it
// holds. It is what lets `raytracer info` describe a file, and merge and resume refuse
// samples that do not estimate one image.
#include "film/SampleRanges.h"
#include "io/ImageFile.h"
#include "scene/Scene.h"
#include "settings/SettingsTable.h"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace film {

// A rectangle of the image in pixels, the top-left pixel (0, 0): columns x0 to x1 - 1, rows
// y0 to y1 - 1 (half-open). A render with --crop traces only these pixels of the full frame;
// the others hold no sample.
struct PixelCrop {
    int x0 = 0;
    int y0 = 0;
    int x1 = 0;
    int y1 = 0;

    int width() const { return x1 - x0; }
    int height() const { return y1 - y0; }
    bool disjointFrom(const PixelCrop& other) const
    {
        return x1 <= other.x0 || other.x1 <= x0 || y1 <= other.y0 || other.y1 <= y0;
    }
    bool operator==(const PixelCrop& other) const
    {
        return x0 == other.x0 && y0 == other.y0 && x1 == other.x1 && y1 == other.y1;
    }
};

// "X0 Y0 X1 Y1", and back (spaces or commas between; nothing where the text is not four whole
// numbers).
std::string formatCrop(const PixelCrop& crop);
std::optional<PixelCrop> parseCrop(const std::string& text);

struct RenderMetadata {
    int width = 0;  // the image's own size (the format holds it; no attribute)
    int height = 0;
    std::string sceneFile;  // as named on the command line
    // SHA-256 over the scene file and every user SDF and texture file it uses
    // (app/SceneDigest.h).
    std::string sceneSha256;
    // The camera the image was rendered from: the scene file's, or where the window moved it.
    scene::Camera camera;
    // Of these only the image-changing ones are recorded (imageSettings()); the rest are
    // defaults when read back.
    settings::RenderSettings settings;
    // Samples per pixel the render aimed at and reached (an interrupted one: the most any
    // pixel holds); for a merge, the sum over its inputs. 64-bit, so that a sum of counts read
    // from files cannot wrap before it is checked against kLargestSampleCount.
    std::int64_t samplesPerPixel = 0;
    std::vector<SampleRange> sampleRanges;
    // Seconds spent rendering the samples held (summed over resumed and merged renders).
    double renderSeconds = 0.0;
    // Empty unless the render was interrupted; then how it stopped.
    std::string interrupted;
    // What rendered the samples: the OpenGL context's kind, GL_RENDERER and GL_VERSION
    // (platform/GlContext.h's ContextIdentity), and the kernel that traced them
    // (settings/PathKernel.h). For the record only: renders on other devices or kernels
    // estimate the same image and may be merged. A render resumed or merged from others
    // lists each distinct value, "; " between them. Empty in files written before they were
    // recorded.
    std::string glContext;
    std::string glRenderer;
    std::string glVersion;
    std::string kernel;
    std::string program;    // "raytracer 1.0.0"
    std::string gitCommit;  // empty when the program was not built from a git checkout
    // The files a merge read, in order.
    std::vector<std::string> mergedFrom;
    // Where only part of the frame was traced (--crop; for a merge, a rectangle holding every
    // pixel its inputs traced): attribute raytracer:crop. Nothing: the whole frame.
    std::optional<PixelCrop> crop;
};

// The settings that change the image (settings/Options.def's rows with .metadata): renders
// that differ in one estimate different images, so their samples never mix. Each is recorded
// as attribute "raytracer:" + key, in the table's order; the check and `raytracer info`'s
// lines come from the same rows.
std::vector<const settings::SettingRow*> imageSettings();

// "eye 0 1 5 target 0 0 0 up 0 1 0 fovy 45": exact (floats round-trip), for the header.
std::string formatCamera(const scene::Camera& camera);

std::vector<io::ImageAttribute> metadataAttributes(const RenderMetadata& metadata);

// From a file's attributes; nothing when they hold none of this program's metadata (no
// raytracer:sceneSha256). Throws std::runtime_error naming `file` and the attribute when one
// is missing or malformed, or holds what no render holds: samples per pixel or a sample index
// beyond kLargestSampleCount (film/Accumulation.h), seconds that are negative or not
// finite. width and height are left 0.
std::optional<RenderMetadata>
metadataFromAttributes(const std::vector<io::ImageAttribute>& attributes, const std::string& file);

// Why two renders' samples do not estimate one image: the first of size, scene, camera,
// image-changing setting and program build in which they differ.
struct MetadataDifference {
    std::string what;  // "the image size", "--max-bounces", ...
    std::string first;
    std::string second;
};
std::optional<MetadataDifference> imageDifference(const RenderMetadata& first,
                                                  const RenderMetadata& second);

// Adds `other`'s context, renderer, version and kernel to `metadata`'s, each value once.
void addRenderingDevice(RenderMetadata& metadata, const RenderMetadata& other);

// "raytracer 1.0.0, commit 0123abcd..." or "raytracer 1.0.0 (no git commit)".
std::string describeProgram(const RenderMetadata& metadata);

}  // namespace film
