#pragma once
// The display's tone curve, described once: John Hable's filmic curve ("Uncharted 2 tone
// mapping", http://filmicgames.com/archives/75) with its published constants, normalised to
// a white point of 11.2, then gamma 2.2, as the original program displayed radiance. The
// display pass (shaders/modules/tone_map.frag) receives the constants as generated
// #defines; displayValue is the same curve in double on the host, for measurements that
// must not be rounded to 8 bits (bench_convergence's tone-mapped RMSE).
#include <string>

namespace film {

struct ToneCurve {
    static constexpr double kShoulderStrength = 0.15;  // A
    static constexpr double kLinearStrength = 0.50;    // B
    static constexpr double kLinearAngle = 0.10;       // C
    static constexpr double kToeStrength = 0.20;       // D
    static constexpr double kToeNumerator = 0.02;      // E
    static constexpr double kToeDenominator = 0.30;    // F
    static constexpr double kWhitePoint = 11.2;        // radiance x exposure shown as white
    static constexpr double kGamma = 2.2;
    // Radiance is multiplied by this before the curve unless the user chooses another.
    static constexpr float kDefaultExposure = 4.0f;
};

// Hable's curve at x (before normalisation to the white point).
double hableFilmic(double x);

// The displayed value of one channel of linear radiance, in [0, 1], unrounded: what the
// display pass computes in float at the given exposure (ToneCurve::kDefaultExposure by default).
double displayValue(double radiance, double exposure);

// The curve's constants as "#define TONE_..." lines for tone_map.frag.
std::string toneCurveDefines();

}  // namespace film
