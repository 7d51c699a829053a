// The guard before accumulation (shaders/modules/path_tracer_main.glsl): a sample that is
// NaN, infinite or negative is dropped and counted, never averaged into its pixel.
#include "hard/HardCaseSupport.h"

#include <gtest/gtest.h>

namespace {

// A white sphere light of radiance 3e38, near FLT_MAX = 3.4e38, hangs just above a white
// floor and fills the middle of the view. A camera ray that meets it carries 3e38 at once;
// its path then scatters off the light's own white surface onto the floor a hair below,
// where light sampling sees the sphere fill half the sky and adds about 1e38 more: the
// path's sum overflows to infinity in float arithmetic. (The light's power, 4 pi^2 r^2 L =
// 1.2e38, is computed in double for light selection, render/SceneUniforms.cpp: it would stay
// finite at any radius.)
TEST(DiscardedSamples, OverflowingSamplesAreCountedAndEveryPixelStaysFinite)
{
    hard::RenderRequest request;
    request.sceneText = R"(
environment none
0 0 1.2
0 0 0
0 1 0
40
0
1
solid 1 1 1
2
0 0 0  0 0 0 0
3e38 3e38 3e38  0 0 0 0
2
0 0 polyhedron 1  0 1 0 0.12
0 1 sphere 0 0 0 0.1
)";
    request.samplesPerPixel = 16;
    request.settings.samplesPerFrame = 16;
    const hard::RenderOutput output = hard::render(request);

    EXPECT_GT(output.discarded, 0u)
        << "paths summing more than 3.4e38 overflow to infinity; expected some samples "
           "discarded, none were";
    EXPECT_EQ(hard::nonFinitePixels(output.radiance), 0)
        << "a discarded sample must not reach its pixel";
    // Every path ends either in the pixel's mean or in its discard count.
    const io::Image& statistics = output.statistics;
    for (int y = 0; y < statistics.height; ++y)
        for (int x = 0; x < statistics.width; ++x)
            ASSERT_EQ(statistics.at(x, y, 0) + statistics.at(x, y, 1),
                      static_cast<float>(request.samplesPerPixel))
                << "pixel (" << x << ", " << y << "): " << statistics.at(x, y, 0)
                << " samples accumulated and " << statistics.at(x, y, 1)
                << " discarded; expected them to add up to the " << request.samplesPerPixel
                << " paths traced";
}

}  // namespace
