#include "render/ProgressiveRenderer.h"

#include "gl/GlError.h"
#include "scene/FileLookup.h"
#include "scene/InvisibleObjects.h"

#include <algorithm>
#include <chrono>
#include <stdexcept>
#include <string>

namespace render {

namespace {

std::filesystem::path shaderDirectory()
{
    return scene::FileLookup::dataDirectory() / "shaders";
}

double secondsSince(std::chrono::steady_clock::time_point start)
{
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

void checkRenderSize(int width, int height)
{
    GLint maxTexture = 0;
    GLint maxViewport[2] = {0, 0};
    glGetIntegerv(GL_MAX_TEXTURE_SIZE, &maxTexture);
    glGetIntegerv(GL_MAX_VIEWPORT_DIMS, maxViewport);
    const int limit = std::min({maxTexture, maxViewport[0], maxViewport[1]});
    if (width < 1 || height < 1 || width > limit || height > limit)
        throw std::runtime_error("image size " + std::to_string(width) + "x" +
                                 std::to_string(height) +
                                 " is out of range: this OpenGL renders at most " +
                                 std::to_string(limit) + " pixels on a side");
}

ProgressiveRenderer::ProgressiveRenderer(const scene::Scene& scene, int width, int height,
                                         const RenderSettings& settings)
    : settings_(settings),
      code_(generateSceneShaderCode(scene::dropInvisibleObjects(scene), settings.variant)),
      uniforms_(packSceneUniforms(scene::dropInvisibleObjects(scene), code_)),
      program_((checkRenderSize(width, height),
                std::make_unique<PathTracerProgram>(code_, shaderDirectory()))),
      pigmentTextures_(loadPigmentTextures(uniforms_.textureLayers)),
      targets_(width, height, settings.seed),
      toneMapper_(shaderDirectory())
{
    // The first band is small: its cost is not known yet (and it pays for the driver's code
    // generation), so a large image's first frame in one band could not be stopped for
    // minutes. Whole frames (secondsPerBand 0) stay whole.
    constexpr int kFirstBandRows = 8;
    rowsPerBand_ = settings.secondsPerBand > 0.0 ? std::min(height, kFirstBandRows) : height;
    uploadAll();
}

void ProgressiveRenderer::uploadAll()
{
    program_->program().use();
    uploadUniforms(program_->program(), uniforms_, code_, settings_, width(), height());
    const gl::Program& program = program_->program();
    glUniform1i(program.uniformLocation("uPreviousEstimate"), 0);
    glUniform1i(program.uniformLocation("uPreviousMoments"), 1);
    glUniform1i(program.uniformLocation("uPreviousRandomState"), 2);
    glUniform1i(program.uniformLocation("uPigmentTextures"), 3);
    glUniform1f(program.uniformLocation("uPigmentTextureSize"),
                static_cast<float>(pigmentTextures_.size));
    gl::throwOnGlError("uploading the scene");
}

void ProgressiveRenderer::setScene(const scene::Scene& original)
{
    const scene::Scene scene = scene::dropInvisibleObjects(original);
    SceneShaderCode code = generateSceneShaderCode(scene, settings_.variant);
    SceneUniforms uniforms = packSceneUniforms(scene, code);
    const bool sameStructure = code.defines == code_.defines &&
                               code.sceneFunctions == code_.sceneFunctions &&
                               code.userSdfFiles == code_.userSdfFiles;
    if (uniforms.textureLayers != uniforms_.textureLayers)
        pigmentTextures_ = loadPigmentTextures(uniforms.textureLayers);
    code_ = std::move(code);
    uniforms_ = std::move(uniforms);
    if (!sameStructure)
        program_ = std::make_unique<PathTracerProgram>(code_, shaderDirectory());
    uploadAll();
    restartAccumulation();
}

void ProgressiveRenderer::restartAccumulation()
{
    targets_ = AccumulationTargets(width(), height(), settings_.seed);
    frames_ = 0;
    samplesPerPixel_ = 0;
}

bool ProgressiveRenderer::renderFrame(const std::function<bool()>& keepGoing, int samples)
{
    if (samples <= 0)
        samples = std::max(1, settings_.samplesPerFrame);
    const auto frameStart = std::chrono::steady_clock::now();
    const AccumulationTargets::Set& source = targets_.previous();
    const AccumulationTargets::Set& destination = targets_.next();

    program_->program().use();
    glUniform1i(program_->program().uniformLocation("uSamplesPerFrame"), samples);
    source.estimate.bind(0);
    source.moments.bind(1);
    source.randomState.bind(2);
    pigmentTextures_.texture.bind(3);
    destination.framebuffer.bindForDrawing();
    // The viewport stays the whole image so gl_FragCoord is the pixel; the scissor picks
    // the band.
    glViewport(0, 0, width(), height());
    glEnable(GL_SCISSOR_TEST);

    for (int row = 0; row < height();) {
        if (row > 0 && keepGoing && !keepGoing()) {
            glDisable(GL_SCISSOR_TEST);
            glBindFramebuffer(GL_FRAMEBUFFER, 0);
            return false;
        }
        const int rows = std::min(rowsPerBand_, height() - row);
        const auto bandStart = std::chrono::steady_clock::now();
        glScissor(0, row, width(), rows);
        triangle_.drawFullscreenTriangle();
        glFinish();
        const double seconds = secondsSince(bandStart);
        row += rows;
        // Aim the next bands at settings_.secondsPerBand each.
        if (settings_.secondsPerBand > 0.0) {
            const double rowsForTarget =
                rows * settings_.secondsPerBand / std::max(seconds, 1e-4);
            rowsPerBand_ = std::clamp(static_cast<int>(rowsForTarget), 1, height());
        }
    }
    glDisable(GL_SCISSOR_TEST);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    gl::throwOnGlError("rendering a frame");
    targets_.swap();
    const double frameSeconds = secondsSince(frameStart);
    if (frames_ == 0)
        firstFrameSeconds_ = frameSeconds;
    lastSecondsPerSample_ = frameSeconds / samples;
    ++frames_;
    samplesPerPixel_ += samples;
    return true;
}

io::Image ProgressiveRenderer::readTarget(const gl::Texture& texture, int channels) const
{
    const gl::Framebuffer reader({&texture});
    reader.bindForReading(0);
    std::vector<float> rgba(static_cast<std::size_t>(width()) * height() * 4);
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glReadPixels(0, 0, width(), height(), GL_RGBA, GL_FLOAT, rgba.data());
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    gl::throwOnGlError("reading back the image");
    io::Image image(width(), height(), channels);
    for (int y = 0; y < height(); ++y)
        for (int x = 0; x < width(); ++x)
            for (int c = 0; c < channels; ++c)
                image.at(x, height() - 1 - y, c) =
                    rgba[(static_cast<std::size_t>(y) * width() + x) * 4 + c];
    return image;
}

io::Image ProgressiveRenderer::radiance() const
{
    return readTarget(targets_.previous().estimate, 3);
}

io::Image ProgressiveRenderer::sampleStatistics() const
{
    const io::Image estimate = readTarget(targets_.previous().estimate, 4);
    const io::Image moments = readTarget(targets_.previous().moments, 4);
    io::Image statistics(width(), height(), 3);
    for (int y = 0; y < height(); ++y)
        for (int x = 0; x < width(); ++x) {
            const float count = estimate.at(x, y, 3);
            const float sumSquares =
                (moments.at(x, y, 0) + moments.at(x, y, 1) + moments.at(x, y, 2)) / 3.0f;
            statistics.at(x, y, 0) = count;
            statistics.at(x, y, 1) = moments.at(x, y, 3);
            statistics.at(x, y, 2) = count > 1.0f ? sumSquares / (count * (count - 1.0f)) : 0.0f;
        }
    return statistics;
}

std::uint64_t ProgressiveRenderer::discardedSamples() const
{
    const io::Image moments = readTarget(targets_.previous().moments, 4);
    double total = 0.0;
    for (int y = 0; y < height(); ++y)
        for (int x = 0; x < width(); ++x)
            total += moments.at(x, y, 3);
    return static_cast<std::uint64_t>(total + 0.5);
}

io::Image ProgressiveRenderer::toneMapped() const
{
    return toneMapper_.render(targets_.previous().estimate, width(), height(), triangle_);
}

void ProgressiveRenderer::displayToWindow(int windowWidth, int windowHeight) const
{
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    toneMapper_.draw(targets_.previous().estimate, width(), height(), windowWidth, windowHeight,
                     triangle_);
}

}  // namespace render
