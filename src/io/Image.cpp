#include "io/Image.h"

namespace io {

Image::Image(int width, int height, int channels)
    : width(width),
      height(height),
      channels(channels),
      pixels(static_cast<std::size_t>(width) * height * channels, 0.0f)
{
}

std::size_t Image::index(int x, int y, int channel) const
{
    return (static_cast<std::size_t>(y) * width + x) * channels + channel;
}

float& Image::at(int x, int y, int channel)
{
    return pixels[index(x, y, channel)];
}

float Image::at(int x, int y, int channel) const
{
    return pixels[index(x, y, channel)];
}

}  // namespace io
