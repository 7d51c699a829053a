#include "app/RenderOutputs.h"

#include "app/BuildInfo.h"
#include "film/RenderFile.h"
#include "io/ImageFile.h"
#include "io/ImageFormats.h"

namespace app {

film::RenderMetadata describeRender(const std::filesystem::path& sceneFile,
                                    const std::string& sceneSha256,
                                    const render::ProgressiveRenderer& renderer,
                                    const platform::ContextIdentity& gl)
{
    film::RenderMetadata metadata;
    metadata.width = renderer.width();
    metadata.height = renderer.height();
    metadata.sceneFile = sceneFile.string();
    metadata.sceneSha256 = sceneSha256;
    metadata.camera = renderer.camera();
    metadata.settings = renderer.settings();
    // The most any pixel holds: with adaptive sampling the counts differ, and each pixel's
    // samples are indices 0 to its count.
    const int most = renderer.samplesAdaptively()
                         ? film::samplesTakenSpan(renderer.accumulation()).most
                         : renderer.samplesPerPixel();
    metadata.samplesPerPixel = most;
    metadata.sampleRanges = {{renderer.settings().seed, 0, most}};
    metadata.glContext = gl.kind;
    metadata.glRenderer = gl.renderer;
    metadata.glVersion = gl.version;
    metadata.kernel = settings::pathKernelName(renderer.kernel().kernel);
    metadata.program = programName();
    metadata.gitCommit = gitCommit();
    return metadata;
}

std::vector<io::OutputImage> renderOutputs(const std::vector<std::filesystem::path>& images,
                                           const std::optional<std::filesystem::path>& statistics,
                                           const film::Accumulation& accumulation,
                                           const film::RenderMetadata& metadata,
                                           const std::function<io::Image()>& picture)
{
    const std::vector<io::ImageAttribute> attributes = film::metadataAttributes(metadata);
    std::vector<io::OutputImage> outputs;
    for (const std::filesystem::path& path : images) {
        if (io::lowerCaseExtension(path) == ".exr")
            outputs.push_back(film::accumulationOutput(path, accumulation, metadata));
        else if (io::holdsLinearRadiance(path))
            outputs.push_back({path, film::meanRadiance(accumulation), attributes, {}});
        else
            outputs.push_back({path, picture(), attributes, {}});
    }
    if (statistics)
        outputs.push_back(film::statisticsOutput(*statistics, accumulation, metadata));
    return outputs;
}

}  // namespace app
