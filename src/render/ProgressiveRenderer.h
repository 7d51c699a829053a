#pragma once
#include "film/Accumulation.h"
#include "film/AdaptiveSampling.h"
#include "gl/VertexArray.h"
#include "io/Image.h"
#include "render/AccumulationTargets.h"
#include "render/EnvironmentMapTextures.h"
#include "render/PathTracerProgram.h"
#include "render/PreviewDenoiser.h"
#include "render/ReloadDecision.h"
#include "render/SceneDataBuffers.h"
#include "render/ScenePreparation.h"
#include "render/SceneUniforms.h"
#include "render/TextureArrayLoader.h"
#include "render/ToneMapper.h"
#include "scene/Scene.h"
#include "settings/RenderSettings.h"

#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <utility>
#include <vector>

namespace render {

// Renders a scene progressively in the GL context current on this thread: every frame adds
// one path per pixel to each pixel's running estimate.
class ProgressiveRenderer {
public:
    // Builds the shader for the scene (specialised or general, per settings.variant; for the
    // kernel settings.kernel stands for in this context, render/KernelChoice.h) and the
    // accumulation targets. Objects that do nothing to light (scene/InvisibleObjects.h) are
    // left out. Throws with a readable message when a shader does not compile,
    // a texture cannot be read, or the size exceeds what the GL supports.
    ProgressiveRenderer(const scene::Scene& scene, int width, int height,
                        const settings::RenderSettings& settings);

    // Adds `samples` samples per pixel (default: settings.samplesPerFrame). The frame is
    // drawn in horizontal bands sized to take about settings.secondsPerBand each (a frame of
    // a heavy scene on a software rasteriser can take many seconds); between bands
    // `keepGoing` is asked whether to go on. When it says no, the partial frame is dropped,
    // the image stays as it was, and false is returned. A pixel may end a frame a sample or
    // two short, where the GPU's loop budget cut a path (shaders/modules/constants.glsl);
    // the next frame makes up for it, and completeSamples() evens every pixel out.
    bool renderFrame(const std::function<bool()>& keepGoing = {}, int samples = 0);

    // Adaptive sampling: from the next frame on, each pixel takes samples only up to its
    // tile's count in `targets` (film/AdaptiveSampling.h), and a tile whose pixels all hold
    // theirs costs almost nothing. samplesPerPixel() then counts what the frames aimed at,
    // the most a pixel may hold; accumulation() says what each holds. Lifted by
    // clearTileSampleTargets and by anything that restarts the accumulation.
    void setTileSampleTargets(const film::TileSampleTargets& targets);
    void clearTileSampleTargets() { tileSize_ = 0; }
    bool samplesAdaptively() const { return tileSize_ > 0; }

    // Renders until every pixel holds samplesPerPixel() samples exactly (kept or discarded).
    void completeSamples();

    // The fewest samples (kept and discarded) any pixel holds.
    int fewestSamples() const;

    // Replaces the scene: if its shader code is unchanged (only values differ) the uniforms
    // are re-uploaded; otherwise the shader is rebuilt (render/ReloadDecision.h decides).
    // `changedFiles`: files whose bytes changed on disk since the scene shown was loaded; a
    // user SDF file among them rebuilds the shader, a texture reloads the textures. Either
    // way accumulation restarts, unless nothing the GPU is given differs (changesNothing: a
    // comment edited, say), when the renderer goes on as it was. Returns what was redone.
    // When the new shader does not compile or a texture cannot be read it throws, and the
    // renderer is as it was: same shader, same scene, same image.
    ReloadDecision setScene(const scene::Scene& scene,
                            const std::vector<std::filesystem::path>& changedFiles = {});

    // The view changes: another camera, settings or image size. Uniforms only, never a
    // recompile; the accumulation starts again from nothing.
    void setCamera(const scene::Camera& camera);
    // Every setting but the shader's (variant, switchable environment), which stay as built.
    void setSettings(const settings::RenderSettings& settings);
    void resize(int width, int height);
    // From the next frame on, traces only columns x0 to x1 - 1 and rows y0 to y1 - 1 (row 0
    // the top; within the image): the other pixels keep what they hold (nothing, from a
    // fresh start), so the crops of a frame merge into it exactly. Lifted by resize.
    void setCrop(int x0, int y0, int x1, int y1);
    const settings::RenderSettings& settings() const { return settings_; }
    // The camera the image is rendered from.
    const scene::Camera& camera() const { return scene_.camera; }

    // Goes on from `accumulation` (of this scene, size and settings: a saved render's)
    // instead of from nothing: each pixel's next sample takes the next index of its sequence
    // (shaders/modules/sampler.glsl), so the samples added are new ones, never those it
    // holds. samplesPerPixel() becomes the most samples a pixel holds; pixels holding fewer
    // catch up in the next frames. Throws std::invalid_argument for another size.
    void resumeFrom(const film::Accumulation& accumulation);

    // One cheap picture while the view keeps changing: one path per pixel for a grid
    // `divisor` times coarser than the image, with at most `maxBounces` bounces. It replaces
    // the estimate on screen but is no part of the accumulation: samplesPerPixel() is 0 and
    // the next renderFrame starts from nothing.
    void renderPreview(int divisor, int maxBounces);
    bool showsPreview() const { return previewDivisor_ > 0; }

    int width() const { return targets_.width(); }
    int height() const { return targets_.height(); }
    int samplesPerPixel() const { return samplesPerPixel_; }
    int frames() const { return frames_; }

