#include "io/ImageFormats.h"

#include <algorithm>
#include <cctype>

namespace io {

const std::vector<ImageFormat>& outputFormats()
{
    static const std::vector<ImageFormat> formats = {
        {{".ppm"}, false, false, "the tone-mapped picture, 8-bit (binary PPM)"},
        {{".png"}, false, false, "the tone-mapped picture, 8-bit"},
        {{".jpg", ".jpeg"}, false, false, "the tone-mapped picture, 8-bit, lossy (JPEG)"},
        {{".tif", ".tiff"}, false, false, "the tone-mapped picture, 8-bit (TIFF)"},
        {{".exr"}, true, true, "linear HDR radiance, 32-bit float (OpenEXR)"},
        {{".pfm"}, true, true, "linear HDR radiance, 32-bit float (portable float map)"},
        {{".hdr"}, true, false, "linear HDR radiance, Radiance RGBE (about 1% precision)"},
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

std::string listExtensions(const std::vector<const ImageFormat*>& formats)
{
    std::string text;
    for (const ImageFormat* format : formats)
        for (const std::string& extension : format->extensions)
            text += (text.empty() ? "" : ", ") + extension;
    return text;
}

}  // namespace io
