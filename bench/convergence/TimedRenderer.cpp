#include "convergence/TimedRenderer.h"

#include <algorithm>
#include <ctime>

#include <time.h>  // clock_gettime, CLOCK_PROCESS_CPUTIME_ID (POSIX)

namespace convergence {

// CPU time of the whole process, llvmpipe's rendering threads included. Wall time is what a
// user waits; CPU time is the work, and on a machine shared with other jobs it varies far
// less than wall time does.
double processCpuSeconds()
{
    timespec now{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &now);
    return static_cast<double>(now.tv_sec) + 1e-9 * static_cast<double>(now.tv_nsec);
}

double secondsSince(std::chrono::steady_clock::time_point start)
{
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// Paths per pixel in one draw: one at 320x240 and above, more at small sizes, where the
// per-frame cost of the host (binding, band timing, glFinish) would otherwise be measured too.
int defaultSamplesPerFrame(int width, int height)
{
    const int pixelsPerDraw = 320 * 240;
    return std::clamp(pixelsPerDraw / std::max(1, width * height), 1, 64);
}

}  // namespace convergence
