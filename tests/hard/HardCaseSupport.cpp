#include "hard/HardCaseSupport.h"

#include "platform/OsMesaContext.h"
#include "render/ProgressiveRenderer.h"
#include "scene/FileLookup.h"
#include "scene/SceneParser.h"
#include "shadergen/ShaderSource.h"

#include <cmath>
#include <memory>
#include <sstream>

namespace hard {

namespace {

platform::OsMesaContext& context()
{
    // One context for the test process, made when the first render needs it.
    static platform::OsMesaContext instance;
    return instance;
}

}  // namespace

RenderOutput render(const RenderRequest& request)
{
    context();
    const scene::FileLookup lookup(HARD_CASES_DIR, scene::FileLookup::dataDirectory());
    const scene::Scene scene = scene::parseSceneText(request.sceneText, "hard-case.in", lookup);
    render::ProgressiveRenderer renderer(scene, request.width, request.height, request.settings);
    while (renderer.samplesPerPixel() < request.samplesPerPixel)
        renderer.renderFrame({}, std::min(request.settings.samplesPerFrame,
                                          request.samplesPerPixel - renderer.samplesPerPixel()));
    renderer.completeSamples();
    RenderOutput output;
    output.radiance = renderer.radiance();
    output.statistics = renderer.sampleStatistics();
    output.discarded = renderer.discardedSamples();
    return output;
}

std::string sceneFile(const std::string& name)
{
    return shadergen::readTextFile(std::string(HARD_CASES_DIR) + "/scenes/" + name);
}

int nonFinitePixels(const io::Image& image)
{
    int count = 0;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            bool finite = true;
            for (int c = 0; c < image.channels; ++c)
                finite = finite && std::isfinite(image.at(x, y, c));
            count += finite ? 0 : 1;
        }
    return count;
}

double meanRadiance(const io::Image& image)
{
    double sum = 0.0;
    for (float value : image.pixels)
        sum += value;
    return sum / static_cast<double>(image.pixels.size());
}

double maxRadiance(const io::Image& image)
{
    double largest = 0.0;
    for (float value : image.pixels)
        largest = std::max(largest, static_cast<double>(value));
    return largest;
}

testing_support::RenderedImage renderedImage(const RenderOutput& output)
{
    testing_support::RenderedImage image;
    image.radiance = output.radiance;
    image.statistics = output.statistics;
    image.discardedSamples = output.discarded;
    return image;
}

double normalUpperQuantile(double p)
{
    // Bisection on the complementary error function: exact enough for test thresholds.
    double low = 0.0;
    double high = 40.0;
    for (int i = 0; i < 200; ++i) {
        const double middle = 0.5 * (low + high);
        if (0.5 * std::erfc(middle / std::sqrt(2.0)) > p)
            low = middle;
        else
            high = middle;
    }
    return 0.5 * (low + high);
}

std::string disagreementWithinNoise(const RenderOutput& a, const RenderOutput& b, int blockSize)
{
    const int width = a.radiance.width;
    const int height = a.radiance.height;
    const int blocksX = width / blockSize;
    const int blocksY = height / blockSize;
    const int blocks = blocksX * blocksY;
    const double threshold = normalUpperQuantile(1e-3 / (2.0 * blocks));
    double worst = 0.0;
    int worstX = 0;
    int worstY = 0;
    for (int by = 0; by < blocksY; ++by)
        for (int bx = 0; bx < blocksX; ++bx) {
            double meanA = 0.0, meanB = 0.0, varianceA = 0.0, varianceB = 0.0;
            for (int y = by * blockSize; y < (by + 1) * blockSize; ++y)
                for (int x = bx * blockSize; x < (bx + 1) * blockSize; ++x) {
                    for (int c = 0; c < 3; ++c) {
                        meanA += a.radiance.at(x, y, c) / 3.0;
                        meanB += b.radiance.at(x, y, c) / 3.0;
                    }
                    varianceA += a.statistics.at(x, y, 2);
                    varianceB += b.statistics.at(x, y, 2);
                }
            const double n = static_cast<double>(blockSize) * blockSize;
            // Blocks of a constant value have no variance; a tiny floor keeps z finite and
            // still demands agreement to float precision there.
            const double standardError =
                std::sqrt((varianceA + varianceB) / (n * n)) + 1e-6 * std::abs(meanA / n);
            const double z = std::abs(meanA - meanB) / n / std::max(standardError, 1e-12);
            if (z > worst) {
                worst = z;
                worstX = bx;
                worstY = by;
            }
        }
    if (worst <= threshold)
        return {};
    std::ostringstream message;
    message << "block (" << worstX << ", " << worstY << ") of " << blockSize << "x" << blockSize
            << " pixels differs by " << worst << " standard errors; at most " << threshold
            << " expected from noise alone over " << blocks << " blocks";
    return message.str();
}

}  // namespace hard
