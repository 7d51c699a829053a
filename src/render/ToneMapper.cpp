#include "render/ToneMapper.h"

#include "film/ToneCurve.h"
#include "gl/Framebuffer.h"
#include "gl/GlError.h"
#include "render/PathTracerProgram.h"
#include "settings/SettingsTable.h"
#include "shadergen/ShaderSource.h"

#include <vector>

namespace render {

ToneMapper::ToneMapper(const std::filesystem::path& shaderDirectory)
    : program_(fullscreenVertexSource(shaderDirectory),
               "#version 330 core\n" + settings::choiceDefines() + film::toneCurveDefines() +
                   shadergen::readTextFile(shaderDirectory / "modules" / "tone_map.frag"),
               "the tone mapper")
{
}

void ToneMapper::draw(const gl::Texture& estimate, int width, int height, int targetWidth,
                      int targetHeight, const gl::VertexArray& triangle, float exposure,
                      settings::ToneCurveKind curve) const
{
    program_.use();
    estimate.bind(0);
    glUniform1i(program_.uniformLocation("uEstimate"), 0);
    glUniform2f(program_.uniformLocation("uImageSize"), static_cast<float>(width),
                static_cast<float>(height));
    glUniform2f(program_.uniformLocation("uTargetSize"), static_cast<float>(targetWidth),
                static_cast<float>(targetHeight));
    glUniform1f(program_.uniformLocation("uExposure"), exposure);
    glUniform1i(program_.uniformLocation("uToneCurve"), settings::choiceCode(curve));
    glViewport(0, 0, targetWidth, targetHeight);
    glDisable(GL_SCISSOR_TEST);
    triangle.drawFullscreenTriangle();
}

io::Image ToneMapper::render(const gl::Texture& estimate, int width, int height,
                             const gl::VertexArray& triangle, float exposure,
                             settings::ToneCurveKind curve) const
{
    const gl::Texture picture =
        gl::createTexture2D(GL_RGBA8, width, height, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
    const gl::Framebuffer target({&picture});
    target.bindForDrawing();
    draw(estimate, width, height, width, height, triangle, exposure, curve);
    target.bindForReading(0);
    io::Image image = readDisplayPixels(width, height);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    gl::throwOnGlError("tone mapping");
    return image;
}

io::Image readDisplayPixels(int width, int height)
{
    std::vector<unsigned char> rgba(static_cast<std::size_t>(width) * height * 4);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
    io::Image image(width, height, 3);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x)
            for (int c = 0; c < 3; ++c)
                // GL's row 0 is the bottom of the picture.
                image.at(x, height - 1 - y, c) =
                    rgba[(static_cast<std::size_t>(y) * width + x) * 4 + c] / 255.0f;
    return image;
}

}  // namespace render

namespace render {

io::Image readWindowPixels(int width, int height)
{
    glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
    glReadBuffer(GL_BACK);
    io::Image image = readDisplayPixels(width, height);
    gl::throwOnGlError("reading the window");
    return image;
}

}  // namespace render
