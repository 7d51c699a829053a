#include "io/ImageFile.h"

#include "io/ImageFormats.h"
#include "io/OpenExrHeader.h"
#include "io/OutputFiles.h"
#include "io/RegularFile.h"

#include <OpenEXR/ImfHeader.h>
#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <string>

namespace io {

namespace fs = std::filesystem;

namespace {

[[noreturn]] void refuseToRead(const fs::path& path, const std::string& reason)
{
    throw std::runtime_error("cannot read image " + path.string() + ": " + reason);
}

// OpenEXR sizes its table of chunk offsets from the header as it opens a file, before
// OpenImageIO hands the header over: its own limit keeps a crafted data window from asking
// for gigabytes there.
void limitOpenExrHeaders()
{
    static std::once_flag once;
    std::call_once(once, [] {
        Imf::Header::setMaxImageSize(kLargestSideRead, kLargestSideRead);
        Imf::Header::setMaxTileSize(kLargestTileSideRead, kLargestTileSideRead);
    });
}

ImageLayout layoutOf(const OIIO::ImageSpec& spec)
{
    ImageLayout layout;
    layout.x = spec.x;
    layout.y = spec.y;
    layout.width = spec.width;
    layout.height = spec.height;
    layout.channels = spec.nchannels;
    layout.bytesPerPixel = static_cast<std::int64_t>(spec.pixel_bytes(true));
    layout.tileWidth = spec.tile_width;
    layout.tileHeight = spec.tile_height;
    layout.deep = spec.deep;
    layout.volume = spec.depth != 1 || spec.z != 0 || spec.tile_depth > 1;
    return layout;
}

// The limits of ImageFile.h, from the header alone (an OpenEXR file's before the C++ library
// opens it, then every file's as OpenImageIO reads it).
void checkWithinLimits(const fs::path& path, const ImageLayout& layout, std::int64_t fileSize)
{
    if (layout.deep)
        refuseToRead(path, "it holds deep data, not an image");
    if (layout.volume)
        refuseToRead(path, "it holds a volume, not an image");
    if (layout.x != 0 || layout.y != 0)
        refuseToRead(path, "its data window starts at (" + std::to_string(layout.x) + ", " +
                               std::to_string(layout.y) + "), not at (0, 0)");
    const std::string size = std::to_string(layout.width) + "x" + std::to_string(layout.height);
    if (layout.width < 1 || layout.height < 1 || layout.channels < 1)
        refuseToRead(path, "it holds no pixels (" + size + ", " + std::to_string(layout.channels) +
                               " channels)");
    if (layout.width > kLargestSideRead || layout.height > kLargestSideRead)
        refuseToRead(path, "its size, " + size + ", is beyond the largest image read (" +
                               std::to_string(kLargestSideRead) + " pixels a side)");
    const std::int64_t pixels = layout.width * layout.height;
    if (pixels > kLargestPixelCountRead)
        refuseToRead(path, "its size, " + size + ", is beyond the largest image read (" +
                               std::to_string(kLargestPixelCountRead) + " pixels)");
    if (layout.channels > kLargestChannelCountRead)
        refuseToRead(path, "its " + std::to_string(layout.channels) +
                               " channels are more than the " +
                               std::to_string(kLargestChannelCountRead) + " read");
    if (layout.tileWidth > kLargestTileSideRead || layout.tileHeight > kLargestTileSideRead)
        refuseToRead(path, "its tiles, " + std::to_string(layout.tileWidth) + "x" +
                               std::to_string(layout.tileHeight) + ", are larger than the " +
                               std::to_string(kLargestTileSideRead) + " pixels a side read");
    const std::int64_t bytes = pixels * layout.bytesPerPixel;
    if (bytes > fileSize * kLargestExpansionRead)
        refuseToRead(path, "its header asks for " + std::to_string(bytes) + " bytes of pixels (" +
                               size + ") from a file of " + std::to_string(fileSize) +
                               " bytes, more than " + std::to_string(kLargestExpansionRead) +
                               " for each byte, which no lossless compression reaches: it is "
                               "cut short or made up");
}

// An image file opened for reading: a regular file, read through the program's own
// descriptor by the reader of the format its extension names, its header within the limits.
class UntrustedImage {
public:
    explicit UntrustedImage(const fs::path& path) : format_(formatFor(path)), file_(path)
    {
        if (format_.openImageIoName == "openexr") {
            limitOpenExrHeaders();
            checkWithinLimits(path, checkOpenExrHeader(file_.stream(), file_.size(), path.string()),
                              file_.size());
        }
        proxy_ = std::make_unique<OIIO::Filesystem::IOFile>(file_.stream(),
                                                            OIIO::Filesystem::IOProxy::Read);
        input_ = OIIO::ImageInput::create(format_.openImageIoName);
        if (!input_)
            refuseToRead(path, "OpenImageIO has no reader for " + format_.openImageIoName + ": " +
                                   OIIO::geterror());
        OIIO::ImageSpec config;
        OIIO::Filesystem::IOProxy* proxy = proxy_.get();
        config.attribute("oiio:ioproxy", OIIO::TypeDesc::PTR, &proxy);
        OIIO::ImageSpec spec;
        if (!input_->open(path.string(), spec, config))
            refuseToRead(path, "not a readable " + lowerCaseExtension(path).substr(1) + " file (" +
                                   input_->geterror() + ")");
        checkWithinLimits(path, layoutOf(input_->spec()), file_.size());
    }
    UntrustedImage(const UntrustedImage&) = delete;
    UntrustedImage& operator=(const UntrustedImage&) = delete;
    ~UntrustedImage()
    {
        if (input_)
            input_->close();
    }

