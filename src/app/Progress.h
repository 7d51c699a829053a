#pragma once
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

    // After each frame.
    void update(int samplesPerPixel);
    // Clears the live line.
    void finish();
    double elapsedSeconds() const;

    // "1280x720, 64 spp in 12.41 s: 4.75 Mpaths/s, 0 samples discarded"; resumed from 16:
    // "1280x720, 64 spp (16 resumed, 48 new) in 12.41 s: ..." with the rate of the new ones.
    static std::string summary(int width, int height, int samplesPerPixel, double seconds,
                               unsigned long long discarded, int samplesResumed = 0);

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
