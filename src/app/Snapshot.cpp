#include "app/Snapshot.h"

#include "app/RenderOutputs.h"
#include "io/OutputFiles.h"

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

void writeSnapshot(const render::ProgressiveRenderer& renderer, const SnapshotFiles& files,
                   const film::RenderMetadata& metadata)
{
    io::writeAllOrNothing(renderOutputs({files.picture, files.radiance}, std::nullopt,
                                        renderer.accumulation(), metadata,
                                        [&] { return renderer.toneMapped(); }));
}

}  // namespace app
