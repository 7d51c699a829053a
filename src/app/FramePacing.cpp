#include "app/FramePacing.h"

#include <algorithm>

namespace app {

int samplesPerFrameFor(double targetFrameSeconds, double secondsPerSample, int most)
{
    if (!(secondsPerSample > 0.0))
        return most;  // too fast to measure
    const double samples = std::min(targetFrameSeconds / secondsPerSample, static_cast<double>(most));
    return std::max(1, static_cast<int>(samples));
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

}  // namespace app
