#include "film/RenderFile.h"

#include "film/RenderFileChecks.h"
#include "io/ImageFormats.h"

#include <stdexcept>

namespace film {

const std::vector<std::string>& accumulationChannelNames()
{
    static const std::vector<std::string> names = {"R",
                                                   "G",
                                                   "B",
                                                   "samples",
                                                   "samplesDiscarded",
                                                   "sumSquaredDeviations.R",
                                                   "sumSquaredDeviations.G",
                                                   "sumSquaredDeviations.B"};
    return names;
}

const std::vector<std::string>& statisticsChannelNames()
{
    static const std::vector<std::string> names = {"samples", "samplesDiscarded", "varianceOfMean"};
    return names;
}

const std::vector<std::string>& featureChannelNames()
{
    static const std::vector<std::string> names = {"albedo.R", "albedo.G", "albedo.B", "N.X",
                                                   "N.Y",      "N.Z",      "Z",        "coverage"};
    return names;
}

namespace {

// Feature channel c (featureChannelNames) of a pixel.
float& featureAt(Accumulation& accumulation, int x, int y, int c)
{
    if (c < 3)
        return accumulation.albedoDepth.at(x, y, c);
    if (c < 6)
        return accumulation.normalCoverage.at(x, y, c - 3);
    return c == 6 ? accumulation.albedoDepth.at(x, y, 3) : accumulation.normalCoverage.at(x, y, 3);
}

float featureAt(const Accumulation& accumulation, int x, int y, int c)
{
    return featureAt(const_cast<Accumulation&>(accumulation), x, y, c);
}

// An EXR says what its pixels were, so that a byte changed later is found (RenderFileChecks.h).
io::OutputImage withPixelDigest(io::OutputImage output)
{
    if (io::lowerCaseExtension(output.path) == ".exr")
        output.attributes.push_back(
            {kPixelDigestAttribute, pixelDigest(output.image, output.channelNames)});
    return output;
}

}  // namespace

io::OutputImage accumulationOutput(const std::filesystem::path& path,
                                   const Accumulation& accumulation, const RenderMetadata& metadata)
{
    const int features = accumulation.hasFeatures() ? 8 : 0;
    io::Image image(accumulation.width(), accumulation.height(), 8 + features);
    std::vector<std::string> names = accumulationChannelNames();
    if (features)
        names.insert(names.end(), featureChannelNames().begin(), featureChannelNames().end());
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            for (int c = 0; c < features; ++c)
                image.at(x, y, 8 + c) = featureAt(accumulation, x, y, c);
            for (int c = 0; c < 3; ++c) {
                image.at(x, y, c) = accumulation.estimate.at(x, y, c);
                image.at(x, y, 5 + c) = accumulation.moments.at(x, y, c);
            }
            image.at(x, y, 3) = accumulation.samplesKept(x, y);
            image.at(x, y, 4) = accumulation.samplesDiscarded(x, y);
        }
    return withPixelDigest(
        {path, std::move(image), metadataAttributes(metadata), std::move(names)});
}

io::OutputImage statisticsOutput(const std::filesystem::path& path,
                                 const Accumulation& accumulation, const RenderMetadata& metadata)
{
    return withPixelDigest({path, sampleStatistics(accumulation), metadataAttributes(metadata),
                            statisticsChannelNames()});
}

RenderFile readRenderFile(const std::filesystem::path& path)
{
    // Read only as OpenEXR: a file named otherwise is never handed to another reader.
    if (io::lowerCaseExtension(path) != ".exr")
        throw std::runtime_error(path.string() +
                                 " holds no accumulation: it is not an .exr "
                                 "file, and only an .exr that this program wrote with --output "
                                 "or merge can be merged or resumed");
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
    checkPixelValues(file, *metadata, path.string());
    checkPixelDigest(file, path.string());

    // Feature buffers: all their channels or none.
    std::vector<int> features;
    for (const std::string& name : featureChannelNames())
        if (const int channel = file.channelIndex(name); channel >= 0)
            features.push_back(channel);
    if (!features.empty() && features.size() != featureChannelNames().size())
        throw std::runtime_error(path.string() +
                                 " holds some feature channels but not all "
                                 "(albedo.R/G/B, N.X/Y/Z, Z, coverage): not a render this "
                                 "program wrote");

    RenderFile render{Accumulation(file.image.width, file.image.height), std::move(*metadata)};
    Accumulation& accumulation = render.accumulation;
    if (!features.empty())
        accumulation.addEmptyFeatures();
    for (int y = 0; y < file.image.height; ++y)
        for (int x = 0; x < file.image.width; ++x) {
            for (int c = 0; c < 3; ++c) {
                accumulation.estimate.at(x, y, c) = file.image.at(x, y, channels[c]);
                accumulation.moments.at(x, y, c) = file.image.at(x, y, channels[5 + c]);
            }
            accumulation.estimate.at(x, y, 3) = file.image.at(x, y, channels[3]);
            accumulation.moments.at(x, y, 3) = file.image.at(x, y, channels[4]);
            for (std::size_t c = 0; c < features.size(); ++c)
                featureAt(accumulation, x, y, static_cast<int>(c)) =
                    file.image.at(x, y, features[c]);
        }
    return render;
}

}  // namespace film
