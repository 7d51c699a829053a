#include "film/RenderFile.h"

#include <stdexcept>

namespace film {

const std::vector<std::string>& accumulationChannelNames()
{
    static const std::vector<std::string> names = {
        "R",       "G", "B", "samples", "samplesDiscarded", "sumSquaredDeviations.R",
        "sumSquaredDeviations.G", "sumSquaredDeviations.B"};
    return names;
}

const std::vector<std::string>& statisticsChannelNames()
{
    static const std::vector<std::string> names = {"samples", "samplesDiscarded",
                                                   "varianceOfMean"};
    return names;
}

io::OutputImage accumulationOutput(const std::filesystem::path& path,
                                   const Accumulation& accumulation,
                                   const RenderMetadata& metadata)
{
    io::Image image(accumulation.width(), accumulation.height(), 8);
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            for (int c = 0; c < 3; ++c) {
                image.at(x, y, c) = accumulation.estimate.at(x, y, c);
                image.at(x, y, 5 + c) = accumulation.moments.at(x, y, c);
            }
            image.at(x, y, 3) = accumulation.samplesKept(x, y);
            image.at(x, y, 4) = accumulation.samplesDiscarded(x, y);
        }
    return {path, std::move(image), metadataAttributes(metadata), accumulationChannelNames()};
}

io::OutputImage statisticsOutput(const std::filesystem::path& path,
                                 const Accumulation& accumulation,
                                 const RenderMetadata& metadata)
{
    return {path, sampleStatistics(accumulation), metadataAttributes(metadata),
            statisticsChannelNames()};
}

RenderFile readRenderFile(const std::filesystem::path& path)
{
    const io::ImageFileContents file = io::readImageFile(path);
    // OpenEXR keeps channels sorted by name: each is found by its name.
    std::vector<int> channels;
    for (const std::string& name : accumulationChannelNames()) {
        channels.push_back(file.channelIndex(name));
        if (channels.back() < 0)
            throw std::runtime_error(
                path.string() + " holds no accumulation (no channel '" + name +
                "'): only an .exr that this program wrote with --output or merge can be merged "
                "or resumed");
    }
    std::optional<RenderMetadata> metadata = metadataFromAttributes(file.attributes, path.string());
    if (!metadata)
        throw std::runtime_error(path.string() + " has no metadata of this program (no "
                                 "raytracer:sceneSha256 attribute)");
    metadata->width = file.image.width;
    metadata->height = file.image.height;

    RenderFile render{Accumulation(file.image.width, file.image.height), std::move(*metadata)};
    Accumulation& accumulation = render.accumulation;
    for (int y = 0; y < file.image.height; ++y)
        for (int x = 0; x < file.image.width; ++x) {
            for (int c = 0; c < 3; ++c) {
                accumulation.estimate.at(x, y, c) = file.image.at(x, y, channels[c]);
                accumulation.moments.at(x, y, c) = file.image.at(x, y, channels[5 + c]);
            }
            accumulation.estimate.at(x, y, 3) = file.image.at(x, y, channels[3]);
            accumulation.moments.at(x, y, 3) = file.image.at(x, y, channels[4]);
        }
    return render;
}

}  // namespace film
