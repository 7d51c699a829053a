#pragma once
#include "gl/VertexArray.h"
#include "io/Image.h"
#include "render/AccumulationTargets.h"
#include "render/PathTracerProgram.h"
#include "render/RenderSettings.h"
#include "render/SceneUniforms.h"
#include "render/TextureArrayLoader.h"
#include "render/ToneMapper.h"
#include "scene/Scene.h"

#include <cstdint>
#include <functional>
#include <memory>

namespace render {

// Renders a scene progressively in the GL context current on this thread: every frame adds
// one path per pixel to each pixel's running estimate.
class ProgressiveRenderer {
public:
    // Builds the shader for the scene (specialised or general, per settings.variant) and the
    // accumulation targets. Objects that do nothing to light (scene/InvisibleObjects.h) are
    // left out. Throws with a readable message when a shader does not compile,
    // a texture cannot be read, or the size exceeds what the GL supports.
    ProgressiveRenderer(const scene::Scene& scene, int width, int height,
                        const RenderSettings& settings);

    // Adds `samples` samples per pixel (default: settings.samplesPerFrame). The frame is
    // drawn in horizontal bands sized to take about settings.secondsPerBand each (a frame of
    // a heavy scene on a software rasteriser can take many seconds); between bands
    // `keepGoing` is asked whether to go on. When it says no, the partial frame is dropped,
    // the image stays as it was, and false is returned. A pixel may end a frame a sample or
    // two short, where the GPU's loop budget cut a path (shaders/modules/constants.glsl);
    // the next frame makes up for it, and completeSamples() evens every pixel out.
    bool renderFrame(const std::function<bool()>& keepGoing = {}, int samples = 0);

    // Renders until every pixel holds samplesPerPixel() samples exactly (kept or discarded).
    void completeSamples();

    // The fewest samples (kept and discarded) any pixel holds.
    int fewestSamples() const;

    // Replaces the scene: if its shader code is unchanged (only values differ) the uniforms
    // are re-uploaded; otherwise the shader is rebuilt. Either way accumulation restarts.
    void setScene(const scene::Scene& scene);

    int width() const { return targets_.width(); }
    int height() const { return targets_.height(); }
    int samplesPerPixel() const { return samplesPerPixel_; }
    int frames() const { return frames_; }

    // Linear radiance, RGB, top row first.
    io::Image radiance() const;
    // Per pixel: r = samples accumulated, g = samples discarded, b = variance of the mean
    // radiance (channel average).
    io::Image sampleStatistics() const;
    // Samples discarded as NaN, infinite or negative, over the whole image.
    std::uint64_t discardedSamples() const;
    // The tone-mapped picture, display values in [0, 1], top row first.
    io::Image toneMapped() const;
    // Draws the tone-mapped picture into the window's default framebuffer.
    void displayToWindow(int windowWidth, int windowHeight) const;

    const std::string& fragmentSource() const { return program_->fragmentSource(); }
    const scene::SceneFeatures& features() const { return code_.features; }
    double compileSeconds() const { return program_->compileSeconds(); }
    // Duration of the first frame, which includes the driver's code generation.
    double firstFrameSeconds() const { return firstFrameSeconds_; }
    // Duration of the last frame completed, per sample per pixel it added.
    double lastSecondsPerSample() const { return lastSecondsPerSample_; }

private:
    void buildProgram();
    void uploadAll();
    void restartAccumulation();
    bool drawFrame(const std::function<bool()>& keepGoing, int samples, int target);
    io::Image readTarget(const gl::Texture& texture, int channels) const;

    RenderSettings settings_;
    SceneShaderCode code_;
    SceneUniforms uniforms_;
    std::unique_ptr<PathTracerProgram> program_;
    PigmentTextures pigmentTextures_;
    AccumulationTargets targets_;
    ToneMapper toneMapper_;
    gl::VertexArray triangle_;
    int frames_ = 0;
    int samplesPerPixel_ = 0;
    int rowsPerBand_ = 0;
    double firstFrameSeconds_ = 0.0;
    double lastSecondsPerSample_ = 0.0;
};

// Largest width or height this GL renders to; throws with a clear message for sizes beyond.
void checkRenderSize(int width, int height);

}  // namespace render
