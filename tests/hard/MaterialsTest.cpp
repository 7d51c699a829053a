// Material parameters at their extremes.
#include "hard/HardCaseSupport.h"

#include <gtest/gtest.h>

#include <sstream>

namespace {

std::string furnaceSphere(const std::string& pigment, const std::string& finish)
{
    std::ostringstream text;
    text << "environment 1 1 1\n0 0 4\n0 0 0\n0 1 0\n40\n0\n1\n"
         << pigment << "\n1\n"
         << finish << "\n1\n0 0 sphere 0 0 0 1\n";
    return text.str();
}

hard::RenderOutput renderFurnace(const std::string& pigment, const std::string& finish)
{
    hard::RenderRequest request;
    request.sceneText = furnaceSphere(pigment, finish);
    request.samplesPerPixel = 64;
    request.settings.samplesPerFrame = 64;
    return hard::render(request);
}

// A Blinn-Phong surface never reflects more than it receives; in a furnace of radiance 1
// no pixel may exceed 1 beyond noise, whatever the exponent.
void expectBlinnPhongBoundedByOne(const std::string& exponent)
{
    const hard::RenderOutput output =
        renderFurnace("solid 0.5 0.5 0.5", "0 0 0 " + exponent + " 0 0 0");
    EXPECT_EQ(hard::nonFinitePixels(output.radiance), 0);
    EXPECT_EQ(output.discarded, 0u);
    for (int y = 0; y < output.radiance.height; ++y)
        for (int x = 0; x < output.radiance.width; ++x) {
            const double noise = 4.0 * std::sqrt(output.statistics.at(x, y, 2));
            ASSERT_LE(output.radiance.at(x, y, 0), 1.0 + noise + 1e-5)
                << "pixel (" << x << ", " << y << ") with exponent " << exponent;
        }
}

TEST(Materials, BlinnPhongExponentOneThousandthConservesEnergy)
{
    expectBlinnPhongBoundedByOne("0.001");
}

TEST(Materials, BlinnPhongExponentOneHundredThousandConservesEnergy)
{
    expectBlinnPhongBoundedByOne("1e5");
}

// A dielectric of index exactly 1 is no interface at all: the scene must look as if it were
// not there, shadows included.
TEST(Materials, DielectricOfIndexOneVanishes)
{
    const std::string common = R"(
environment sky
0 2 6
0 0.5 0
0 1 0
40
1
2 4 2  20 20 20
2
solid 0.7 0.7 0.7
solid 1 1 1
2
0 0 0 0 0 0 0
0 0 0 0 0 1 1
)";
    hard::RenderRequest with;
    with.sceneText = common + "2\n0 0 polyhedron 1 0 1 0 0\n1 1 sphere 0 1 0 1\n";
    with.samplesPerPixel = 64;
    with.settings.samplesPerFrame = 64;
    with.settings.seed = 1;
    hard::RenderRequest without = with;
    without.sceneText = common + "1\n0 0 polyhedron 1 0 1 0 0\n";
    without.settings.seed = 2;
    const std::string disagreement =
        hard::disagreementWithinNoise(hard::render(with), hard::render(without));
    EXPECT_TRUE(disagreement.empty()) << disagreement;
}

// Below 1, the "denser" medium is outside: entering rays may be totally reflected. Every path
// still ends in the furnace carrying exactly 1 (the radiance factors of entering and leaving
// cancel).
TEST(Materials, DielectricOfIndexBelowOneConservesEnergyInFurnace)
{
    const hard::RenderOutput output = renderFurnace("solid 1 1 1", "0 0 0 0 0 1 0.7");
    EXPECT_EQ(output.discarded, 0u);
    EXPECT_NEAR(hard::meanRadiance(output.radiance), 1.0, 1e-3);
    EXPECT_LE(hard::maxRadiance(output.radiance), 1.0 + 1e-5);
}

TEST(Materials, PigmentZeroAbsorbsEverythingAndPigmentOneNothing)
{
    const hard::RenderOutput black = renderFurnace("solid 0 0 0", "0 0 0 0 0 0 0");
    const hard::RenderOutput white = renderFurnace("solid 1 1 1", "0 0 0 0 0 0 0");
    const io::Image& b = black.radiance;
    const io::Image& w = white.radiance;
    EXPECT_EQ(b.at(b.width / 2, b.height / 2, 0), 0.0f);
    for (float value : w.pixels)
        ASSERT_NEAR(value, 1.0, 1e-5);
}

}  // namespace
