#pragma once
// Reference images on disk: one OpenEXR file per regression case holding the linear radiance
// and the statistics the comparison needs (channels R, G, B, samples, varianceOfMean), with
// how it was made in the header (scene, samples per pixel, seed).
#include "support/RenderRun.h"

#include <cstdint>
#include <filesystem>
#include <string>

namespace testing_support {

struct ReferenceProvenance {
    std::string scene;  // relative to the project's source folder
    int samplesPerPixel = 0;
    std::uint64_t seed = 0;
};

void writeReference(const std::filesystem::path& path, const RenderedImage& image,
                    const ReferenceProvenance& provenance);

// Throws std::runtime_error naming the file when it is missing or not a reference.
RenderedImage readReference(const std::filesystem::path& path,
                            ReferenceProvenance* provenance = nullptr);

}  // namespace testing_support
