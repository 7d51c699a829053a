#pragma once
// The display's tone curves, described once: their constants here, passed to the display pass
// (shaders/modules/tone_map.frag) as generated #defines, and each curve computed the same way
// in double on the host (displayColour), for measurements that must not be rounded to 8 bits
// (bench_convergence's tone-mapped RMSE) and for the tests that hold the shader to it. Which
// curve and exposure are settings (--tone-curve, --exposure; settings/Choices.h names them).
// Every curve maps exposed radiance to a linear display value in [0, 1], then gamma 2.2, as
// the original program displayed radiance:
//   clamp    the value itself;
//   hable    John Hable's filmic curve ("Uncharted 2 tone mapping",
//            http://filmicgames.com/archives/75) with its published constants, normalised to
//            a white point of 11.2 (the original program's, and the default);
//   aces     Krzysztof Narkowicz's fit of the ACES reference rendering transform ("ACES
//            Filmic Tone Mapping Curve", 2016);
//   agx      Troy Sobotka's AgX in Benjamin Wrensch's minimal fit ("Minimal AgX
//            implementation", 2023): inset matrix, log2 encoding from -12.47 to +4.03 EV, a
//            sixth-degree sigmoid, outset matrix; the sigmoid's display encoding undone by the
//            same gamma that is applied after;
//   neutral  Khronos PBR Neutral (2024): colours below 0.76 unchanged but for a small
//            offset at black, highlights compressed towards white and desaturated.
#include "settings/Choices.h"
#include "settings/RenderSettings.h"

#include <array>
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
    // Radiance is multiplied by this before the curve unless the user chooses another
    // (--exposure, --tone-curve: settings/Options.def holds the defaults).
    static constexpr float kDefaultExposure = settings::RenderSettings{}.exposure;
    static constexpr settings::ToneCurveKind kDefaultCurve = settings::RenderSettings{}.toneCurve;

    // Narkowicz: x (A x + B) / (x (C x + D) + E).
    static constexpr std::array<double, 5> kAces = {2.51, 0.03, 2.43, 0.59, 0.14};
    // AgX's inset and outset matrices, column by column (as GLSL's mat3 takes them).
    static constexpr std::array<double, 9> kAgxInset = {
        0.842479062253094,  0.0423282422610123, 0.0423756549057051,
        0.0784335999999992, 0.878468636469772,  0.0784336,
        0.0792237451477643, 0.0791661274605434, 0.879142973793104};
    static constexpr std::array<double, 9> kAgxOutset = {
        1.19687900512017,    -0.0528968517574562, -0.0529716355144438,
        -0.0980208811401368, 1.15190312990417,    -0.0980434501171241,
        -0.0990297440797205, -0.0989611768448433, 1.15107367264116};
    static constexpr double kAgxMinimumEv = -12.47393;
    static constexpr double kAgxMaximumEv = 4.026069;
    // The sigmoid's coefficients, from x^6 down to x^0.
    static constexpr std::array<double, 7> kAgxContrast = {15.5,   -40.14, 31.96,   -6.868,
                                                           0.4298, 0.1191, -0.00232};
    // PBR Neutral: the offset at black (F90 of a dielectric), where compression starts, and
    // how much compressed highlights lose of their colour.
    static constexpr double kNeutralOffset = 0.04;
    static constexpr double kNeutralStartCompression = 0.8 - kNeutralOffset;
    static constexpr double kNeutralDesaturation = 0.15;
};

using Rgb = std::array<double, 3>;

// The displayed colour of linear radiance `radiance` (RGB), each channel in [0, 1],
// unrounded: what the display pass computes in float for `curve` at `exposure`.
Rgb displayColour(const Rgb& radiance, double exposure, settings::ToneCurveKind curve);

// Hable's curve at x (before normalisation to the white point).
double hableFilmic(double x);

// The displayed value of one channel of linear radiance, in [0, 1], unrounded, by Hable's curve
// (the default; a channel alone, as every curve but agx and neutral maps it).
double displayValue(double radiance, double exposure);

// The curves' constants as "#define TONE_..." lines for tone_map.frag.
std::string toneCurveDefines();

}  // namespace film
