#include "io/ImageFile.h"

#include "io/ImageFormats.h"
#include "io/OutputFiles.h"

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cerrno>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <memory>
#include <stdexcept>
#include <string>
#include <unistd.h>

namespace io {

namespace fs = std::filesystem;

namespace {

bool isPfm(const fs::path& path)
{
    return lowerCaseExtension(path) == ".pfm";
}

// OpenImageIO says only that it could not open the file; the system says why.
std::unique_ptr<OIIO::ImageInput> openForReading(const fs::path& path)
{
    if (::access(path.c_str(), R_OK) != 0)
        throw std::runtime_error("cannot read image " + path.string() + ": " +
                                 std::strerror(errno));
    auto input = OIIO::ImageInput::open(path.string());
    if (!input)
        throw std::runtime_error("cannot read image " + path.string() + ": " + OIIO::geterror());
    return input;
}

// Messages name the user's path: a library's message about the temporary file is rewritten.
std::string aboutDestination(std::string message, const fs::path& file,
                             const fs::path& destination)
{
    const std::string from = file.string();
    for (std::size_t at; !from.empty() && (at = message.find(from)) != std::string::npos;)
        message.replace(at, from.size(), destination.string());
    return message;
}

// OpenImageIO 2.4 (Debian 12) reads PFM but has no writer for it, so PFM is written here:
// "PF" (colour) or "Pf" (grey), size, a negative scale for little-endian floats, then the
// rows bottom first. The format holds no attributes.
void writePfm(const fs::path& file, const fs::path& destination, const Image& image)
{
    if (image.channels != 3 && image.channels != 1)
        throw std::runtime_error("cannot write " + destination.string() +
                                 ": PFM holds one or three channels");
    std::ofstream out(file, std::ios::binary);
    if (!out)
        throw std::runtime_error("cannot write " + destination.string() + ": " +
                                 std::strerror(errno));
    out << (image.channels == 3 ? "PF" : "Pf") << "\n"
        << image.width << " " << image.height << "\n-1.0\n";
    for (int y = image.height - 1; y >= 0; --y) {
        const float* row = &image.pixels[image.index(0, y, 0)];
        for (int i = 0; i < image.width * image.channels; ++i) {
            std::uint32_t bits;
            std::memcpy(&bits, &row[i], sizeof bits);
            const unsigned char bytes[4] = {
                static_cast<unsigned char>(bits), static_cast<unsigned char>(bits >> 8),
                static_cast<unsigned char>(bits >> 16), static_cast<unsigned char>(bits >> 24)};
            out.write(reinterpret_cast<const char*>(bytes), 4);
        }
    }
    out.close();
    if (!out)
        throw std::runtime_error("cannot write " + destination.string() + ": " +
                                 std::strerror(errno));
}

void writeThroughOpenImageIo(const fs::path& file, const fs::path& destination,
                             const ImageFormat& format, const Image& image,
                             const std::vector<ImageAttribute>& attributes,
                             const std::vector<std::string>& channelNames)
{
    // The writer is chosen by the destination's extension, whatever the file is called.
    auto output = OIIO::ImageOutput::create(destination.string());
    if (!output)
        throw std::runtime_error("cannot write " + destination.string() +
                                 ": OpenImageIO has no writer for this format");
    OIIO::ImageSpec spec(image.width, image.height, image.channels,
                         format.linearRadiance ? OIIO::TypeDesc::FLOAT : OIIO::TypeDesc::UINT8);
    if (!channelNames.empty()) {
        if (static_cast<int>(channelNames.size()) != image.channels)
            throw std::logic_error("writing " + destination.string() + ": " +
                                   std::to_string(channelNames.size()) + " channel names for " +
                                   std::to_string(image.channels) + " channels");
        spec.channelnames = channelNames;
        const auto alpha = std::find(channelNames.begin(), channelNames.end(), "A");
        spec.alpha_channel =
            alpha == channelNames.end() ? -1 : static_cast<int>(alpha - channelNames.begin());
    }
    for (const ImageAttribute& attribute : attributes)
        spec.attribute(attribute.name, attribute.value);
    if (!output->open(file.string(), spec))
        throw std::runtime_error("cannot write " + destination.string() + ": " +
                                 aboutDestination(output->geterror(), file, destination));
    const bool written = output->write_image(OIIO::TypeDesc::FLOAT, image.pixels.data());
    const std::string writeError = written ? std::string() : output->geterror();
    const bool closed = output->close();
    if (!written || !closed)
        throw std::runtime_error(
            "cannot write " + destination.string() + ": " +
            aboutDestination(written ? output->geterror() : writeError, file, destination));
}

}  // namespace

bool holdsLinearRadiance(const fs::path& path)
{
    const ImageFormat* format = outputFormatOf(path);
    return format != nullptr && format->linearRadiance;
}

void writeImageFile(const fs::path& file, const fs::path& destination, const Image& image,
                    const std::vector<ImageAttribute>& attributes,
                    const std::vector<std::string>& channelNames)
{
    const ImageFormat* format = outputFormatOf(destination);
    if (format == nullptr)
        throw std::runtime_error("cannot write " + destination.string() +
                                 ": unknown image format");
    if (isPfm(destination))
        writePfm(file, destination, image);
    else
        writeThroughOpenImageIo(file, destination, *format, image, attributes, channelNames);
}

void writeImage(const fs::path& path, const Image& image,
                const std::vector<ImageAttribute>& attributes)
{
    writeAllOrNothing({{path, image, attributes, {}}});
}

void checkReadableImage(const fs::path& path)
{
    openForReading(path)->close();
}

ImageSize readImageSize(const fs::path& path)
{
    const auto input = openForReading(path);
    const OIIO::ImageSpec& spec = input->spec();
    return {spec.width, spec.height, spec.nchannels};
}

std::optional<std::string> readImageAttribute(const fs::path& path, const std::string& name)
{
    const auto input = openForReading(path);
    const OIIO::ParamValue* value = input->spec().find_attribute(name);
    if (value == nullptr)
        return std::nullopt;
    return input->spec().get_string_attribute(name);
}

Image readImage(const fs::path& path)
{
    return readImageFile(path).image;
}

int ImageFileContents::channelIndex(const std::string& name) const
{
    const auto found = std::find(channelNames.begin(), channelNames.end(), name);
    return found == channelNames.end() ? -1 : static_cast<int>(found - channelNames.begin());
}

ImageFileContents readImageFile(const fs::path& path)
{
    const auto input = openForReading(path);
    const OIIO::ImageSpec& spec = input->spec();
    ImageFileContents contents;
    contents.format = input->format_name();
    contents.image = Image(spec.width, spec.height, spec.nchannels);
    contents.channelNames = spec.channelnames;
    for (const OIIO::ParamValue& attribute : spec.extra_attribs)
        contents.attributes.push_back(
            {attribute.name().string(), attribute.type() == OIIO::TypeDesc::STRING
                                            ? std::string(attribute.get_string())
                                            : std::string(spec.metadata_val(attribute))});
    if (!input->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT,
                           contents.image.pixels.data()))
        throw std::runtime_error("cannot read image " + path.string() + ": " + input->geterror());
    input->close();
    return contents;
}

}  // namespace io
