#include "render/AccumulationTargets.h"

#include "gl/GlError.h"

#include <algorithm>
#include <vector>

namespace render {

namespace {

AccumulationTargets::Set makeSet(int width, int height, const float* estimateTexels,
                                 const float* momentsTexels)
{
    gl::Texture estimate =
        gl::createTexture2D(GL_RGBA32F, width, height, GL_RGBA, GL_FLOAT, estimateTexels);
    gl::Texture moments =
        gl::createTexture2D(GL_RGBA32F, width, height, GL_RGBA, GL_FLOAT, momentsTexels);
    gl::Framebuffer framebuffer({&estimate, &moments});
    return {std::move(estimate), std::move(moments), std::move(framebuffer)};
}

AccumulationTargets::Set makeEmptySet(int width, int height)
{
    const std::vector<float> zeros(static_cast<std::size_t>(width) * height * 4, 0.0f);
    return makeSet(width, height, zeros.data(), zeros.data());
}

// GL's rows run bottom first, an image's top first.
std::vector<float> texelsOf(const io::Image& image)
{
    std::vector<float> texels(image.pixels.size());
    const std::size_t row = static_cast<std::size_t>(image.width) * image.channels;
    for (int y = 0; y < image.height; ++y)
        std::copy_n(&image.pixels[image.index(0, y, 0)], row,
                    &texels[static_cast<std::size_t>(image.height - 1 - y) * row]);
    return texels;
}

}  // namespace

AccumulationTargets::AccumulationTargets(int width, int height)
    : width_(width), height_(height), sets_{makeEmptySet(width, height), makeEmptySet(width, height)}
{
    gl::throwOnGlError("creating the accumulation targets");
}

AccumulationTargets::AccumulationTargets(const film::Accumulation& initial)
    : width_(initial.width()), height_(initial.height()), sets_([&] {
          const std::vector<float> estimate = texelsOf(initial.estimate);
          const std::vector<float> moments = texelsOf(initial.moments);
          return std::array<Set, 2>{makeSet(width_, height_, estimate.data(), moments.data()),
                                    makeSet(width_, height_, estimate.data(), moments.data())};
      }())
{
    gl::throwOnGlError("uploading the accumulation to resume");
}

}  // namespace render
