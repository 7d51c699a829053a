#include "io/ImageFormats.h"

#include <algorithm>
#include <cctype>
#include <stdexcept>

namespace io {

const std::vector<ImageFormat>& outputFormats()
{
    static const std::vector<ImageFormat> formats = {
        {{".ppm"}, false, false, "the tone-mapped picture, 8-bit (binary PPM)", "pnm"},
        {{".png"}, false, false, "the tone-mapped picture, 8-bit", "png"},
        {{".jpg", ".jpeg"}, false, false, "the tone-mapped picture, 8-bit, lossy (JPEG)", "jpeg"},
        {{".tif", ".tiff"}, false, false, "the tone-mapped picture, 8-bit (TIFF)", "tiff"},
        {{".exr"}, true, true, "linear HDR radiance, 32-bit float (OpenEXR)", "openexr"},
        {{".pfm"}, true, true, "linear HDR radiance, 32-bit float (portable float map)", "pnm"},
        {{".hdr"}, true, false, "linear HDR radiance, Radiance RGBE (about 1% precision)", "hdr"},
    };
    return formats;
}

std::string lowerCaseExtension(const std::filesystem::path& path)
{
    std::string extension = path.extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return extension;
}

const ImageFormat* outputFormatOf(const std::filesystem::path& path)
{
    const std::string extension = lowerCaseExtension(path);
    for (const ImageFormat& format : outputFormats())
        if (std::find(format.extensions.begin(), format.extensions.end(), extension) !=
            format.extensions.end())
            return &format;
    return nullptr;
}

const ImageFormat& imageFormatOf(const std::filesystem::path& path)
{
    const ImageFormat* format = outputFormatOf(path);
    if (format == nullptr) {
        std::vector<const ImageFormat*> all;
        for (const ImageFormat& known : outputFormats())
            all.push_back(&known);
        throw std::runtime_error(path.string() + ": unknown image format (" + listExtensions(all) +
                                 ")");
    }
    return *format;
}

std::string listExtensions(const std::vector<const ImageFormat*>& formats)
{
    std::string text;
    for (const ImageFormat* format : formats)
        for (const std::string& extension : format->extensions)
            text += (text.empty() ? "" : ", ") + extension;
    return text;
}

}  // namespace io
