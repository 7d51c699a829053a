#pragma once
#include "film/RenderMetadata.h"
#include "render/ProgressiveRenderer.h"

#include <filesystem>
#include <optional>

namespace app {

struct SnapshotFiles {
    std::filesystem::path picture;   // tone-mapped, 8-bit PNG
    std::filesystem::path radiance;  // linear HDR, EXR
};

// Where the window's save key writes: NAME-Nspp.png and NAME-Nspp.exr, NAME being the scene
// file's name without its extension, in the folder of `output` (--output) when given, else
// in the current folder.
SnapshotFiles snapshotFiles(const std::filesystem::path& sceneFile, int samplesPerPixel,
                            const std::optional<std::filesystem::path>& output);

// Writes the image the renderer holds as both files, with `metadata` (both complete, or
// neither); the EXR holds the accumulation too, as a batch render's does.
void writeSnapshot(const render::ProgressiveRenderer& renderer, const SnapshotFiles& files,
                   const film::RenderMetadata& metadata);

}  // namespace app
