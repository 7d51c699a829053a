// Lights at the edges of their range: tiny far spheres, huge radiance, lights touching or
// inside geometry, no light at all.
#include "hard/HardCaseSupport.h"

#include <gtest/gtest.h>

#include <sstream>

namespace {

std::string floorUnder(const std::string& lights, const std::string& extraFinishes = "",
                       const std::string& extraObjects = "", int objects = 1, int finishes = 1,
                       int pigments = 1, const std::string& extraPigments = "")
{
    std::ostringstream text;
    text << "environment none\n0 5 5\n0 0 0\n0 1 0\n45\n"
         << lights << pigments << "\nsolid 0.5 0.5 0.5\n"
         << extraPigments << finishes << "\n0 0 0 0 0 0 0\n"
         << extraFinishes << objects << "\n0 0 polyhedron 1 0 1 0 0\n"
         << extraObjects;
    return text.str();
}

// A sphere light of radius r and radiance L far away is a point light of intensity
// L pi r^2 (its irradiance is exactly that of the point for any point that sees all of it).
// Radius 1e-4 at distance 100 makes 1 - cos(thetaMax) = 5e-13: only a cone computed without
// cancellation keeps it.
TEST(Lights, TinyDistantSphereLightMatchesEquivalentPointLight)
{
    const double radius = 1e-4;
    const double radiance = 1e12;
    const double intensity = radiance * M_PI * radius * radius;
    std::ostringstream pointLight;
    pointLight << "1\n0 100 0 " << intensity << " " << intensity << " " << intensity << "\n";
    hard::RenderRequest point;
    point.sceneText = floorUnder(pointLight.str());
    point.samplesPerPixel = 16;
    point.settings.samplesPerFrame = 16;
    point.settings.seed = 1;

    std::ostringstream sphereFinish;
    sphereFinish << radiance << " " << radiance << " " << radiance << " 0 0 0 0\n";
    std::ostringstream sphereObject;
    sphereObject << "1 1 sphere 0 100 0 " << radius << "\n";
    hard::RenderRequest sphere = point;
    sphere.sceneText =
        floorUnder("0\n", sphereFinish.str(), sphereObject.str(), 2, 2, 2, "solid 0 0 0\n");
    sphere.settings.seed = 2;

    const hard::RenderOutput pointOutput = hard::render(point);
    const hard::RenderOutput sphereOutput = hard::render(sphere);
    EXPECT_EQ(hard::nonFinitePixels(sphereOutput.radiance), 0);
    EXPECT_EQ(sphereOutput.discarded, 0u);
    EXPECT_NEAR(hard::meanRadiance(sphereOutput.radiance), hard::meanRadiance(pointOutput.radiance),
                1e-3 * hard::meanRadiance(pointOutput.radiance));
}

// A light is selected in proportion to its power 4 pi^2 r^2 L, which for radiance near the
// float maximum on a sphere of radius 0.5 is far beyond it: computed in float it overflowed,
// every selection probability became NaN, light sampling never chose the light and every
// path that met it was discarded (a black floor). Radiance is linear: ten times the
// radiance is ten times the image.
TEST(Lights, RadianceNearTheFloatMaximumOnALargeSphereIsStillSampled)
{
    auto floorUnderLight = [](const char* radiance) {
        return floorUnder("0\n",
                          std::string(radiance) + " " + radiance + " " + radiance + " 0 0 0 0\n",
                          "1 1 sphere 0 2 0 0.5\n", 2, 2, 2, "solid 0 0 0\n");
    };
    hard::RenderRequest dimmer;
    dimmer.sceneText = floorUnderLight("1e37");
    dimmer.samplesPerPixel = 64;
    dimmer.settings.seed = 1;
    hard::RenderRequest brighter = dimmer;
    brighter.sceneText = floorUnderLight("1e38");
    brighter.settings.seed = 2;

    const hard::RenderOutput dimmerOutput = hard::render(dimmer);
    const hard::RenderOutput brighterOutput = hard::render(brighter);
    EXPECT_EQ(hard::nonFinitePixels(brighterOutput.radiance), 0);
    EXPECT_EQ(brighterOutput.discarded, 0u) << "paths meeting the light were discarded";
    const double expected = 10.0 * hard::meanRadiance(dimmerOutput.radiance);
    EXPECT_NEAR(hard::meanRadiance(brighterOutput.radiance), expected, 0.02 * expected)
        << "radiance 1e38 should light the floor ten times as brightly as 1e37";
}

TEST(Lights, MillionRadianceOnTinySphereStaysFinite)
{
    hard::RenderRequest request;
    request.sceneText = floorUnder("0\n", "1e6 1e6 1e6 0 0 0 0\n", "1 1 sphere 0 0.5 0 0.001\n", 2,
                                   2, 2, "solid 0 0 0\n");
    request.samplesPerPixel = 32;
    request.settings.samplesPerFrame = 32;
    const hard::RenderOutput output = hard::render(request);
    EXPECT_EQ(hard::nonFinitePixels(output.radiance), 0);
    EXPECT_EQ(output.discarded, 0u);
    EXPECT_GT(hard::meanRadiance(output.radiance), 0.0);
}

TEST(Lights, PointLightOnTheSurfaceItLightsStaysFinite)
{
    hard::RenderRequest request;
    request.sceneText = floorUnder("1\n0 0 0  10 10 10\n");
    request.samplesPerPixel = 16;
    request.settings.samplesPerFrame = 16;
    const hard::RenderOutput output = hard::render(request);
    EXPECT_EQ(hard::nonFinitePixels(output.radiance), 0);
    EXPECT_EQ(output.discarded, 0u);
}

TEST(Lights, PointLightInsideAnObjectLightsNothingOutside)
{
    hard::RenderRequest request;
    request.sceneText = floorUnder("1\n0 1 0  10 10 10\n", "", "0 0 sphere 0 1 0 0.5\n", 2);
    request.samplesPerPixel = 16;
    request.settings.samplesPerFrame = 16;
    const hard::RenderOutput output = hard::render(request);
    EXPECT_EQ(hard::nonFinitePixels(output.radiance), 0);
    EXPECT_EQ(output.discarded, 0u);
    EXPECT_EQ(hard::maxRadiance(output.radiance), 0.0);
}

TEST(Lights, ClosedRoomWithoutLightIsBlackAndFinite)
{
    hard::RenderRequest request;
    request.sceneText = R"(
environment sky
0 0 0
0 0 -1
0 1 0
60
0
1
solid 0.8 0.8 0.8
1
0 0 0 0 0 0 0
1
0 0 polyhedron 6  1 0 0 2  -1 0 0 2  0 1 0 2  0 -1 0 2  0 0 1 2  0 0 -1 2
)";
    request.samplesPerPixel = 16;
    request.settings.samplesPerFrame = 16;
    const hard::RenderOutput output = hard::render(request);
    EXPECT_EQ(hard::nonFinitePixels(output.radiance), 0);
    EXPECT_EQ(output.discarded, 0u);
    EXPECT_EQ(hard::maxRadiance(output.radiance), 0.0);
}

}  // namespace
