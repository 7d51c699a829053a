#include "io/ImageFile.h"

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cctype>
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
    std::error_code error;
    fs::rename(temporary, path, error);
    if (error) {
        fs::remove(temporary, error);
        throw std::runtime_error("cannot write " + path.string() + ": " + error.message());
    }
}

void checkWritableFormat(const fs::path& path)
{
    if (!OIIO::ImageOutput::create(path.string()))
        throw std::runtime_error("cannot write " + path.string() +
                                 ": unknown image format (use .ppm, .png, .exr or .pfm)");
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
