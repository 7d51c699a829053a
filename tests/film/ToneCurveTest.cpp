// The display's tone curve on the host (film/ToneCurve.h), and the constants the display
// pass receives from it.
#include "film/ToneCurve.h"

#include <gtest/gtest.h>

namespace {

TEST(ToneCurve, BlackIsZeroAndTheWhitePointIsOne)
{
    const double exposure = film::ToneCurve::kDefaultExposure;
    EXPECT_EQ(film::displayValue(0.0, exposure), 0.0);
    EXPECT_EQ(film::displayValue(-1.0, exposure), 0.0) << "negative radiance shows black";
    EXPECT_NEAR(film::displayValue(film::ToneCurve::kWhitePoint / exposure, exposure), 1.0,
                1e-12);
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

}  // namespace
