#pragma once
#include "film/AdaptiveSampling.h"
#include "film/ConvergenceEstimate.h"
#include "interaction/ConvergenceHistory.h"
#include "render/ProgressiveRenderer.h"

#include <optional>
#include <string>
#include <vector>

namespace app {

// A render aimed at an error (--target-error): after every frame it estimates the error
// reached (film/ConvergenceEstimate.h), sends the next samples where the error is
// (film/AdaptiveSampling.h; unless sampling uniformly) and predicts the time still needed.
class ErrorTargetRun {
public:
    ErrorTargetRun(const film::AdaptiveSampling& sampling, bool adaptive);

    // Before the first frame: every pixel's first aim is the minimum.
    void start(render::ProgressiveRenderer& renderer);
    // After each frame, `elapsedSeconds` into the render.
    void afterFrame(render::ProgressiveRenderer& renderer, double elapsedSeconds);

    // After the last frame, for the summary: the estimate of what the render holds (a window
    // renders without afterFrame).
    void conclude(const render::ProgressiveRenderer& renderer);

    // Every pixel holds the minimum and the estimate, two standard deviations up, is at most
    // the target.
    bool reached() const { return reached_; }
    // Adaptive sampling with a sample limit (--spp) has no pixel left to sample: every one
    // holds the limit, or its tile's share.
    bool limitReached() const { return limitReached_; }
    const std::optional<film::ErrorEstimate>& estimate() const { return estimate_; }
    // Seconds still needed, from the trend of the estimate so far (interaction::ConvergenceHistory);
    // nothing before every pixel holds the minimum.
    std::optional<double> predictedSecondsLeft() const { return predictedSecondsLeft_; }
    bool adaptive() const { return adaptive_; }
    // The most samples the last frame added to one pixel. Under adaptive sampling a frame
    // asked for N samples lasts as long as its busiest pixels take theirs, which stop at
    // their shares: N alone overstates what the frame did and understates a sample's cost.
    float mostSamplesAddedToAPixel() const { return mostSamplesAdded_; }
    const film::AdaptiveSampling& sampling() const { return sampling_; }

    // "error 2.31 % (target 1 %), about 14 s left", for the progress line.
    std::string progressText() const;
    // "error 0.98 % +- 0.02 % (target 1 %, adaptive sampling: reached)", for the summary;
    // `stop` says what ended the render otherwise ("stopped at the time limit before it").
    std::string summaryText(const std::string& stop) const;

private:
    bool judge(const film::Accumulation& accumulation);
    void noteSamplesAdded(const film::Accumulation& accumulation);

    film::AdaptiveSampling sampling_;
    bool adaptive_;
    std::optional<film::ErrorEstimate> estimate_;
    std::optional<double> predictedSecondsLeft_;
    interaction::ConvergenceHistory history_;
    bool reached_ = false;
    bool limitReached_ = false;
    std::vector<float> samplesTakenBefore_;  // each pixel's, row by row, after the last frame
    float mostSamplesAdded_ = 0.0f;
};

}  // namespace app
