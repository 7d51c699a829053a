#pragma once
#include <chrono>
#include <optional>
#include <string>

namespace app {

// The live progress line of a batch render, redrawn in place on a terminal (standard error)
// and silent otherwise, and the one summary line every render ends with.
class Progress {
public:
    Progress(int width, int height, std::optional<double> seconds,
             std::optional<int> samplesPerPixel, bool enabled);

    // After each frame.
    void update(int samplesPerPixel);
    // Clears the live line.
    void finish();
    double elapsedSeconds() const;

    // "1280x720, 64 spp in 12.41 s: 4.75 Mpaths/s, 0 samples discarded"
    static std::string summary(int width, int height, int samplesPerPixel, double seconds,
                               unsigned long long discarded);

private:
    int width_;
    int height_;
    std::optional<double> seconds_;
    std::optional<int> samplesPerPixel_;
    bool enabled_;
    std::chrono::steady_clock::time_point start_;
    bool drawn_ = false;
};

}  // namespace app
