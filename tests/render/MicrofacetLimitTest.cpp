// As the roughness alpha goes to 0, a GGX surface becomes smooth: the rough conductor becomes
// the mirror (both take Schlick's Fresnel with the pigment as R0) and the rough dielectric
// the smooth glass. A coloured ball over a checkered floor under the sky, rendered with the
// same seed both ways, must then give the same picture but for the tiny spread of the
// microfacet lobe.
#include "support/RenderRun.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <string>
#include <vector>

namespace render_tests {
namespace {

using namespace testing_support;

constexpr int kWidth = 64;
constexpr int kHeight = 48;

scene::Scene ballOverCheckers(const std::string& finish)
{
    return sceneFromText("0 1.2 4\n0 0.8 0\n0 1 0\n40\n0\n2\nsolid 0.9 0.6 0.3\n"
                         "checker 0.9 0.9 0.9 0.1 0.1 0.1 0.5\n1\n" +
                         finish + "\n2\n0 0 sphere 0 1 0 1\n1 0 polyhedron 1 0 1 0 0\n");
}

// The mean over pixels and channels of |a - b|, over the mean of b: how far one picture is
// from another, relative to its brightness.
double relativeMeanDifference(const RenderedImage& a, const RenderedImage& b)
{
    double difference = 0.0;
    double brightness = 0.0;
    for (std::size_t i = 0; i < a.radiance.pixels.size(); ++i) {
        difference += std::abs(a.radiance.pixels[i] - b.radiance.pixels[i]);
        brightness += std::abs(b.radiance.pixels[i]);
    }
    return difference / brightness;
}

double differenceFromSmooth(const std::string& smooth, const std::string& rough)
{
    const settings::RenderSettings settings = settingsWithSeed(3);
    const RenderedImage reference =
        renderScene(ballOverCheckers(smooth), kWidth, kHeight, 16, settings);
    const RenderedImage image = renderScene(ballOverCheckers(rough), kWidth, kHeight, 16, settings);
    return relativeMeanDifference(image, reference);
}

TEST(MicrofacetLimit, RoughConductorOfVanishingRoughnessIsTheMirror)
{
    const double difference = differenceFromSmooth("0 0 0  0 1 0 0", "rough_conductor 0.001");
    std::cout << "rough conductor, alpha 0.001, against the mirror: relative mean difference "
              << difference << "\n";
    EXPECT_LT(difference, 0.01) << "a rough conductor of alpha 0.001 should render as the mirror "
                                   "of the same pigment";
}

TEST(MicrofacetLimit, RoughDielectricOfVanishingRoughnessIsTheSmoothGlass)
{
    const double difference =
        differenceFromSmooth("0 0 0  0 0 1 1.5", "rough_dielectric 0.001 1.5");
    std::cout << "rough dielectric, alpha 0.001, against the smooth glass: relative mean "
                 "difference "
              << difference << "\n";
    EXPECT_LT(difference, 0.01) << "a rough dielectric of alpha 0.001 should render as the glass "
                                   "of the same index";
}

}  // namespace
}  // namespace render_tests
