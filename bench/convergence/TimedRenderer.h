#pragma once
// A progressive renderer timed as bench_convergence measures it: only the frames that add
// samples count, in wall and in CPU time.
#include "render/ProgressiveRenderer.h"

#include <chrono>

namespace convergence {

double secondsSince(std::chrono::steady_clock::time_point start);

// CPU time of the whole process, llvmpipe's rendering threads included (wall time is what a
// user waits; CPU time is the work, which varies far less on a shared machine).
double processCpuSeconds();

// A progressive renderer whose clock counts only the frames that add samples: construction
// (shader compile and link) and one warm-up frame (llvmpipe's code generation at the first
// draw) are timed apart, and the warm-up sample is thrown away.
class TimedRenderer {
public:
    TimedRenderer(const scene::Scene& scene, int width, int height,
                  const settings::RenderSettings& settings, int samplesPerFrame)
        : renderer_(scene, width, height, settings), samplesPerFrame_(samplesPerFrame)
    {
        compileSeconds_ = renderer_.compileSeconds();
        const auto start = std::chrono::steady_clock::now();
        renderer_.renderFrame({}, 1);
        warmUpSeconds_ = secondsSince(start);
        // The same scene again: the program (and the code llvmpipe generated for it) stays,
        // the accumulation restarts from nothing.
        renderer_.setScene(scene);
    }

    // Renders until the image holds `samplesPerPixel` samples per pixel.
    void renderTo(int samplesPerPixel)
    {
        while (renderer_.samplesPerPixel() < samplesPerPixel) {
            const int samples =
                std::min(samplesPerFrame_, samplesPerPixel - renderer_.samplesPerPixel());
            const auto start = std::chrono::steady_clock::now();
            const double cpuStart = processCpuSeconds();
            renderer_.renderFrame({}, samples);
            renderSeconds_ += secondsSince(start);
            cpuSeconds_ += processCpuSeconds() - cpuStart;
        }
    }

    // Renders whole frames while the clock is below `budgetSeconds`. A frame still drawing
    // when the budget runs out is abandoned between bands (its samples are not in the image)
    // but its time is spent: the image is what this much rendering time gives. Near the end,
    // frames hold fewer samples, as many as the time left is expected to take, so that a
    // frame of one band (small images) overruns the budget by little.
    void renderUntil(double budgetSeconds)
    {
        while (renderSeconds_ < budgetSeconds) {
            int samples = samplesPerFrame_;
            if (samplesPerPixel() > 0) {
                const double secondsPerSample = renderSeconds_ / samplesPerPixel();
                const double affordable = (budgetSeconds - renderSeconds_) / secondsPerSample;
                samples = std::clamp(static_cast<int>(affordable), 1, samplesPerFrame_);
            }
            const auto start = std::chrono::steady_clock::now();
            const double cpuStart = processCpuSeconds();
            const double before = renderSeconds_;
            const bool completed = renderer_.renderFrame(
                [&] { return before + secondsSince(start) < budgetSeconds; }, samples);
            renderSeconds_ += secondsSince(start);
            cpuSeconds_ += processCpuSeconds() - cpuStart;
            if (completed)
                secondsAtLastFrame_ = renderSeconds_;
            else
                break;
        }
    }

    const render::ProgressiveRenderer& renderer() const { return renderer_; }
    double compileSeconds() const { return compileSeconds_; }
    double warmUpSeconds() const { return warmUpSeconds_; }
    double renderSeconds() const { return renderSeconds_; }
    double cpuSeconds() const { return cpuSeconds_; }
    double secondsAtLastFrame() const { return secondsAtLastFrame_; }
    int samplesPerPixel() const { return renderer_.samplesPerPixel(); }
    double megapathsPerSecond() const
    {
        return static_cast<double>(renderer_.width()) * renderer_.height() * samplesPerPixel() /
               std::max(renderSeconds_, 1e-9) / 1e6;
    }

private:
    render::ProgressiveRenderer renderer_;
    int samplesPerFrame_;
    double compileSeconds_ = 0.0;
    double warmUpSeconds_ = 0.0;
    double renderSeconds_ = 0.0;
    double cpuSeconds_ = 0.0;
    double secondsAtLastFrame_ = 0.0;
};

// Paths per pixel in one draw: one at 320x240 and above, more at small sizes, where the
// per-frame cost of the host (binding, band timing, glFinish) would otherwise be measured too.
int defaultSamplesPerFrame(int width, int height);

}  // namespace convergence
