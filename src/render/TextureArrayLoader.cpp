#include "render/TextureArrayLoader.h"

#include "gl/GlError.h"

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>

#include <algorithm>
#include <stdexcept>

namespace render {

namespace {

OIIO::ImageBuf readAsRgb8(const std::filesystem::path& file)
{
    OIIO::ImageBuf image(file.string());
    if (!image.read(0, 0, true, OIIO::TypeDesc::UINT8))
        throw std::runtime_error("cannot read texture " + file.string() + ": " + image.geterror());
    const int channels = image.spec().nchannels;
    if (channels == 3)
        return image;
    // Grey images are repeated into three channels; alpha and extra channels are dropped.
    const int grey[3] = {0, 0, 0};
    const int rgb[3] = {0, 1, 2};
    OIIO::ImageBuf converted = OIIO::ImageBufAlgo::channels(image, 3, channels < 3 ? grey : rgb);
    if (converted.has_error())
        throw std::runtime_error("cannot use texture " + file.string() + ": " +
                                 converted.geterror());
    return converted;
}

}  // namespace

PigmentTextures loadPigmentTextures(const std::vector<std::filesystem::path>& files)
{
    PigmentTextures result;
    std::vector<OIIO::ImageBuf> images;
    int width = 1;
    int height = 1;
    for (const auto& file : files) {
        images.push_back(readAsRgb8(file));
        width = std::max(width, images.back().spec().width);
        height = std::max(height, images.back().spec().height);
    }
    result.size = std::max(width, height);

    result.texture.bind(3);
    const int layers = std::max<int>(1, static_cast<int>(images.size()));
    glTexImage3D(GL_TEXTURE_2D_ARRAY, 0, GL_SRGB8, width, height, layers, 0, GL_RGB,
                 GL_UNSIGNED_BYTE, nullptr);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    for (std::size_t layer = 0; layer < images.size(); ++layer) {
        OIIO::ImageBuf resized = images[layer];
        if (resized.spec().width != width || resized.spec().height != height)
            resized = OIIO::ImageBufAlgo::resize(images[layer], "", 0.0f,
                                                 OIIO::ROI(0, width, 0, height, 0, 1, 0, 3));
        std::vector<unsigned char> pixels(static_cast<std::size_t>(width) * height * 3);
        resized.get_pixels(OIIO::ROI(0, width, 0, height, 0, 1, 0, 3), OIIO::TypeDesc::UINT8,
                           pixels.data());
        // The file's first row goes to t = 0, as the original program uploaded it.
        glTexSubImage3D(GL_TEXTURE_2D_ARRAY, 0, 0, 0, static_cast<GLint>(layer), width, height, 1,
                        GL_RGB, GL_UNSIGNED_BYTE, pixels.data());
    }
    glGenerateMipmap(GL_TEXTURE_2D_ARRAY);
    result.texture.setSampling(GL_LINEAR_MIPMAP_LINEAR, GL_LINEAR, GL_REPEAT, GL_REPEAT);
    gl::throwOnGlError("uploading the pigment textures");
    return result;
}

}  // namespace render
