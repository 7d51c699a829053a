// A renderer that starts from a saved accumulation (ProgressiveRenderer::resumeFrom) goes on
// with the next sample indices of every pixel: the same accumulation, bit for bit, as one
// render that never stopped, whatever the frames in between.
#include "render/ProgressiveRenderer.h"
#include "support/RenderRun.h"
#include "support/TestPaths.h"

#include <gtest/gtest.h>

namespace render_tests {
namespace {

using namespace testing_support;

scene::Scene classicScene()
{
    return loadScene(sourceDirectory() / "scenes" / "scene1.in");
}

void renderTo(render::ProgressiveRenderer& renderer, int samples, int perFrame)
{
    while (renderer.samplesPerPixel() < samples)
        renderer.renderFrame({}, std::min(perFrame, samples - renderer.samplesPerPixel()));
    renderer.completeSamples();
}

int differingValues(const io::Image& a, const io::Image& b)
{
    int differing = 0;
    for (std::size_t i = 0; i < a.pixels.size(); ++i)
        differing += a.pixels[i] != b.pixels[i] ? 1 : 0;
    return differing;
}

TEST(ResumedRenderer, GoesOnAsTheRenderThatNeverStopped)
{
    const settings::RenderSettings settings = settingsWithSeed(21);
    render::ProgressiveRenderer whole(classicScene(), 40, 30, settings);
    renderTo(whole, 12, 5);

    render::ProgressiveRenderer first(classicScene(), 40, 30, settings);
    renderTo(first, 5, 2);
    render::ProgressiveRenderer second(classicScene(), 40, 30, settings);
    second.resumeFrom(first.accumulation());
    EXPECT_EQ(second.samplesPerPixel(), 5);
    renderTo(second, 12, 3);

    const film::Accumulation expected = whole.accumulation();
    const film::Accumulation resumed = second.accumulation();
    EXPECT_EQ(differingValues(resumed.estimate, expected.estimate), 0)
        << "the means and counts must be those of the render that never stopped";
    EXPECT_EQ(differingValues(resumed.moments, expected.moments), 0)
        << "the second moments must be those of the render that never stopped";
}

TEST(ResumedRenderer, RefusesAnAccumulationOfAnotherSize)
{
    render::ProgressiveRenderer renderer(classicScene(), 16, 12, settingsWithSeed(1));
    EXPECT_THROW(renderer.resumeFrom(film::Accumulation(12, 16)), std::invalid_argument);
}

}  // namespace
}  // namespace render_tests
