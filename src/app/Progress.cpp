#include "app/Progress.h"

#include <algorithm>
#include <cstdio>
#include <unistd.h>

namespace app {

Progress::Progress(int width, int height, std::optional<double> seconds,
                   std::optional<int> samplesPerPixel, bool enabled)
    : width_(width),
      height_(height),
      seconds_(seconds),
      samplesPerPixel_(samplesPerPixel),
      enabled_(enabled && ::isatty(STDERR_FILENO)),
      start_(std::chrono::steady_clock::now())
{
}

double Progress::elapsedSeconds() const
{
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}

void Progress::update(int samples)
{
    if (!enabled_)
        return;
    const double elapsed = elapsedSeconds();
    const double rate = elapsed > 0.0 ? samples / elapsed : 0.0;
    double remaining = -1.0;
    if (seconds_)
        remaining = std::max(0.0, *seconds_ - elapsed);
    if (samplesPerPixel_ && rate > 0.0) {
        const double bySamples = (*samplesPerPixel_ - samples) / rate;
        remaining = remaining < 0.0 ? bySamples : std::min(remaining, bySamples);
    }
    char line[160];
    if (remaining >= 0.0)
        std::snprintf(line, sizeof line, "\r%6d spp  %7.2f spp/s  %7.1f s elapsed  %7.1f s left ",
                      samples, rate, elapsed, remaining);
    else
        std::snprintf(line, sizeof line, "\r%6d spp  %7.2f spp/s  %7.1f s elapsed ", samples,
                      rate, elapsed);
    std::fputs(line, stderr);
    std::fflush(stderr);
    drawn_ = true;
}

void Progress::finish()
{
    if (drawn_) {
        std::fputs("\r\033[K", stderr);
        std::fflush(stderr);
        drawn_ = false;
    }
}

std::string Progress::summary(int width, int height, int samples, double seconds,
                              unsigned long long discarded)
{
    const double paths = static_cast<double>(width) * height * samples;
    const double megapathsPerSecond = seconds > 0.0 ? paths / seconds / 1e6 : 0.0;
    char line[200];
    std::snprintf(line, sizeof line,
                  "%dx%d, %d spp in %.2f s: %.3f Mpaths/s, %llu samples discarded", width,
                  height, samples, seconds, megapathsPerSecond, discarded);
    return line;
}

}  // namespace app
