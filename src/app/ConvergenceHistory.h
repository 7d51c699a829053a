#pragma once
#include <cstddef>
#include <vector>

namespace app {

// The error estimate against time since the accumulation began, for the panel's plot: at
// most kCapacity points, about equally spaced in time so that the plot's horizontal axis is
// time. When it is full every other point is dropped and the spacing doubles, so the plot
// always spans the whole accumulation.
class ConvergenceHistory {
public:
    static constexpr std::size_t kCapacity = 128;
    static constexpr double kFirstSpacingSeconds = 0.5;

    void clear();
    // The estimate at `seconds` since the accumulation began; kept when it falls about one
    // spacing or more after the last point kept (5% early is still on time: the caller's
    // clock is a frame loop's, not a metronome).
    void add(double seconds, float relativeError);

    const std::vector<float>& errors() const { return errors_; }
    double spacingSeconds() const { return spacing_; }
    // The time of the last point kept (0 when there is none).
    double lastSeconds() const { return seconds_.empty() ? 0.0 : seconds_.back(); }

private:
    std::vector<float> errors_;
    std::vector<double> seconds_;
    double spacing_ = kFirstSpacingSeconds;
};

}  // namespace app
