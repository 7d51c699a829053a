#pragma once
// The window's preview denoiser (shaders/modules/atrous_denoise.frag): an edge-avoiding
// à-trous filter guided by the feature buffers, five passes between two RGBA32F textures of
// its own. Display only: what it makes is tone-mapped to the screen, never written to a file
// (a final frame is denoised by Open Image Denoise, app/Denoising.h). Texture units 12 to 15.
#include "gl/Framebuffer.h"
#include "gl/Shader.h"
#include "gl/Texture.h"
#include "gl/VertexArray.h"
#include "render/AccumulationTargets.h"

#include <array>
#include <filesystem>
#include <memory>

namespace render {

class PreviewDenoiser {
public:
    explicit PreviewDenoiser(const std::filesystem::path& shaderDirectory);

    // Filters the lower-left width x height pixels of `accumulation` (which must have feature
    // targets); returns the texture holding the result (rgb: radiance), valid until the next
    // call.
    const gl::Texture& filter(const AccumulationTargets::Set& accumulation, int width, int height,
                              const gl::VertexArray& triangle);

    static constexpr int kPasses = 5;

private:
    struct Target {
        gl::Texture texture;
        gl::Framebuffer framebuffer;
    };
    void resize(int width, int height);

    gl::Program program_;
    int width_ = 0;
    int height_ = 0;
    std::array<std::unique_ptr<Target>, 2> targets_;
};

}  // namespace render
