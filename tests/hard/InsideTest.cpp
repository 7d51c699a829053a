// Cameras inside things: a glass sphere, a diffuse sphere, a room's corner.
#include "hard/HardCaseSupport.h"

#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

namespace {

std::string cameraInsideGlass(double ior)
{
    std::ostringstream text;
    text << "environment 1 1 1\n0 0 0.2\n0 0 -1\n0 1 0\n60\n0\n1\nsolid 1 1 1\n1\n"
         << "0 0 0 0 0 1 " << ior << "\n1\n0 0 sphere 0 0 0 1\n";
    return text.str();
}

// Radiance is n^2 times larger inside a medium of index n (it is L / n^2 that is conserved
// across a refraction). Every path from a camera inside a clear glass sphere in a furnace of
// radiance 1 leaves through the surface exactly once more than it enters, so it carries n^2.
TEST(Inside, CameraInsideGlassSphereInFurnaceSeesIndexSquared)
{
    hard::RenderRequest request;
    request.sceneText = cameraInsideGlass(1.5);
    request.samplesPerPixel = 32;
    request.settings.samplesPerFrame = 32;
    const hard::RenderOutput output = hard::render(request);
    EXPECT_EQ(output.discarded, 0u);
    // Paths trapped by total internal reflection for all 16 bounces are lost: a tiny deficit.
    EXPECT_NEAR(hard::meanRadiance(output.radiance), 2.25, 2.25 * 2e-3);
    EXPECT_LE(hard::maxRadiance(output.radiance), 2.25 * (1.0 + 1e-5));
}

// An integrating sphere: a point light of intensity I at the centre of a diffuse sphere of
// radius R and albedo rho. Direct irradiance is I / R^2 everywhere and every wall point sees
// the same, so the radiance of the walls is rho / pi * (I / R^2) / (1 - rho).
TEST(Inside, CameraInsideDiffuseSphereMatchesIntegratingSphere)
{
    hard::RenderRequest request;
    request.sceneText = R"(
environment sky
0 0 0.3
0 0 -1
0 1 0
70
1
0 0 0  2 2 2
1
solid 0.5 0.5 0.5
1
0 0 0 0 0 0 0
1
0 0 sphere 0 0 0 2
)";
    request.samplesPerPixel = 256;
    request.settings.samplesPerFrame = 64;
    request.settings.maxBounces = 32;  // rho^32: the truncated tail is below 1e-9
    const hard::RenderOutput output = hard::render(request);
    const double expected = 0.5 / M_PI * (2.0 / 4.0) / (1.0 - 0.5);
    EXPECT_EQ(output.discarded, 0u);
    EXPECT_NEAR(hard::meanRadiance(output.radiance), expected, expected * 5e-3);
}

TEST(Inside, CameraInRoomCornerRendersFinite)
{
    hard::RenderRequest request;
    request.sceneText = R"(
0.999 0.999 0.999
0 0 0
0 1 0
90
1
0 0 0  5 5 5
1
solid 0.7 0.7 0.7
1
0 0 0 0 0 0 0
1
0 0 polyhedron 6  1 0 0 1  -1 0 0 1  0 1 0 1  0 -1 0 1  0 0 1 1  0 0 -1 1
)";
    request.samplesPerPixel = 16;
    request.settings.samplesPerFrame = 16;
    const hard::RenderOutput output = hard::render(request);
    EXPECT_EQ(hard::nonFinitePixels(output.radiance), 0);
    EXPECT_EQ(output.discarded, 0u);
    EXPECT_GT(hard::meanRadiance(output.radiance), 0.0);
}

}  // namespace
