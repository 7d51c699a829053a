#include "render/AccumulationTargets.h"

#include "gl/GlError.h"

#include <vector>

namespace render {

namespace {

AccumulationTargets::Set makeSet(int width, int height)
{
    const std::vector<float> zeros(static_cast<std::size_t>(width) * height * 4, 0.0f);
    gl::Texture estimate =
        gl::createTexture2D(GL_RGBA32F, width, height, GL_RGBA, GL_FLOAT, zeros.data());
    gl::Texture moments =
        gl::createTexture2D(GL_RGBA32F, width, height, GL_RGBA, GL_FLOAT, zeros.data());
    gl::Framebuffer framebuffer({&estimate, &moments});
    return {std::move(estimate), std::move(moments), std::move(framebuffer)};
}

}  // namespace

AccumulationTargets::AccumulationTargets(int width, int height)
    : width_(width), height_(height), sets_{makeSet(width, height), makeSet(width, height)}
{
    gl::throwOnGlError("creating the accumulation targets");
}

}  // namespace render
