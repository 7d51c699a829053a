#include "render/PreviewDenoiser.h"

#include "gl/GlError.h"
#include "render/PathTracerProgram.h"
#include "render/TextureUnits.h"
#include "shadergen/ShaderSource.h"

namespace render {

namespace {

// Tuned by eye on the classic scenes at 1 to 64 samples per pixel (docs/DENOISING.md).
constexpr float kColorSigma = 4.0f;
constexpr float kNormalSigma = 0.1f;
constexpr float kDepthSigma = 0.05f;

}  // namespace

PreviewDenoiser::PreviewDenoiser(const std::filesystem::path& shaderDirectory)
    : program_(fullscreenVertexSource(shaderDirectory),
               "#version 330 core\n" +
                   shadergen::readTextFile(shaderDirectory / "modules" / "atrous_denoise.frag"),
               "the preview denoiser")
{
}

void PreviewDenoiser::resize(int width, int height)
{
    if (width == width_ && height == height_ && targets_[0])
        return;
    for (auto& target : targets_) {
        gl::Texture texture =
            gl::createTexture2D(GL_RGBA32F, width, height, GL_RGBA, GL_FLOAT, nullptr);
        gl::Framebuffer framebuffer({&texture});
        target = std::make_unique<Target>(Target{std::move(texture), std::move(framebuffer)});
    }
    width_ = width;
    height_ = height;
}

const gl::Texture& PreviewDenoiser::filter(const AccumulationTargets::Set& accumulation, int width,
                                           int height, const gl::VertexArray& triangle)
{
    resize(width, height);
    program_.use();
    accumulation.albedoDepth->bind(texture_units::kAlbedoDepth);
    accumulation.normalCoverage->bind(texture_units::kNormalCoverage);
    accumulation.moments.bind(texture_units::kDenoiserMoments);
    const auto set = [&](const char* name, int value) {
        glUniform1i(program_.uniformLocation(name), value);
    };
    const auto setFloat = [&](const char* name, float value) {
        glUniform1f(program_.uniformLocation(name), value);
    };
    set("uAlbedoDepth", texture_units::kAlbedoDepth);
    set("uNormalCoverage", texture_units::kNormalCoverage);
    set("uMoments", texture_units::kDenoiserMoments);
    set("uSource", texture_units::kDenoiserSource);
    setFloat("uColorSigma", kColorSigma);
    setFloat("uNormalSigma", kNormalSigma);
    setFloat("uDepthSigma", kDepthSigma);
    glUniform2i(program_.uniformLocation("uSize"), width, height);
    glViewport(0, 0, width, height);
    glDisable(GL_SCISSOR_TEST);
    const gl::Texture* source = &accumulation.estimate;
    for (int pass = 0; pass < kPasses; ++pass) {
        const Target& destination = *targets_[pass % 2];
        destination.framebuffer.bindForDrawing();
        source->bind(texture_units::kDenoiserSource);
        set("uStep", 1 << pass);
        set("uFirstPass", pass == 0);
        set("uLastPass", pass == kPasses - 1);
        triangle.drawFullscreenTriangle();
        source = &destination.texture;
    }
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    gl::throwOnGlError("the preview denoiser");
    return *source;
}

}  // namespace render
