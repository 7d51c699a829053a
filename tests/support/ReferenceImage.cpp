#include "support/ReferenceImage.h"

#include <OpenImageIO/imageio.h>

#include <stdexcept>
#include <vector>

namespace testing_support {

namespace {

const std::vector<std::string> kChannels = {"R", "G", "B", "samples", "varianceOfMean"};

}  // namespace

void writeReference(const std::filesystem::path& path, const RenderedImage& image,
                    const ReferenceProvenance& provenance)
{
    const int width = image.width();
    const int height = image.height();
    const int channels = static_cast<int>(kChannels.size());
    OIIO::ImageSpec spec(width, height, channels, OIIO::TypeDesc::FLOAT);
    spec.channelnames = kChannels;
    spec.alpha_channel = -1;
    spec.attribute("compression", "zip");
    spec.attribute("raytracer:scene", provenance.scene);
    spec.attribute("raytracer:samplesPerPixel", provenance.samplesPerPixel);
    spec.attribute("raytracer:seed", std::to_string(provenance.seed));

    std::vector<float> pixels(static_cast<std::size_t>(width) * height * channels);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            float* pixel = &pixels[(static_cast<std::size_t>(y) * width + x) * channels];
            for (int c = 0; c < 3; ++c)
                pixel[c] = image.radiance.at(x, y, c);
            pixel[3] = image.samples(x, y);
            pixel[4] = image.varianceOfMean(x, y);
        }

    auto output = OIIO::ImageOutput::create(path.string());
    if (!output || !output->open(path.string(), spec) ||
        !output->write_image(OIIO::TypeDesc::FLOAT, pixels.data()) || !output->close())
        throw std::runtime_error("cannot write reference " + path.string() +
                                 (output ? ": " + output->geterror() : std::string()));
}

RenderedImage readReference(const std::filesystem::path& path, ReferenceProvenance* provenance)
{
    auto input = OIIO::ImageInput::open(path.string());
    if (!input)
        throw std::runtime_error("cannot read reference " + path.string() + ": " +
                                 OIIO::geterror() +
                                 " (make it with tools/update-references.sh, see tests/README.md)");
    const OIIO::ImageSpec& spec = input->spec();
    // OpenEXR keeps channels sorted by name; find each by its name.
    std::vector<int> channelIndex;
    for (const std::string& name : kChannels) {
        const int index = spec.channelindex(name);
        if (index < 0)
            throw std::runtime_error(path.string() + " is not a reference: it has no channel '" +
                                     name + "'");
        channelIndex.push_back(index);
    }
    const int width = spec.width;
    const int height = spec.height;
    const int channels = spec.nchannels;
    std::vector<float> pixels(static_cast<std::size_t>(width) * height * channels);
    if (!input->read_image(0, 0, 0, channels, OIIO::TypeDesc::FLOAT, pixels.data()))
        throw std::runtime_error("cannot read reference " + path.string() + ": " +
                                 input->geterror());
    if (provenance != nullptr) {
        provenance->scene = spec.get_string_attribute("raytracer:scene");
        provenance->samplesPerPixel = spec.get_int_attribute("raytracer:samplesPerPixel");
        provenance->seed = std::stoull(spec.get_string_attribute("raytracer:seed", "0"));
    }
    input->close();

    RenderedImage image;
    image.radiance = io::Image(width, height, 3);
    image.statistics = io::Image(width, height, 3);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const float* pixel = &pixels[(static_cast<std::size_t>(y) * width + x) * channels];
            for (int c = 0; c < 3; ++c)
                image.radiance.at(x, y, c) = pixel[channelIndex[c]];
            image.statistics.at(x, y, 0) = pixel[channelIndex[3]];
            image.statistics.at(x, y, 2) = pixel[channelIndex[4]];
        }
    return image;
}

}  // namespace testing_support
