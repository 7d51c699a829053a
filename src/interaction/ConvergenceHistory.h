#pragma once
#include <cstddef>
#include <optional>
#include <vector>

namespace interaction {

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

    // Seconds from `nowSeconds` until the error, `errorNow` at present, falls to `target`
    // (0 when it is there), from the trend of the points kept in the latter half of the time
    // so far: error ~ seconds^-a, a fitted by least squares on log-log axes. Uniform sampling
    // gives a = 1/2 (the error falls as 1 / sqrt(samples)); adaptive sampling a steeper one
    // as the image's easy parts stop. Until three such points span 1.4x in time, a = 1/2.
    // Nothing when the error is not positive or nowSeconds is 0.
    std::optional<double> secondsLeftToReach(double target, double nowSeconds,
                                             double errorNow) const;

    const std::vector<float>& errors() const { return errors_; }
    double spacingSeconds() const { return spacing_; }
    // The time of the last point kept (0 when there is none).
    double lastSeconds() const { return seconds_.empty() ? 0.0 : seconds_.back(); }

private:
    std::vector<float> errors_;
    std::vector<double> seconds_;
    double spacing_ = kFirstSpacingSeconds;
};

}  // namespace interaction
