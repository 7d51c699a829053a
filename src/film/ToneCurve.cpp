#include "film/ToneCurve.h"

#include "settings/OptionValues.h"

#include <algorithm>
#include <cmath>

namespace film {

namespace {

// The shortest decimal that reads back as `value`, as a GLSL float literal.
std::string shortestDecimal(double value)
{
    std::string decimal = settings::shortestDoubleText(value);
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

namespace {

// Hable's curve normalised to its white point, before gamma.
double hableNormalised(double x)
{
    return hableFilmic(x) / hableFilmic(ToneCurve::kWhitePoint);
}

double aces(double x)
{
    const auto& k = ToneCurve::kAces;
    return (x * (k[0] * x + k[1])) / (x * (k[2] * x + k[3]) + k[4]);
}

// A GLSL mat3 (column by column) times v.
Rgb times(const std::array<double, 9>& matrix, const Rgb& v)
{
    Rgb result{};
    for (int row = 0; row < 3; ++row)
        for (int column = 0; column < 3; ++column)
            result[row] += matrix[column * 3 + row] * v[column];
    return result;
}

Rgb agx(const Rgb& colour)
{
    Rgb v = times(ToneCurve::kAgxInset, colour);
    for (double& c : v) {
        const double ev = std::clamp(std::log2(std::max(c, 1e-10)), ToneCurve::kAgxMinimumEv,
                                     ToneCurve::kAgxMaximumEv);
        const double x =
            (ev - ToneCurve::kAgxMinimumEv) / (ToneCurve::kAgxMaximumEv - ToneCurve::kAgxMinimumEv);
        double sigmoid = 0.0;
        for (double coefficient : ToneCurve::kAgxContrast)
            sigmoid = sigmoid * x + coefficient;
        c = sigmoid;
    }
    v = times(ToneCurve::kAgxOutset, v);
    for (double& c : v)
        c = std::pow(std::max(c, 0.0), ToneCurve::kGamma);
    return v;
}

Rgb pbrNeutral(Rgb colour)
{
    const double offsetAtBlack = ToneCurve::kNeutralOffset;
    const double start = ToneCurve::kNeutralStartCompression;
    const double x = std::min({colour[0], colour[1], colour[2]});
    const double offset =
        x < 2.0 * offsetAtBlack ? x - x * x / (4.0 * offsetAtBlack) : offsetAtBlack;
    for (double& c : colour)
        c -= offset;
    const double peak = std::max({colour[0], colour[1], colour[2]});
    if (peak < start)
        return colour;
    const double d = 1.0 - start;
    const double newPeak = 1.0 - d * d / (peak + d - start);
    const double g = 1.0 - 1.0 / (ToneCurve::kNeutralDesaturation * (peak - newPeak) + 1.0);
    for (double& c : colour)
        c = c * (newPeak / peak) * (1.0 - g) + newPeak * g;
    return colour;
}

}  // namespace

Rgb displayColour(const Rgb& radiance, double exposure, settings::ToneCurveKind curve)
{
    Rgb exposed{};
    for (int c = 0; c < 3; ++c)
        exposed[c] = exposure * std::max(radiance[c], 0.0);
    Rgb mapped = exposed;
    switch (curve) {
    case settings::ToneCurveKind::Clamp:
        break;
    case settings::ToneCurveKind::Hable:
        for (double& c : mapped)
            c = hableNormalised(c);
        break;
    case settings::ToneCurveKind::Aces:
        for (double& c : mapped)
            c = aces(c);
        break;
    case settings::ToneCurveKind::Agx:
        mapped = agx(exposed);
        break;
    case settings::ToneCurveKind::Neutral:
        mapped = pbrNeutral(exposed);
        break;
    }
    for (double& c : mapped)
        c = std::pow(std::clamp(c, 0.0, 1.0), 1.0 / ToneCurve::kGamma);
    return mapped;
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
    const char* acesNames[] = {"TONE_ACES_A", "TONE_ACES_B", "TONE_ACES_C", "TONE_ACES_D",
                               "TONE_ACES_E"};
    for (std::size_t i = 0; i < ToneCurve::kAces.size(); ++i)
        define(acesNames[i], ToneCurve::kAces[i]);
    auto list = [](const auto& values) {
        std::string text;
        for (double value : values)
            text += (text.empty() ? "" : ", ") + shortestDecimal(value);
        return text;
    };
    defines += "#define TONE_AGX_INSET mat3(" + list(ToneCurve::kAgxInset) + ")\n";
    defines += "#define TONE_AGX_OUTSET mat3(" + list(ToneCurve::kAgxOutset) + ")\n";
    defines += "#define TONE_AGX_CONTRAST float[7](" + list(ToneCurve::kAgxContrast) + ")\n";
    define("TONE_AGX_MIN_EV", ToneCurve::kAgxMinimumEv);
    define("TONE_AGX_MAX_EV", ToneCurve::kAgxMaximumEv);
    define("TONE_NEUTRAL_OFFSET", ToneCurve::kNeutralOffset);
    define("TONE_NEUTRAL_START_COMPRESSION", ToneCurve::kNeutralStartCompression);
    define("TONE_NEUTRAL_DESATURATION", ToneCurve::kNeutralDesaturation);
    return defines;
}

}  // namespace film
