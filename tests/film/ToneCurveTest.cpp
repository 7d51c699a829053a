// The display's tone curve on the host (film/ToneCurve.h), and the constants the display
// pass receives from it.
#include "film/ToneCurve.h"

#include <gtest/gtest.h>

#include <cmath>

namespace {

TEST(ToneCurve, BlackIsZeroAndTheWhitePointIsOne)
{
    const double exposure = film::ToneCurve::kDefaultExposure;
    EXPECT_EQ(film::displayValue(0.0, exposure), 0.0);
    EXPECT_EQ(film::displayValue(-1.0, exposure), 0.0) << "negative radiance shows black";
    EXPECT_NEAR(film::displayValue(film::ToneCurve::kWhitePoint / exposure, exposure), 1.0, 1e-12);
    EXPECT_EQ(film::displayValue(1e6, exposure), 1.0) << "beyond white, clamped";
}

TEST(ToneCurve, GrowsWithRadiance)
{
    double previous = 0.0;
    for (double radiance = 0.01; radiance < 2.8; radiance *= 1.5) {
        const double value = film::displayValue(radiance, 4.0);
        EXPECT_GT(value, previous) << "at radiance " << radiance;
        previous = value;
    }
}

TEST(ToneCurve, TheDisplayPassGetsEachConstantAsWritten)
{
    const std::string defines = film::toneCurveDefines();
    for (const char* line :
         {"#define TONE_SHOULDER_STRENGTH 0.15\n", "#define TONE_LINEAR_STRENGTH 0.5\n",
          "#define TONE_LINEAR_ANGLE 0.1\n", "#define TONE_TOE_STRENGTH 0.2\n",
          "#define TONE_TOE_NUMERATOR 0.02\n", "#define TONE_TOE_DENOMINATOR 0.3\n",
          "#define TONE_WHITE_POINT 11.2\n", "#define TONE_GAMMA 2.2\n"})
        EXPECT_NE(defines.find(line), std::string::npos) << line << "not in:\n" << defines;
}

// Every curve of --tone-curve: black is black, a grey stays grey, and more light is never
// shown darker, up to white.
TEST(ToneCurve, EveryCurveShowsBlackAsBlackGreyAsGreyAndGrowsWithRadiance)
{
    for (const auto& choice : settings::Choices<settings::ToneCurveKind>::values) {
        EXPECT_EQ(film::displayColour({0.0, 0.0, 0.0}, 4.0, choice.value)[0], 0.0) << choice.name;
        double previous = 0.0;
        for (double radiance = 0.001; radiance < 1000.0; radiance *= 1.5) {
            const film::Rgb shown =
                film::displayColour({radiance, radiance, radiance}, 1.0, choice.value);
            // Within a quarter of an 8-bit step: AgX's published matrices keep a grey to 2e-4.
            EXPECT_NEAR(shown[0], shown[1], 1e-3) << choice.name << " at " << radiance;
            EXPECT_NEAR(shown[0], shown[2], 1e-3) << choice.name << " at " << radiance;
            EXPECT_GE(shown[0], previous - 1e-12) << choice.name << " at " << radiance;
            EXPECT_LE(shown[0], 1.0) << choice.name;
            previous = shown[0];
        }
        EXPECT_GT(previous, 0.95) << choice.name << ": bright light shows (nearly) white";
    }
}

// The default is the original program's picture: Hable's curve at exposure 4.
TEST(ToneCurve, TheDefaultCurveAndExposureAreHablesAtFour)
{
    EXPECT_EQ(film::ToneCurve::kDefaultCurve, settings::ToneCurveKind::Hable);
    EXPECT_EQ(film::ToneCurve::kDefaultExposure, 4.0f);
    for (double radiance : {0.01, 0.1, 0.5, 2.0})
        EXPECT_EQ(film::displayColour({radiance, radiance, radiance}, 4.0,
                                      settings::ToneCurveKind::Hable)[0],
                  film::displayValue(radiance, 4.0));
}

// Khronos PBR Neutral shows a base colour below its compression start as it is, but for the
// small offset near black.
TEST(ToneCurve, NeutralShowsMidTonesAsTheyAre)
{
    const film::Rgb shown =
        film::displayColour({0.5, 0.3, 0.2}, 1.0, settings::ToneCurveKind::Neutral);
    EXPECT_NEAR(std::pow(shown[0], 2.2), 0.5 - 0.04, 1e-9);
    EXPECT_NEAR(std::pow(shown[1], 2.2), 0.3 - 0.04, 1e-9);
    EXPECT_NEAR(std::pow(shown[2], 2.2), 0.2 - 0.04, 1e-9);
}

}  // namespace
