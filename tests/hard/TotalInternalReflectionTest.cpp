// Total internal reflection: where it must happen, and glass touching other things.
#include "hard/HardCaseSupport.h"

#include <gtest/gtest.h>

namespace {

// Camera at the centre of a sphere of index 2.4 (diamond) in a furnace: every ray meets the
// surface head-on, leaves, and carries n^2. From off-centre, steep rays are trapped by total
// internal reflection (a sphere keeps the angle of incidence) and never leave: the image
// must then be darker where rays are steep, and still finite and never above n^2.
TEST(TotalInternalReflection, SteepRaysInsideDiamondSphereAreTrappedAndNothingBlowsUp)
{
    hard::RenderRequest request;
    request.sceneText = R"(
environment 1 1 1
0.9 0 0
-1 0 0
0 1 0
90
0
1
solid 1 1 1
1
0 0 0 0 0 1 2.4
1
0 0 sphere 0 0 0 1
)";
    request.samplesPerPixel = 32;
    request.settings.samplesPerFrame = 32;
    const hard::RenderOutput output = hard::render(request);
    const double nSquared = 2.4 * 2.4;
    EXPECT_EQ(hard::nonFinitePixels(output.radiance), 0);
    EXPECT_EQ(output.discarded, 0u);
    EXPECT_LE(hard::maxRadiance(output.radiance), nSquared * (1.0 + 1e-5));
    // The centre pixel looks through the sphere's centre: head-on, it escapes.
    const io::Image& image = output.radiance;
    EXPECT_GT(image.at(image.width / 2, image.height / 2, 0), 0.8 * nSquared);
    // The edge of a 90-degree view from 0.9 off-centre meets the surface beyond the critical
    // angle (asin(1 / 2.4) = 24.6 degrees): trapped light never reaches the camera.
    EXPECT_LT(image.at(0, image.height / 2, 0), 0.2 * nSquared);
}

TEST(TotalInternalReflection, GlassSphereRestingOnFloorAndTwoTouchingGlassSpheresRenderFinite)
{
    hard::RenderRequest request;
    request.sceneText = R"(
environment sky
0 1.5 6
0 1 0
0 1 0
45
1
3 6 4  60 60 60
2
checker 0.9 0.9 0.9  0.2 0.2 0.2  0.5
solid 1 1 1
2
0 0 0 0 0 0 0
0 0 0 0 0 1 1.5
3
0 0 polyhedron 1 0 1 0 0
1 1 sphere -1 1 0 1
1 1 sphere 1 1 0 1
)";
    request.samplesPerPixel = 32;
    request.settings.samplesPerFrame = 32;
    const hard::RenderOutput output = hard::render(request);
    EXPECT_EQ(hard::nonFinitePixels(output.radiance), 0);
    EXPECT_EQ(output.discarded, 0u);
    EXPECT_GT(hard::meanRadiance(output.radiance), 0.01);
}

}  // namespace
