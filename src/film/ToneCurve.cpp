#include "film/ToneCurve.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace film {

namespace {

// The shortest decimal that reads back as `value` ("0.15", not "0.14999999999999999").
std::string shortestDecimal(double value)
{
    char text[32];
    for (int digits = 1; digits <= 17; ++digits) {
        std::snprintf(text, sizeof text, "%.*g", digits, value);
        if (std::strtod(text, nullptr) == value)
            break;
    }
    std::string decimal = text;
    // A GLSL float literal needs a point or an exponent.
    if (decimal.find_first_of(".e") == std::string::npos)
        decimal += ".0";
    return decimal;
}

}  // namespace

double hableFilmic(double x)
{
    const double A = ToneCurve::kShoulderStrength;
    const double B = ToneCurve::kLinearStrength;
    const double C = ToneCurve::kLinearAngle;
    const double D = ToneCurve::kToeStrength;
    const double E = ToneCurve::kToeNumerator;
    const double F = ToneCurve::kToeDenominator;
    return ((x * (A * x + C * B) + D * E) / (x * (A * x + B) + D * F)) - E / F;
}

double displayValue(double radiance, double exposure)
{
    const double mapped =
        hableFilmic(exposure * std::max(radiance, 0.0)) / hableFilmic(ToneCurve::kWhitePoint);
    return std::pow(std::clamp(mapped, 0.0, 1.0), 1.0 / ToneCurve::kGamma);
}

std::string toneCurveDefines()
{
    std::string defines;
    auto define = [&](const char* name, double value) {
        defines += std::string("#define ") + name + " " + shortestDecimal(value) + "\n";
    };
    define("TONE_SHOULDER_STRENGTH", ToneCurve::kShoulderStrength);
    define("TONE_LINEAR_STRENGTH", ToneCurve::kLinearStrength);
    define("TONE_LINEAR_ANGLE", ToneCurve::kLinearAngle);
    define("TONE_TOE_STRENGTH", ToneCurve::kToeStrength);
    define("TONE_TOE_NUMERATOR", ToneCurve::kToeNumerator);
    define("TONE_TOE_DENOMINATOR", ToneCurve::kToeDenominator);
    define("TONE_WHITE_POINT", ToneCurve::kWhitePoint);
    define("TONE_GAMMA", ToneCurve::kGamma);
    return defines;
}

}  // namespace film
