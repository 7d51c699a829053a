// Every tolerance (hit distance, normal step, ray offset, far distance) follows the scene's
// scale or the hit distance, so a scene scaled by 1e-3 or 1e3 renders as at scale 1.
#include "hard/HardCaseSupport.h"

#include <gtest/gtest.h>

#include <sstream>

namespace {

// A floor, a sphere resting on it, a box, a torus, a checker and two lights. Lengths are
// multiplied by `s`; point-light intensity by s^2 (so irradiance is unchanged); radiance of
// the sphere light is scale-free.
std::string scaledScene(double s)
{
    std::ostringstream text;
    auto v = [&](double x) { return x * s; };
    text << "environment 0.2 0.2 0.25\n";
    text << v(0) << " " << v(2.5) << " " << v(6) << "\n"
         << v(0) << " " << v(0.6) << " " << v(0) << "\n0 1 0\n45\n";
    text << "1\n"
         << v(3) << " " << v(5) << " " << v(3) << " " << 30 * s * s << " " << 30 * s * s << " "
         << 30 * s * s << "\n";
    text << "3\nchecker 0.8 0.8 0.8  0.3 0.3 0.3 " << v(1) << "\nsolid 0.7 0.4 0.2\nsolid 0 0 0\n";
    text << "3\n0 0 0 0 0 0 0\n0 0 0 40 0 0 0\n20 20 20 0 0 0 0\n";
    text << "5\n";
    text << "0 0 polyhedron 1 0 1 0 0\n";
    text << "1 1 sphere " << v(-0.8) << " " << v(0.7) << " " << v(0) << " " << v(0.7) << "\n";
    text << "1 0 box " << v(1.0) << " " << v(0.4) << " " << v(0.5) << " " << v(0.4) << " " << v(0.4)
         << " " << v(0.4) << "\n";
    text << "1 1 torus " << v(0.4) << " " << v(0.25) << " " << v(-1.5) << " " << v(0.6) << " "
         << v(0.25) << "\n";
    text << "2 2 sphere " << v(-2) << " " << v(3) << " " << v(1) << " " << v(0.3) << "\n";
    return text.str();
}

// Independent seeds, so that the two renders' noise is independent as the comparison
// assumes.
hard::RenderOutput renderAtScale(double scale, std::uint64_t seed)
{
    hard::RenderRequest request;
    request.settings.seed = seed;
    request.sceneText = scaledScene(scale);
    request.samplesPerPixel = 64;
    request.settings.samplesPerFrame = 16;
    return hard::render(request);
}

TEST(Scale, SceneScaledDownByAThousandRendersAsAtScaleOne)
{
    const hard::RenderOutput one = renderAtScale(1.0, 1);
    const hard::RenderOutput small = renderAtScale(1e-3, 2);
    EXPECT_EQ(hard::nonFinitePixels(small.radiance), 0);
    EXPECT_EQ(small.discarded, 0u);
    const std::string disagreement = hard::disagreementWithinNoise(one, small);
    EXPECT_TRUE(disagreement.empty()) << disagreement;
}

TEST(Scale, SceneScaledUpByAThousandRendersAsAtScaleOne)
{
    const hard::RenderOutput one = renderAtScale(1.0, 1);
    const hard::RenderOutput large = renderAtScale(1e3, 3);
    EXPECT_EQ(hard::nonFinitePixels(large.radiance), 0);
    EXPECT_EQ(large.discarded, 0u);
    const std::string disagreement = hard::disagreementWithinNoise(one, large);
    EXPECT_TRUE(disagreement.empty()) << disagreement;
}

}  // namespace
