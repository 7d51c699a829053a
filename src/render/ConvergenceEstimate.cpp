#include "render/ConvergenceEstimate.h"

#include <cmath>

namespace render {

std::optional<double> relativeRmsError(const io::Image& radiance, const io::Image& statistics)
{
    if (radiance.width != statistics.width || radiance.height != statistics.height ||
        radiance.channels < 3 || statistics.channels < 3 || radiance.width == 0 ||
        radiance.height == 0)
        return std::nullopt;
    double varianceSum = 0.0;
    double radianceSum = 0.0;
    long pixels = 0;
    for (int y = 0; y < radiance.height; ++y)
        for (int x = 0; x < radiance.width; ++x) {
            if (!(statistics.at(x, y, 0) >= 2.0f))
                continue;
            // The statistics hold the channel average already: the mean over channels.
            varianceSum += statistics.at(x, y, 2);
            radianceSum +=
                (radiance.at(x, y, 0) + radiance.at(x, y, 1) + radiance.at(x, y, 2)) / 3.0;
            ++pixels;
        }
    if (pixels == 0)
        return std::nullopt;
    const double meanRadiance = radianceSum / static_cast<double>(pixels);
    if (!(meanRadiance > 0.0))
        return std::nullopt;
    return std::sqrt(varianceSum / static_cast<double>(pixels)) / meanRadiance;
}

}  // namespace render
