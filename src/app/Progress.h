#pragma once
#include "film/Accumulation.h"

#include <chrono>
#include <optional>
#include <string>

namespace app {

// The live progress line of a batch render, redrawn in place on a terminal (standard error)
// and silent otherwise, and the one summary line every render ends with.
class Progress {
public:
    // `samplesAtStart`: what a resumed render holds already (the rate counts new samples).
    Progress(int width, int height, std::optional<double> seconds,
             std::optional<int> samplesPerPixel, bool enabled, int samplesAtStart = 0);

    // After each frame; `aim` (a render to a target error's estimate and prediction) takes
    // the place of the time left.
    void update(int samplesPerPixel, const std::string& aim = {});
    // Clears the live line.
    void finish();
    double elapsedSeconds() const;

    // "1280x720, 64 spp in 12.41 s: 4.75 Mpaths/s, 0 samples discarded"; resumed from 16:
    // "1280x720, 64 spp (16 resumed, 48 new) in 12.41 s: ..." with the rate of the new ones.
    static std::string summary(int width, int height, int samplesPerPixel, double seconds,
                               unsigned long long discarded, int samplesResumed = 0);
    // Where pixels hold different counts (adaptive sampling): "160x120, 87.4 spp on average
    // (32-1024) in 5.02 s: 0.334 Mpaths/s, 0 samples discarded".
    static std::string adaptiveSummary(int width, int height, film::SampleCountSpan span,
                                       double samplesInAll, double seconds,
                                       unsigned long long discarded);

private:
    int width_;
    int height_;
    std::optional<double> seconds_;
    std::optional<int> samplesPerPixel_;
    bool enabled_;
    int samplesAtStart_;
    std::chrono::steady_clock::time_point start_;
    bool drawn_ = false;
};

}  // namespace app
