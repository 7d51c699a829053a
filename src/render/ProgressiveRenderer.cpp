#include "render/ProgressiveRenderer.h"

#include "gl/GlError.h"
#include "render/TextureUnits.h"

#include <algorithm>
#include <chrono>
#include <optional>
#include <stdexcept>
#include <string>

namespace render {

namespace {

double secondsSince(std::chrono::steady_clock::time_point start)
{
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// Pixels along a side of the preview's coarse grid.
int coarseSide(int side, int divisor)
{
    return std::max(1, (side + divisor - 1) / divisor);
}

std::optional<EnvironmentMapTextures> uploadEnvironmentTextures(const EnvironmentMap* map)
{
    if (map == nullptr)
        return std::nullopt;
    return uploadEnvironmentMap(*map);
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
                                         const settings::RenderSettings& settings)
    : ProgressiveRenderer(chooseKernel(settings.kernel), scene, width, height, settings)
{
}

ProgressiveRenderer::ProgressiveRenderer(const KernelChoice& kernel, const scene::Scene& scene,
                                         int width, int height,
                                         const settings::RenderSettings& settings)
    : ProgressiveRenderer(prepareScene(scene, shadergen::shaderBuild(settings),
                                       defaultShaderDirectory(), kernel.kernel),
                          kernel, width, height, settings)
{
}

ProgressiveRenderer::ProgressiveRenderer(PreparedScene prepared, const KernelChoice& kernel,
                                         int width, int height,
                                         const settings::RenderSettings& settings)
    : settings_(settings),
      kernel_(kernel),
      scene_(std::move(prepared.visible)),
      code_(std::move(prepared.code)),
      uniforms_(std::move(prepared.uniforms)),
      program_((checkRenderSize(width, height),
                std::make_unique<PathTracerProgram>(prepared.pathTracerSource, kernel.kernel,
                                                    defaultShaderDirectory()))),
      pigmentTextures_(loadPigmentTextures(uniforms_.textureLayers)),
      environmentMap_(std::move(prepared.environmentMap)),
      environmentTextures_(uploadEnvironmentTextures(environmentMap_.get())),
      targets_(width, height, settings.featureBuffers),
      toneMapper_(defaultShaderDirectory()),
      tileSampleTargets_(gl::createTexture2D(GL_R32F, 1, 1, GL_RED, GL_FLOAT, nullptr))
{
    // The first band is small: its cost is not known yet (and it pays for the driver's code
    // generation), so a large image's first frame in one band could not be stopped for
    // minutes. Whole frames (secondsPerBand 0) stay whole.
    constexpr int kFirstBandRows = 8;
    rowsPerBand_ = settings.secondsPerBand > 0.0 ? std::min(height, kFirstBandRows) : height;
    uploadAll();
    generateDriverCode();
}

// A draw of one pixel that traces nothing (no sample wanted): the driver generates the
// shader's machine code at its first draw (0.5 to 2 s on llvmpipe), and that belongs to
// setting up, not to the first frame's time per sample.
void ProgressiveRenderer::generateDriverCode()
{
    program_->program().use();
    setDrawUniforms(0, 0, 0);
    bindPrevious(targets_.previous());
    pigmentTextures_.texture.bind(texture_units::kPigmentTextures);
    bindEnvironmentTextures();
    if (sceneData_)
        sceneData_->bind();
    program_->trace(targets_.next(), {0, 0, 1, 1}, width(), height(), triangle_);
    // Every uniform the shader declares is set by now: the scene's and the settings' by
    // uploadAll, the draw's by setDrawUniforms, the compute kernel's region by trace.
    program_->uniforms().checkEveryDeclaredSet();
    glFinish();
    gl::throwOnGlError("generating the shader's code");
}

void ProgressiveRenderer::bindPrevious(const AccumulationTargets::Set& source) const
{
    source.estimate.bind(texture_units::kPreviousEstimate);
    source.moments.bind(texture_units::kPreviousMoments);
    if (source.albedoDepth) {
        source.albedoDepth->bind(texture_units::kAlbedoDepth);
        source.normalCoverage->bind(texture_units::kNormalCoverage);
    }
}

void ProgressiveRenderer::bindEnvironmentTextures() const
{
    if (environmentTextures_)
        environmentTextures_->bind();
}

void ProgressiveRenderer::uploadAll()
{
    program_->program().use();
    ProgramUniforms& uniforms = program_->uniforms();
    uploadUniforms(
        uniforms,
        {uniforms_, settings_, width(), height(), static_cast<float>(pigmentTextures_.size)},
        code_);
    if (shadergen::specializesShapes(code_.variant)) {
        sceneData_.reset();
    } else {
        sceneData_.emplace(uniforms_, code_);
        SceneDataBuffers::setSamplers(uniforms);
    }
    uniforms.set("uPreviousEstimate", texture_units::kPreviousEstimate);
    uniforms.set("uPreviousMoments", texture_units::kPreviousMoments);
    uniforms.set("uPigmentTextures", texture_units::kPigmentTextures);
    uniforms.set("uTileSampleTargets", texture_units::kTileSampleTargets);
    if (uniforms.declares("uPreviousAlbedoDepth")) {
        uniforms.set("uPreviousAlbedoDepth", texture_units::kAlbedoDepth);
        uniforms.set("uPreviousNormalCoverage", texture_units::kNormalCoverage);
    }
    // Their units whether or not the scene has a map: a shader without one reads neither.
    uniforms.set("uEnvironmentMap", EnvironmentMapTextures::kRadianceUnit);
    uniforms.set("uEnvironmentDistribution", EnvironmentMapTextures::kDistributionUnit);
    gl::throwOnGlError("uploading the scene");
}

// The uniforms each draw sets (path_tracer_main.glsl): paths per pixel, the count no pixel
// passes (0: none), and the adaptive tiles' side (0: none).
void ProgressiveRenderer::setDrawUniforms(int samplesPerFrame, int sampleTarget, int tileSize)
{
    ProgramUniforms& uniforms = program_->uniforms();
    uniforms.set("uSamplesPerFrame", samplesPerFrame);
    uniforms.set("uSampleTarget", sampleTarget);
    uniforms.set("uTileSize", tileSize);
}

ReloadDecision ProgressiveRenderer::setScene(const scene::Scene& original,
                                             const std::vector<std::filesystem::path>& changedFiles)
{
    PreparedScene prepared = prepareScene(original, shadergen::shaderBuild(settings_),
                                          defaultShaderDirectory(), kernel_.kernel);
    const ReloadDecision decision =
        decideReload(code_, uniforms_, prepared.code, prepared.uniforms, changedFiles);
    if (decision.changesNothing)
        return decision;
    // Everything that can fail comes first: until the new program and textures exist, the
    // renderer keeps the old ones.
    std::unique_ptr<PathTracerProgram> program =
        decision.rebuildShader
            ? std::make_unique<PathTracerProgram>(prepared.pathTracerSource, kernel_.kernel,
                                                  defaultShaderDirectory())
            : nullptr;
    std::optional<PigmentTextures> textures;
    std::optional<EnvironmentMapTextures> environmentTextures;
    if (decision.reloadTextures) {
        textures = loadPigmentTextures(prepared.uniforms.textureLayers);
        environmentTextures = uploadEnvironmentTextures(prepared.environmentMap.get());
    }

    scene_ = std::move(prepared.visible);
    code_ = std::move(prepared.code);
    uniforms_ = std::move(prepared.uniforms);
    if (program)
        program_ = std::move(program);
    if (textures) {
        pigmentTextures_ = std::move(*textures);
        environmentTextures_ = std::move(environmentTextures);
    }
    environmentMap_ = std::move(prepared.environmentMap);
    uploadAll();
    restartAccumulation();
    if (decision.rebuildShader)
        generateDriverCode();
    return decision;
}

void ProgressiveRenderer::setCamera(const scene::Camera& camera)
{
    scene_.camera = camera;
    // The scene's bounds hold the camera, and the tolerances follow the bounds.
    uniforms_ = packSceneUniforms(scene_, code_, environmentMap_.get());
    uploadAll();
    clearAccumulation();
}

void ProgressiveRenderer::setSettings(const settings::RenderSettings& settings)
{
    const settings::ShaderVariant variant = settings_.variant;
    const bool switchableEnvironment = settings_.switchableEnvironment;
    const settings::PathKernel kernel = settings_.kernel;
    const bool featureBuffers = settings_.featureBuffers;
    settings_ = settings;
    settings_.featureBuffers = featureBuffers;
    settings_.variant = variant;
    settings_.switchableEnvironment = switchableEnvironment;
    settings_.kernel = kernel;
    uploadAll();
    clearAccumulation();
}

void ProgressiveRenderer::setCrop(int x0, int y0, int x1, int y1)
{
    if (!(0 <= x0 && x0 < x1 && x1 <= width() && 0 <= y0 && y0 < y1 && y1 <= height()))
        throw std::invalid_argument("a crop must lie within the image and hold a pixel");
    crop_ = {x0, height() - y1, x1 - x0, y1 - y0};
    rowsPerBand_ = std::min(rowsPerBand_, crop_.height);
}

void ProgressiveRenderer::resize(int width, int height)
{
    if (width == this->width() && height == this->height())
        return;
    crop_ = {};
    checkRenderSize(width, height);
    targets_ = AccumulationTargets(width, height, settings_.featureBuffers);
    rowsPerBand_ = height;
    frames_ = 0;
    samplesPerPixel_ = 0;
    previewDivisor_ = 0;
    tileSize_ = 0;
    uploadAll();
}

void ProgressiveRenderer::resumeFrom(const film::Accumulation& accumulation)
{
    if (accumulation.width() != width() || accumulation.height() != height())
        throw std::invalid_argument("cannot resume a " + std::to_string(accumulation.width()) +
                                    "x" + std::to_string(accumulation.height()) +
                                    " accumulation in a " + std::to_string(width()) + "x" +
                                    std::to_string(height()) + " render");
    if (accumulation.hasFeatures() != settings_.featureBuffers)
        throw std::invalid_argument(
            accumulation.hasFeatures()
                ? "cannot resume an accumulation with feature buffers in a render without them"
                : "cannot resume an accumulation without feature buffers in a render with them: "
                  "its samples have no features to go on from");
    targets_ = AccumulationTargets(accumulation);
    frames_ = 0;
    samplesPerPixel_ = samplesTakenSpan(accumulation).most;
    previewDivisor_ = 0;
    tileSize_ = 0;
}

void ProgressiveRenderer::restartAccumulation()
{
    targets_ = AccumulationTargets(width(), height(), settings_.featureBuffers);
    frames_ = 0;
    samplesPerPixel_ = 0;
    previewDivisor_ = 0;
    tileSize_ = 0;
}

void ProgressiveRenderer::clearAccumulation()
{
    const float zero[4] = {0.0f, 0.0f, 0.0f, 0.0f};
    const AccumulationTargets::Set& shown = targets_.previous();
    shown.framebuffer.bindForDrawing();
    glDisable(GL_SCISSOR_TEST);
    glClearBufferfv(GL_COLOR, 0, zero);  // estimate
    glClearBufferfv(GL_COLOR, 1, zero);  // moments
    if (shown.albedoDepth) {
        glClearBufferfv(GL_COLOR, 2, zero);
        glClearBufferfv(GL_COLOR, 3, zero);
    }
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    gl::throwOnGlError("restarting the accumulation");
    frames_ = 0;
    samplesPerPixel_ = 0;
    previewDivisor_ = 0;
    tileSize_ = 0;
}

void ProgressiveRenderer::renderPreview(int divisor, int maxBounces)
{
    divisor = std::clamp(divisor, 1, std::max(width(), height()));
    const int previewWidth = coarseSide(width(), divisor);
    const int previewHeight = coarseSide(height(), divisor);
    clearAccumulation();

    program_->program().use();
    ProgramUniforms& uniforms = program_->uniforms();
    // The camera spans the coarse grid, which fills the lower-left corner of the targets.
    uniforms.set("uImageSize",
                 glm::vec2(static_cast<float>(previewWidth), static_cast<float>(previewHeight)));
    uniforms.set("uMaxBounces", std::min(maxBounces, settings_.maxBounces));
    setDrawUniforms(1, 0, 0);
    bindPrevious(targets_.previous());
    pigmentTextures_.texture.bind(texture_units::kPigmentTextures);
    bindEnvironmentTextures();
    if (sceneData_)
        sceneData_->bind();
    program_->trace(targets_.next(), {0, 0, previewWidth, previewHeight}, width(), height(),
                    triangle_);
    uniforms.set("uImageSize",
                 glm::vec2(static_cast<float>(width()), static_cast<float>(height())));
    uniforms.set("uMaxBounces", settings_.maxBounces);
    gl::throwOnGlError("rendering a preview");
    targets_.swap();
    previewDivisor_ = divisor;
}

bool ProgressiveRenderer::renderFrame(const std::function<bool()>& keepGoing, int samples)
{
    if (showsPreview())
        clearAccumulation();
    if (samples <= 0)
        samples = std::max(1, settings_.samplesPerFrame);
    if (!drawFrame(keepGoing, samples, samplesPerPixel_ + samples))
        return false;
    ++frames_;
    samplesPerPixel_ += samples;
    return true;
}

void ProgressiveRenderer::setTileSampleTargets(const film::TileSampleTargets& targets)
{
    if (targets.tileSize < 1 || targets.columns * targets.tileSize < width() ||
        targets.rows * targets.tileSize < height() ||
        targets.samples.size() != static_cast<std::size_t>(targets.columns) * targets.rows)
        throw std::invalid_argument("tile sample targets do not cover the image");
    tileSampleTargets_ = gl::createTexture2D(GL_R32F, targets.columns, targets.rows, GL_RED,
                                             GL_FLOAT, targets.samples.data());
    tileSize_ = targets.tileSize;
}

void ProgressiveRenderer::completeSamples()
{
    // A pixel short of the count is short by the paths of one frame's cut at most; a few
    // frames make up any run of them.
    for (int frame = 0; frame < 16 && fewestSamples() < samplesPerPixel_; ++frame)
        drawFrame({}, samplesPerPixel_, samplesPerPixel_);
}

int ProgressiveRenderer::fewestSamples() const
{
    const io::Image estimate = readTarget(targets_.previous().estimate, 4);
    const io::Image moments = readTarget(targets_.previous().moments, 4);
    float fewest = static_cast<float>(samplesPerPixel_);
    const PixelRegion traced = tracedRegion();
    // The images' row 0 is the top, the region's the bottom.
    for (int y = height() - traced.y - traced.height; y < height() - traced.y; ++y)
        for (int x = traced.x; x < traced.x + traced.width; ++x)
            fewest = std::min(fewest, estimate.at(x, y, 3) + moments.at(x, y, 3));
    return static_cast<int>(fewest + 0.5f);
}

// Traces up to `samples` paths per pixel, none beyond `target` samples in all, so that a
// pixel a frame left short catches up.
bool ProgressiveRenderer::drawFrame(const std::function<bool()>& keepGoing, int samples, int target)
{
    const auto frameStart = std::chrono::steady_clock::now();
    const AccumulationTargets::Set& source = targets_.previous();
    const AccumulationTargets::Set& destination = targets_.next();

    program_->program().use();
    setDrawUniforms(2 * samples, target, tileSize_);
    bindPrevious(source);
    pigmentTextures_.texture.bind(texture_units::kPigmentTextures);
    bindEnvironmentTextures();
    if (sceneData_)
        sceneData_->bind();
    tileSampleTargets_.bind(texture_units::kTileSampleTargets);
    const PixelRegion traced = tracedRegion();
    const int top = traced.y + traced.height;
    for (int row = traced.y; row < top;) {
        if (row > traced.y && keepGoing && !keepGoing())
            return false;
        const int rows = std::min(rowsPerBand_, top - row);
        const auto bandStart = std::chrono::steady_clock::now();
        program_->trace(destination, {traced.x, row, traced.width, rows}, width(), height(),
                        triangle_);
        glFinish();
        const double seconds = secondsSince(bandStart);
        row += rows;
        // Aim the next bands at settings_.secondsPerBand each.
        if (settings_.secondsPerBand > 0.0) {
            const double rowsForTarget = rows * settings_.secondsPerBand / std::max(seconds, 1e-4);
            rowsPerBand_ = std::clamp(static_cast<int>(rowsForTarget), 1, traced.height);
        }
    }
    gl::throwOnGlError("rendering a frame");
    targets_.swap();
    const double frameSeconds = secondsSince(frameStart);
    if (frames_ == 0)
        firstFrameSeconds_ = frameSeconds;
    lastSecondsPerSample_ = frameSeconds / samples;
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
    return film::sampleStatistics(accumulation());
}

film::Accumulation ProgressiveRenderer::accumulation() const
{
    film::Accumulation state;
    state.estimate = readTarget(targets_.previous().estimate, 4);
    state.moments = readTarget(targets_.previous().moments, 4);
    if (targets_.hasFeatures()) {
        state.albedoDepth = readTarget(*targets_.previous().albedoDepth, 4);
        state.normalCoverage = readTarget(*targets_.previous().normalCoverage, 4);
    }
    return state;
}

std::pair<io::Image, io::Image> ProgressiveRenderer::accumulationTargets() const
{
    return {readTarget(targets_.previous().estimate, 4),
            readTarget(targets_.previous().moments, 4)};
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
    return toneMapper_.render(targets_.previous().estimate, width(), height(), triangle_,
                              settings_.exposure, settings_.toneCurve);
}

void ProgressiveRenderer::displayToWindow(int windowWidth, int windowHeight) const
{
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    int shownWidth = width();
    int shownHeight = height();
    if (showsPreview()) {
        shownWidth = coarseSide(width(), previewDivisor_);
        shownHeight = coarseSide(height(), previewDivisor_);
    }
    const bool denoised = previewDenoising_ && canPreviewDenoise() && !showsPreview();
    toneMapper_.draw(denoised ? previewDenoised() : targets_.previous().estimate, shownWidth,
                     shownHeight, windowWidth, windowHeight, triangle_, settings_.exposure,
                     settings_.toneCurve);
}

const gl::Texture& ProgressiveRenderer::previewDenoised() const
{
    if (!previewDenoiser_)
        previewDenoiser_ = std::make_unique<PreviewDenoiser>(defaultShaderDirectory());
    const gl::Texture& filtered =
        previewDenoiser_->filter(targets_.previous(), width(), height(), triangle_);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    return filtered;
}

io::Image ProgressiveRenderer::previewDenoisedRadiance() const
{
    if (!canPreviewDenoise())
        throw std::logic_error("the preview denoiser needs feature buffers");
    return readTarget(previewDenoised(), 3);
}

}  // namespace render