    OIIO::ImageInput& input() { return *input_; }

private:
    static const ImageFormat& formatFor(const fs::path& path)
    {
        try {
            return imageFormatOf(path);
        } catch (const std::runtime_error& error) {
            throw std::runtime_error("cannot read image " + std::string(error.what()));
        }
    }

    const ImageFormat& format_;
    RegularFile file_;
    std::unique_ptr<OIIO::Filesystem::IOFile> proxy_;
    std::unique_ptr<OIIO::ImageInput> input_;
};

bool isTiled(const OIIO::ImageSpec& spec)
{
    return spec.tile_width > 0 && spec.tile_height > 0;
}

// Converts `rows` rows of `width` pixels of the file's native data (every channel in its own
// format, rows `sourceRow` bytes apart) into 32-bit floats (8-bit values scaled to [0, 1]),
// rows `width of the image` floats apart.
bool convertToFloat(const OIIO::ImageSpec& spec, const unsigned char* source, std::size_t sourceRow,
                    int width, int rows, float* destination)
{
    const auto pixelBytes = static_cast<OIIO::stride_t>(spec.pixel_bytes(true));
    const auto floatBytes = static_cast<OIIO::stride_t>(sizeof(float));
    std::size_t offset = 0;
    for (int c = 0; c < spec.nchannels; ++c) {
        const OIIO::TypeDesc format = spec.channelformat(c);
        if (!OIIO::convert_image(1, width, rows, 1, source + offset, format, pixelBytes,
                                 static_cast<OIIO::stride_t>(sourceRow), OIIO::AutoStride,
                                 destination + c, OIIO::TypeFloat, spec.nchannels * floatBytes,
                                 spec.nchannels * floatBytes * spec.width, OIIO::AutoStride))
            return false;
        offset += format.size();
    }
    return true;
}

// Rows [y, end) of every channel as 32-bit floats into `band`, read as the file stores them
// (scan lines, or whole tiles of tile_height rows) and converted here: OpenImageIO 2.4's
// converting reads set aside 64 MB for any read, however small.
bool readBand(OIIO::ImageInput& input, int y, int end, float* band,
              std::vector<unsigned char>& native)
{
    const OIIO::ImageSpec& spec = input.spec();
    const std::size_t pixelBytes = spec.pixel_bytes(true);
    if (!isTiled(spec)) {
        native.resize(static_cast<std::size_t>(end - y) * spec.width * pixelBytes);
        return input.read_native_scanlines(0, 0, y, end, 0, 0, spec.nchannels, native.data()) &&
               convertToFloat(spec, native.data(), spec.width * pixelBytes, spec.width, end - y,
                              band);
    }
    native.resize(spec.tile_bytes(true));
    for (int x = 0; x < spec.width; x += spec.tile_width) {
        if (!input.read_native_tile(0, 0, x, y, 0, native.data()) ||
            !convertToFloat(spec, native.data(), spec.tile_width * pixelBytes,
                            std::min(spec.tile_width, spec.width - x), end - y,
                            band + static_cast<std::size_t>(x) * spec.nchannels))
            return false;
    }
    return true;
}

// OpenImageIO 2.4 (Debian 12) reads PFM but has no writer for it, so PFM is encoded here:
// "PF" (colour) or "Pf" (grey), size, a negative scale for little-endian floats, then the
// rows bottom first. The format holds no attributes.
std::vector<unsigned char> encodePfm(const fs::path& destination, const Image& image)
{
    if (image.channels != 3 && image.channels != 1)
        throw std::runtime_error("cannot write " + destination.string() +
                                 ": PFM holds one or three channels");
    const std::string header = std::string(image.channels == 3 ? "PF" : "Pf") + "\n" +
                               std::to_string(image.width) + " " + std::to_string(image.height) +
                               "\n-1.0\n";
    std::vector<unsigned char> bytes(header.begin(), header.end());
    bytes.reserve(header.size() + image.pixels.size() * 4);
    for (int y = image.height - 1; y >= 0; --y) {
        const float* row = &image.pixels[image.index(0, y, 0)];
        for (int i = 0; i < image.width * image.channels; ++i) {
            std::uint32_t bits;
            std::memcpy(&bits, &row[i], sizeof bits);
            for (int shift = 0; shift < 32; shift += 8)
                bytes.push_back(static_cast<unsigned char>(bits >> shift));
        }
    }
    return bytes;
}

}  // namespace

bool holdsLinearRadiance(const fs::path& path)
{
    const ImageFormat* format = outputFormatOf(path);
    return format != nullptr && format->linearRadiance;
}

std::vector<unsigned char> encodeImage(const fs::path& destination, const Image& image,
                                       const std::vector<ImageAttribute>& attributes,
                                       const std::vector<std::string>& channelNames)
{
    const ImageFormat* format = outputFormatOf(destination);
    if (format == nullptr)
        throw std::runtime_error("cannot write " + destination.string() + ": unknown image format");
    if (lowerCaseExtension(destination) == ".pfm")
        return encodePfm(destination, image);

    auto output = OIIO::ImageOutput::create(format->openImageIoName);
    if (!output)
        throw std::runtime_error("cannot write " + destination.string() +
                                 ": OpenImageIO has no writer for this format");
    OIIO::ImageSpec spec(image.width, image.height, image.channels,
                         format->linearRadiance ? OIIO::TypeDesc::FLOAT : OIIO::TypeDesc::UINT8);
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
    // Into memory: no library sees the file, so none can lose a failed write (PNG and TIFF
    // report none) or end the process over one (JPEG's library exits). The program writes
    // the bytes itself and checks every call (io/OutputFiles.cpp).
    std::vector<unsigned char> bytes;
    OIIO::Filesystem::IOVecOutput memory(bytes);
    OIIO::Filesystem::IOProxy* proxy = &memory;
    spec.attribute("oiio:ioproxy", OIIO::TypeDesc::PTR, &proxy);
    if (!output->open(destination.string(), spec))
        throw std::runtime_error("cannot write " + destination.string() + ": " +
                                 output->geterror());
    const bool written = output->write_image(OIIO::TypeDesc::FLOAT, image.pixels.data());
    const std::string writeError = written ? std::string() : output->geterror();
    const bool closed = output->close();
    if (!written || !closed)
        throw std::runtime_error("cannot write " + destination.string() + ": " +
                                 (written ? output->geterror() : writeError));
    return bytes;
}

void writeImage(const fs::path& path, const Image& image,
                const std::vector<ImageAttribute>& attributes)
{
    writeAllOrNothing({{path, image, attributes, {}}});
}

void checkReadableImage(const fs::path& path)
{
    // Textures may be in any format OpenImageIO recognises, but only a regular file is
    // handed to it (a device or FIFO named like an image would make it read forever), and an
    // EXR only once its header parses strictly (io/OpenExrHeader.h).
    const RegularFile file(path);
    if (lowerCaseExtension(path) == ".exr") {
        limitOpenExrHeaders();
        checkOpenExrHeader(file.stream(), file.size(), path.string());
    }
    auto input = OIIO::ImageInput::open(path.string());
    if (!input)
        refuseToRead(path, OIIO::geterror());
    input->close();
}

ImageHeader readImageHeader(const fs::path& path)
{
    UntrustedImage image(path);
    const OIIO::ImageSpec& spec = image.input().spec();
    return {spec.width, spec.height, spec.nchannels, image.input().format_name()};
}

std::optional<std::string> readImageAttribute(const fs::path& path, const std::string& name)
{
    UntrustedImage image(path);
    const OIIO::ImageSpec& spec = image.input().spec();
    if (spec.find_attribute(name) == nullptr)
        return std::nullopt;
    return spec.get_string_attribute(name);
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
    UntrustedImage file(path);
    OIIO::ImageInput& input = file.input();
    const OIIO::ImageSpec& spec = input.spec();
    ImageFileContents contents;
    contents.format = input.format_name();
    contents.channelNames = spec.channelnames;
    for (const OIIO::ParamValue& attribute : spec.extra_attribs)
        contents.attributes.push_back(
            {attribute.name().string(), attribute.type() == OIIO::TypeDesc::STRING
                                            ? std::string(attribute.get_string())
                                            : std::string(spec.metadata_val(attribute))});
    // Read in bands of rows, the pixels growing with each band read: memory follows the
    // pixels the file holds, not those its header claims (a crafted header within the limits
    // still asks for up to 4096 times the file's size).
    Image& image = contents.image;
    image.width = spec.width;
    image.height = spec.height;
    image.channels = spec.nchannels;
    const std::size_t row = static_cast<std::size_t>(spec.width) * spec.nchannels;
    const int rowsPerBand = isTiled(spec) ? spec.tile_height : 16;
    std::vector<unsigned char> native;
    for (int y = 0; y < spec.height; y += rowsPerBand) {
        const int end = std::min(spec.height, y + rowsPerBand);
        image.pixels.resize(static_cast<std::size_t>(end) * row);
        if (!readBand(input, y, end, image.pixels.data() + y * row, native))
            refuseToRead(path, input.geterror());
    }
    return contents;
}

}  // namespace io
