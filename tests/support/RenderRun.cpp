#include "support/RenderRun.h"

#include "render/ProgressiveRenderer.h"
#include "scene/FileLookup.h"
#include "scene/SceneParser.h"
#include "support/TestPaths.h"

#include <algorithm>

namespace testing_support {

scene::Scene loadScene(const std::filesystem::path& path)
{
    return scene::parseSceneFile(path);
}

scene::Scene sceneFromText(const std::string& text, const std::string& name)
{
    const scene::FileLookup lookup(testScenesDirectory(), scene::FileLookup::dataDirectory());
    return scene::parseSceneText(text, name, lookup);
}

settings::RenderSettings settingsWithSeed(std::uint64_t seed)
{
    settings::RenderSettings settings;
    settings.seed = seed;
    return settings;
}

RenderedImage renderScene(const scene::Scene& scene, int width, int height, int samplesPerPixel,
                          const settings::RenderSettings& settings)
{
    render::ProgressiveRenderer renderer(scene, width, height, settings);
    // Several paths per pixel in one draw cost less than as many draws, and give the same
    // estimate (the running mean is updated after each path).
    constexpr int kSamplesPerDraw = 8;
    while (renderer.samplesPerPixel() < samplesPerPixel)
        renderer.renderFrame(
            {}, std::min(kSamplesPerDraw, samplesPerPixel - renderer.samplesPerPixel()));
    renderer.completeSamples();
    RenderedImage image;
    image.radiance = renderer.radiance();
    image.statistics = renderer.sampleStatistics();
    image.discardedSamples = renderer.discardedSamples();
    image.accumulation = renderer.accumulation();
    return image;
}

float channelMean(const io::Image& image, int x, int y)
{
    return (image.at(x, y, 0) + image.at(x, y, 1) + image.at(x, y, 2)) / 3.0f;
}

}  // namespace testing_support
