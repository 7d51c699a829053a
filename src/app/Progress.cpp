#include "app/Progress.h"

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <sys/ioctl.h>
#include <unistd.h>

namespace app {

Progress::Progress(int width, int height, std::optional<double> seconds,
                   std::optional<int> samplesPerPixel, bool enabled, int samplesAtStart)
    : width_(width),
      height_(height),
      seconds_(seconds),
      samplesPerPixel_(samplesPerPixel),
      enabled_(enabled && ::isatty(STDERR_FILENO)),
      samplesAtStart_(samplesAtStart),
      start_(std::chrono::steady_clock::now())
{
}

double Progress::elapsedSeconds() const
{
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}

namespace {

// The terminal's width in columns, or 0 where it does not say.
int terminalColumns()
{
    winsize size{};
    if (::ioctl(STDERR_FILENO, TIOCGWINSZ, &size) != 0)
        return 0;
    return size.ws_col;
}

// The widest form of the line that fits `columns` (less one: writing the last column makes
// some terminals wrap); the short form where the width is unknown. Nothing is wider than the
// terminal, so each redraw overwrites the last instead of leaving a trail of cut lines.
std::string progressLine(int samples, double rate, double elapsed, double remaining,
                         const std::string& aim, int columns)
{
    char forms[4][240];
    const bool ends = remaining >= 0.0;
    if (!aim.empty()) {
        std::snprintf(forms[0], sizeof forms[0], "%6d spp  %7.2f spp/s  %7.1f s elapsed  %s",
                      samples, rate, elapsed, aim.c_str());
        std::snprintf(forms[1], sizeof forms[1], "%d spp  %.0f s  %s", samples, elapsed,
                      aim.c_str());
        std::snprintf(forms[2], sizeof forms[2], "%s", aim.c_str());
    } else if (ends)
        std::snprintf(forms[0], sizeof forms[0],
                      "%6d spp  %7.2f spp/s  %7.1f s elapsed  %7.1f s left", samples, rate, elapsed,
                      remaining);
    else
        std::snprintf(forms[0], sizeof forms[0], "%6d spp  %7.2f spp/s  %7.1f s elapsed", samples,
                      rate, elapsed);
    if (aim.empty()) {
        std::snprintf(forms[1], sizeof forms[1],
                      ends ? "%d spp  %.2f spp/s  %.0f s left" : "%d spp  %.2f spp/s  %.0f s",
                      samples, rate, ends ? remaining : elapsed);
        std::snprintf(forms[2], sizeof forms[2], ends ? "%d spp, %.0f s left" : "%d spp, %.0f s",
                      samples, ends ? remaining : elapsed);
    }
    std::snprintf(forms[3], sizeof forms[3], "%d spp", samples);
    if (columns <= 0)
        return forms[2];
    const std::size_t room = static_cast<std::size_t>(columns - 1);
    for (const char* form : forms)
        if (std::strlen(form) <= room)
            return form;
    return std::string(forms[3]).substr(0, room);
}

}  // namespace

void Progress::update(int samples, const std::string& aim)
{
    if (!enabled_)
        return;
    const double elapsed = elapsedSeconds();
    const double rate = elapsed > 0.0 ? (samples - samplesAtStart_) / elapsed : 0.0;
    double remaining = -1.0;
    if (seconds_)
        remaining = std::max(0.0, *seconds_ - elapsed);
    if (samplesPerPixel_ && rate > 0.0) {
        const double bySamples = (*samplesPerPixel_ - samples) / rate;
        remaining = remaining < 0.0 ? bySamples : std::min(remaining, bySamples);
    }
    // Asked every time: the terminal may have been resized.
    const std::string line =
        progressLine(samples, rate, elapsed, remaining, aim, terminalColumns());
    std::fputs(("\r" + line + "\033[K").c_str(), stderr);
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
                              unsigned long long discarded, int samplesResumed)
{
    const double paths = static_cast<double>(width) * height * (samples - samplesResumed);
    const double megapathsPerSecond = seconds > 0.0 ? paths / seconds / 1e6 : 0.0;
    char resumed[80] = "";
    if (samplesResumed > 0)
        std::snprintf(resumed, sizeof resumed, " (%d resumed, %d new)", samplesResumed,
                      samples - samplesResumed);
    char line[240];
    std::snprintf(line, sizeof line,
                  "%dx%d, %d spp%s in %.2f s: %.3f Mpaths/s, %llu samples discarded", width, height,
                  samples, resumed, seconds, megapathsPerSecond, discarded);
    return line;
}

std::string Progress::adaptiveSummary(int width, int height, film::SampleCountSpan span,
                                      double samplesInAll, double seconds,
                                      unsigned long long discarded)
{
    const double pixels = std::max(1.0, static_cast<double>(width) * height);
    const double megapathsPerSecond = seconds > 0.0 ? samplesInAll / seconds / 1e6 : 0.0;
    char line[240];
    std::snprintf(line, sizeof line,
                  "%dx%d, %.1f spp on average (%d-%d) in %.2f s: %.3f Mpaths/s, %llu samples "
                  "discarded",
                  width, height, samplesInAll / pixels, span.fewest, span.most, seconds,
                  megapathsPerSecond, discarded);
    return line;
}

}  // namespace app
