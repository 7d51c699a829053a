#pragma once
// What an output file says of itself (in its header: OpenImageIO attributes, prefixed
// "raytracer:", in EXR and PNG files): what it shows, how it was made and which samples it
// holds. It is what lets `raytracer info` describe a file, and merge and resume refuse
// samples that do not estimate one image.
#include "io/ImageFile.h"
#include "settings/RenderSettings.h"
#include "film/SampleRanges.h"
#include "scene/Scene.h"

#include <optional>
#include <string>
#include <vector>

namespace film {

struct RenderMetadata {
    int width = 0;   // the image's own size (the format holds it; no attribute)
    int height = 0;
    std::string sceneFile;    // as named on the command line
    // SHA-256 over the scene file and every user SDF and texture file it uses
    // (app/SceneDigest.h).
    std::string sceneSha256;
    // The camera the image was rendered from: the scene file's, or where the window moved it.
    scene::Camera camera;
    // Of these only the image-changing ones are recorded (imageSettings()); the rest are
    // defaults when read back.
    settings::RenderSettings settings;
    // Samples per pixel the render aimed at and reached (an interrupted one: the most any
    // pixel holds); for a merge, the sum over its inputs.
    int samplesPerPixel = 0;
    std::vector<SampleRange> sampleRanges;
    // Seconds spent rendering the samples held (summed over resumed and merged renders).
    double renderSeconds = 0.0;
    // Empty unless the render was interrupted; then how it stopped.
    std::string interrupted;
    std::string program;    // "raytracer 1.0.0"
    std::string gitCommit;  // empty when the program was not built from a git checkout
    // The files a merge read, in order.
    std::vector<std::string> mergedFrom;
};

// A setting that changes the image: renders that differ in one estimate different images,
// so their samples never mix. Each is described once here; the attribute, the check and
// `raytracer info`'s line all come from this table.
struct ImageSetting {
    const char* key;     // attribute "raytracer:" + key
    const char* label;   // for people
    const char* option;  // the command-line option that sets it
    std::string (*text)(const settings::RenderSettings& settings);
    // False when `text` is not a value of this setting.
    bool (*read)(settings::RenderSettings& settings, const std::string& text);
};
const std::vector<ImageSetting>& imageSettings();

// "eye 0 1 5 target 0 0 0 up 0 1 0 fovy 45": exact (floats round-trip), for the header.
std::string formatCamera(const scene::Camera& camera);

std::vector<io::ImageAttribute> metadataAttributes(const RenderMetadata& metadata);

// From a file's attributes; nothing when they hold none of this program's metadata (no
// raytracer:sceneSha256). Throws std::runtime_error naming `file` and the attribute when one
// is missing or malformed. width and height are left 0.
std::optional<RenderMetadata> metadataFromAttributes(
    const std::vector<io::ImageAttribute>& attributes, const std::string& file);

// Why two renders' samples do not estimate one image: the first of size, scene, camera,
// image-changing setting and program build in which they differ.
struct MetadataDifference {
    std::string what;  // "the image size", "--max-bounces", ...
    std::string first;
    std::string second;
};
std::optional<MetadataDifference> imageDifference(const RenderMetadata& first,
                                                  const RenderMetadata& second);

// "raytracer 1.0.0, commit 0123abcd..." or "raytracer 1.0.0 (no git commit)".
std::string describeProgram(const RenderMetadata& metadata);

}  // namespace film