    // Linear radiance, RGB, top row first.
    io::Image radiance() const;
    // Per pixel: r = samples accumulated, g = samples discarded, b = variance of the mean
    // radiance (channel average).
    io::Image sampleStatistics() const;
    // What every pixel has accumulated (film/Accumulation.h).
    film::Accumulation accumulation() const;
    // The two accumulation targets as they are (RGBA each, top row first): in a shader built
    // with profileCounters, the work counted per pixel (shaders/modules/work_counters.glsl).
    std::pair<io::Image, io::Image> accumulationTargets() const;
    // Samples discarded as NaN, infinite or negative, over the whole image.
    std::uint64_t discardedSamples() const;
    // The tone-mapped picture, display values in [0, 1], top row first.
    io::Image toneMapped() const;
    // Draws the tone-mapped picture into the window's default framebuffer.
    void displayToWindow(int windowWidth, int windowHeight) const;
    // The window's preview denoiser (render/PreviewDenoiser.h): display only, never in
    // toneMapped() or any file. Takes effect only with feature buffers (canPreviewDenoise).
    void setPreviewDenoising(bool on) { previewDenoising_ = on; }
    bool previewDenoising() const { return previewDenoising_; }
    bool canPreviewDenoise() const { return targets_.hasFeatures(); }
    // What the preview denoiser makes of the accumulation: linear RGB, top row first (for
    // tests and docs/DENOISING.md's measurements). Throws std::logic_error without features.
    io::Image previewDenoisedRadiance() const;
    // The tone map's exposure and curve (settings().exposure and toneCurve; display only: the
    // accumulation goes on).
    void setExposure(float exposure) { settings_.exposure = exposure; }
    float exposure() const { return settings_.exposure; }
    void setToneCurve(settings::ToneCurveKind curve) { settings_.toneCurve = curve; }

    const scene::SceneFeatures& features() const { return code_.features; }
    // The kernel that traces the paths (settings().kernel as chosen in this context), and why.
    const KernelChoice& kernel() const { return kernel_; }
    double compileSeconds() const { return program_->compileSeconds(); }
    // Duration of the first frame, which includes the driver's code generation.
    double firstFrameSeconds() const { return firstFrameSeconds_; }
    // Duration of the last frame completed, per sample per pixel it added.
    double lastSecondsPerSample() const { return lastSecondsPerSample_; }
    // What building the hierarchy over the objects took (0 for specialised shapes).
    double hierarchySeconds() const { return uniforms_.hierarchySeconds; }
    // What the general shader's scene data takes on the GPU (0 for specialised shapes).
    std::size_t sceneDataBytes() const { return sceneData_ ? sceneData_->bytes() : 0; }

private:
    ProgressiveRenderer(const KernelChoice& kernel, const scene::Scene& scene, int width,
                        int height, const settings::RenderSettings& settings);
    ProgressiveRenderer(PreparedScene prepared, const KernelChoice& kernel, int width, int height,
                        const settings::RenderSettings& settings);
    void uploadAll();
    void setDrawUniforms(int samplesPerFrame, int sampleTarget, int tileSize);
    void bindEnvironmentTextures() const;
    // The accumulation the next draw reads, on its units.
    void bindPrevious(const AccumulationTargets::Set& source) const;
    void generateDriverCode();
    void restartAccumulation();
    bool drawFrame(const std::function<bool()>& keepGoing, int samples, int target);
    // Starts the accumulation again without reseeding: cheaper than restartAccumulation,
    // for the many restarts of a view being changed.
    void clearAccumulation();
    // The crop, or the whole image.
    PixelRegion tracedRegion() const
    {
        return crop_.width > 0 ? crop_ : PixelRegion{0, 0, width(), height()};
    }
    io::Image readTarget(const gl::Texture& texture, int channels) const;

    settings::RenderSettings settings_;
    KernelChoice kernel_;  // never Automatic
    scene::Scene scene_;   // without its invisible objects
    shadergen::SceneShaderCode code_;
    SceneUniforms uniforms_;
    std::unique_ptr<PathTracerProgram> program_;
    PigmentTextures pigmentTextures_;
    // Where the scene has an environment map: the map (its power weighs its light's
    // selection) and its textures.
    std::shared_ptr<const EnvironmentMap> environmentMap_;
    std::optional<EnvironmentMapTextures> environmentTextures_;
    // The general shader's scene data (units 7 to 11); none for specialised shapes.
    std::optional<SceneDataBuffers> sceneData_;
    AccumulationTargets targets_;
    ToneMapper toneMapper_;
    gl::VertexArray triangle_;
    gl::Texture tileSampleTargets_;
    int tileSize_ = 0;  // 0: every pixel samples alike
    int frames_ = 0;
    int samplesPerPixel_ = 0;
    int rowsPerBand_ = 0;
    // The pixels a frame traces, in GL's coordinates (row 0 the bottom): the whole image
    // unless setCrop says otherwise; empty (width 0) for the whole image.
    PixelRegion crop_;
    int previewDivisor_ = 0;  // 0: the estimate is the accumulation
    bool previewDenoising_ = false;
    mutable std::unique_ptr<PreviewDenoiser> previewDenoiser_;  // made at its first use
    const gl::Texture& previewDenoised() const;
    double firstFrameSeconds_ = 0.0;
    double lastSecondsPerSample_ = 0.0;
};

// Largest width or height this GL renders to; throws with a clear message for sizes beyond.
void checkRenderSize(int width, int height);

}  // namespace render
