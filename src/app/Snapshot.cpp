#include "app/Snapshot.h"

#include "io/ImageFile.h"

#include <string>

namespace app {

namespace fs = std::filesystem;

SnapshotFiles snapshotFiles(const fs::path& sceneFile, int samplesPerPixel,
                            const std::optional<fs::path>& output)
{
    const fs::path folder = output ? output->parent_path() : fs::path();
    const std::string name =
        sceneFile.stem().string() + "-" + std::to_string(samplesPerPixel) + "spp";
    return {folder / (name + ".png"), folder / (name + ".exr")};
}

void writeSnapshot(const render::ProgressiveRenderer& renderer, const SnapshotFiles& files)
{
    io::writeImage(files.picture, renderer.toneMapped());
    io::writeImage(files.radiance, renderer.radiance());
}

}  // namespace app
