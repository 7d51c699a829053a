#include "interaction/FramePacing.h"

#include <algorithm>

namespace interaction {

int samplesPerFrameFor(double targetFrameSeconds, double secondsPerSample, int most)
{
    if (!(secondsPerSample > 0.0))
        return most;  // too fast to measure
    const double samples =
        std::min(targetFrameSeconds / secondsPerSample, static_cast<double>(most));
    return std::max(1, static_cast<int>(samples));
}

SamplesPerFrame::SamplesPerFrame(int initial, bool given, double targetFrameSeconds, int most)
    : samples_(initial), given_(given), targetFrameSeconds_(targetFrameSeconds), most_(most)
{
}

void SamplesPerFrame::afterFrame(int framesDrawn, double lastSecondsPerSample,
                                 std::optional<double> secondsLeft,
                                 std::optional<double> secondsToLimit)
{
    if (given_ || framesDrawn < 1)
        return;
    double frameSeconds = targetFrameSeconds_;
    auto atMostShareOf = [&frameSeconds](double share, std::optional<double> seconds) {
        if (seconds)
            frameSeconds =
                std::min(frameSeconds, std::max(kShortestAimedFrameSeconds, share * *seconds));
    };
    atMostShareOf(kFrameShareOfTimeLeft, secondsLeft);
    atMostShareOf(kFrameShareOfTimeToLimit, secondsToLimit);
    samples_ = samplesPerFrameFor(frameSeconds, lastSecondsPerSample, most_);
}

int nextPreviewDivisor(int divisor, double lastPreviewFrameSeconds)
{
    if (lastPreviewFrameSeconds > kSlowPreviewSeconds)
        ++divisor;
    else if (lastPreviewFrameSeconds < kFastPreviewSeconds)
        --divisor;
    return std::clamp(divisor, 1, kMaxPreviewDivisor);
}

int firstPreviewDivisor(double secondsPerFullSample)
{
    int divisor = 1;
    while (divisor < kMaxPreviewDivisor &&
           secondsPerFullSample / (static_cast<double>(divisor) * divisor) > kFirstPreviewSeconds)
        ++divisor;
    return divisor;
}

}  // namespace interaction
