#include "io/ImageFile.h"

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <stdexcept>
#include <string>
#include <system_error>
#include <unistd.h>

namespace io {

namespace fs = std::filesystem;

namespace {

std::string lowerExtension(const fs::path& path)
{
    std::string extension = path.extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return extension;
}

bool isPfm(const fs::path& path)
{
    return lowerExtension(path) == ".pfm";
}

// OpenImageIO 2.4 (Debian 12) reads PFM but has no writer for it, so PFM is written here:
// "PF" (colour) or "Pf" (grey), size, a negative scale for little-endian floats, then the
// rows bottom first.
void writePfm(const fs::path& path, const Image& image)
{
    if (image.channels != 3 && image.channels != 1)
        throw std::runtime_error("cannot write " + path.string() +
                                 ": PFM holds one or three channels");
    std::ofstream file(path, std::ios::binary);
    file << (image.channels == 3 ? "PF" : "Pf") << "\n"
         << image.width << " " << image.height << "\n-1.0\n";
    for (int y = image.height - 1; y >= 0; --y) {
        const float* row = &image.pixels[image.index(0, y, 0)];
        for (int i = 0; i < image.width * image.channels; ++i) {
            std::uint32_t bits;
            std::memcpy(&bits, &row[i], sizeof bits);
            const unsigned char bytes[4] = {
                static_cast<unsigned char>(bits), static_cast<unsigned char>(bits >> 8),
                static_cast<unsigned char>(bits >> 16), static_cast<unsigned char>(bits >> 24)};
            file.write(reinterpret_cast<const char*>(bytes), 4);
        }
    }
    if (!file.flush())
        throw std::runtime_error("cannot write " + path.string());
}

void writeThroughOpenImageIo(const fs::path& path, const fs::path& temporary, const Image& image)
{
    checkWritableFormat(path);
    auto output = OIIO::ImageOutput::create(path.string());
    const bool linear = holdsLinearRadiance(path);
    OIIO::ImageSpec spec(image.width, image.height, image.channels,
                         linear ? OIIO::TypeDesc::FLOAT : OIIO::TypeDesc::UINT8);
    if (!output->open(temporary.string(), spec)) {
        throw std::runtime_error("cannot write " + path.string() + ": " + output->geterror());
    }
    const bool written = output->write_image(OIIO::TypeDesc::FLOAT, image.pixels.data());
    const std::string writeError = written ? std::string() : output->geterror();
    const bool closed = output->close();
    if (!written || !closed) {
        std::error_code ignored;
        fs::remove(temporary, ignored);
        throw std::runtime_error("cannot write " + path.string() + ": " +
                                 (written ? output->geterror() : writeError));
    }
}

}  // namespace

bool holdsLinearRadiance(const fs::path& path)
{
    const std::string extension = lowerExtension(path);
    return extension == ".exr" || extension == ".pfm" || extension == ".hdr";
}

void writeImage(const fs::path& path, const Image& image)
{
    // Same folder (so the rename cannot cross file systems), same extension (OpenImageIO
    // picks the format from it).
    const fs::path temporary =
        path.parent_path() / ("." + path.stem().string() + ".partial-" +
                              std::to_string(::getpid()) + path.extension().string());
    if (isPfm(path)) {
        writePfm(temporary, image);
    } else {
        writeThroughOpenImageIo(path, temporary, image);
    }
    std::error_code error;
    fs::rename(temporary, path, error);
    if (error) {
        fs::remove(temporary, error);
        throw std::runtime_error("cannot write " + path.string() + ": " + error.message());
    }
}

void checkWritableFormat(const fs::path& path)
{
    if (isPfm(path))
        return;
    if (!OIIO::ImageOutput::create(path.string()))
        throw std::runtime_error("cannot write " + path.string() +
                                 ": unknown image format (use .ppm, .png, .exr or .pfm)");
}

void checkReadableImage(const fs::path& path)
{
    auto input = OIIO::ImageInput::open(path.string());
    if (!input)
        throw std::runtime_error("cannot read image " + path.string() + ": " + OIIO::geterror());
    input->close();
}

Image readImage(const fs::path& path)
{
    auto input = OIIO::ImageInput::open(path.string());
    if (!input)
        throw std::runtime_error("cannot read image " + path.string() + ": " + OIIO::geterror());
    const OIIO::ImageSpec& spec = input->spec();
    Image image(spec.width, spec.height, spec.nchannels);
    if (!input->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, image.pixels.data()))
        throw std::runtime_error("cannot read image " + path.string() + ": " + input->geterror());
    input->close();
    return image;
}

}  // namespace io
