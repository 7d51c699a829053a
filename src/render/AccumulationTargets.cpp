#include "render/AccumulationTargets.h"

#include "gl/GlError.h"

#include <algorithm>
#include <vector>

namespace render {

namespace {

gl::Texture makeTarget(int width, int height, const float* texels)
{
    return gl::createTexture2D(GL_RGBA32F, width, height, GL_RGBA, GL_FLOAT, texels);
}

// `texels`: estimate, moments and, where there are four, the feature targets' texels.
AccumulationTargets::Set makeSet(int width, int height, const std::vector<const float*>& texels)
{
    gl::Texture estimate = makeTarget(width, height, texels[0]);
    gl::Texture moments = makeTarget(width, height, texels[1]);
    std::optional<gl::Texture> albedoDepth;
    std::optional<gl::Texture> normalCoverage;
    std::vector<const gl::Texture*> attachments = {&estimate, &moments};
    if (texels.size() == 4) {
        albedoDepth = makeTarget(width, height, texels[2]);
        normalCoverage = makeTarget(width, height, texels[3]);
        attachments.push_back(&*albedoDepth);
        attachments.push_back(&*normalCoverage);
    }
    gl::Framebuffer framebuffer(attachments);
    return {std::move(estimate), std::move(moments), std::move(albedoDepth),
            std::move(normalCoverage), std::move(framebuffer)};
}

AccumulationTargets::Set makeEmptySet(int width, int height, bool features)
{
    const std::vector<float> zeros(static_cast<std::size_t>(width) * height * 4, 0.0f);
    std::vector<const float*> texels(features ? 4 : 2, zeros.data());
    return makeSet(width, height, texels);
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

AccumulationTargets::AccumulationTargets(int width, int height, bool features)
    : width_(width),
      height_(height),
      sets_{makeEmptySet(width, height, features), makeEmptySet(width, height, features)}
{
    gl::throwOnGlError("creating the accumulation targets");
}

AccumulationTargets::AccumulationTargets(const film::Accumulation& initial)
    : width_(initial.width()), height_(initial.height()), sets_([&] {
          std::vector<std::vector<float>> images = {texelsOf(initial.estimate),
                                                    texelsOf(initial.moments)};
          if (initial.hasFeatures()) {
              images.push_back(texelsOf(initial.albedoDepth));
              images.push_back(texelsOf(initial.normalCoverage));
          }
          std::vector<const float*> texels;
          for (const std::vector<float>& image : images)
              texels.push_back(image.data());
          return std::array<Set, 2>{makeSet(width_, height_, texels),
                                    makeSet(width_, height_, texels)};
      }())
{
    gl::throwOnGlError("uploading the accumulation to resume");
}

}  // namespace render
