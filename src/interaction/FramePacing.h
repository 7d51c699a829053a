#pragma once

#include <optional>

namespace interaction {

// Paths per pixel in the next frame so that it takes about `targetFrameSeconds`, from what
// one path per pixel took in the last frame: at least 1 and at most `most`. Several paths per
// frame keep SIMD lanes busy (a pixel whose path ends starts the next at once) and the
// per-draw overhead small; a window still wants frequent frames. Adaptive sampling asks for
// more: where only a few pixels still sample, a frame of 16 would be mostly overhead.
int samplesPerFrameFor(double targetFrameSeconds, double secondsPerSample, int most = 16);

// The samples per pixel the frames of a render loop add, the one policy of the batch render
// and the window: the user's --samples-per-frame when given; otherwise the setting's value
// for the first frame, then samplesPerFrameFor the loop's frame time and the cost the last
// frame measured. The first frame's cost includes code generation, which can only make the
// second frame shorter than aimed, never longer; a second frame at the setting's value
// instead (one path per pixel) runs at a third of the speed of a full one (scene 3 of the
// original on llvmpipe: SIMD lanes wait for the slowest pixel of their group).
//
// A render aimed at an error stops at the first frame that ends with the target reached, so
// a frame longer than the time left wastes the difference (and under adaptive sampling,
// which replans after every frame, it also carries every pixel to a share planned from an
// older estimate). Where the time left is predicted, frames take at most kFrameShareOfTimeLeft
// of it, and no less than kShortestAimedFrameSeconds, whose samples dwarf a frame's fixed cost
// (the read-back and the plan).
//
// A render with a time limit abandons the frame the limit interrupts (its bands are not
// all drawn), so frames aim to end by the limit: at most kFrameShareOfTimeToLimit of the
// time to it, and no less than kShortestAimedFrameSeconds.
constexpr double kFrameShareOfTimeLeft = 0.1;
constexpr double kFrameShareOfTimeToLimit = 0.9;
constexpr double kShortestAimedFrameSeconds = 0.05;

class SamplesPerFrame {
public:
    SamplesPerFrame(int initial, bool given, double targetFrameSeconds, int most = 16);
    int samples() const { return samples_; }
    // After a frame that added samples; `framesDrawn` counts it. `secondsLeft`: the predicted
    // time to the render's target error, where it aims at one and a prediction is made;
    // `secondsToLimit`: the time to the render's time limit, where it has one.
    void afterFrame(int framesDrawn, double lastSecondsPerSample,
                    std::optional<double> secondsLeft = std::nullopt,
                    std::optional<double> secondsToLimit = std::nullopt);

private:
    int samples_;
    bool given_;
    double targetFrameSeconds_;
    int most_;
};

// While the view changes the window shows one cheap sample per frame on a coarse grid
// (ProgressiveRenderer::renderPreview). The grid's divisor follows the time the last such
// frame took, drawing and showing included: one step coarser when it took longer than
// kSlowPreviewSeconds, one step finer when it took less than kFastPreviewSeconds, within 1
// to kMaxPreviewDivisor. The band between the two keeps it from flickering between sizes.
constexpr double kSlowPreviewSeconds = 0.07;
constexpr double kFastPreviewSeconds = 0.025;
constexpr int kMaxPreviewDivisor = 16;
int nextPreviewDivisor(int divisor, double lastPreviewFrameSeconds);

// The divisor for the first preview, before any was timed: the smallest whose grid takes
// at most kFirstPreviewSeconds at the cost of one full-resolution sample
// (`secondsPerFullSample`, with every bounce: a preview's fewer bounces only make it cheaper).
constexpr double kFirstPreviewSeconds = 0.04;
int firstPreviewDivisor(double secondsPerFullSample);

}  // namespace interaction
