// Display pass: linear radiance to a picture. Radiance times uExposure (the original's 4 by
// default; --exposure and the window's panel change it) goes through the curve uToneCurve
// names (TONE_CURVE_*, generated from settings/Choices.h; Hable's filmic curve by default, as
// the original displayed radiance) to a linear display value, then gamma. The curves'
// constants (TONE_*) are generated #defines from film/ToneCurve.h, which says where each curve
// comes from and computes the same curves on the host.

uniform sampler2D uEstimate;
uniform vec2 uImageSize;
uniform vec2 uTargetSize;
uniform float uExposure;
uniform int uToneCurve;

out vec4 outColor;

const float kWhitePoint = TONE_WHITE_POINT;

vec3 hableFilmic(vec3 x)
{
    const float A = TONE_SHOULDER_STRENGTH;
    const float B = TONE_LINEAR_STRENGTH;
    const float C = TONE_LINEAR_ANGLE;
    const float D = TONE_TOE_STRENGTH;
    const float E = TONE_TOE_NUMERATOR;
    const float F = TONE_TOE_DENOMINATOR;
    return ((x * (A * x + C * B) + D * E) / (x * (A * x + B) + D * F)) - E / F;
}

// Narkowicz's fit of ACES.
vec3 acesFilmic(vec3 x)
{
    return (x * (TONE_ACES_A * x + TONE_ACES_B)) /
           (x * (TONE_ACES_C * x + TONE_ACES_D) + TONE_ACES_E);
}

// AgX, Wrensch's minimal fit: the sigmoid's display encoding is undone by the gamma that
// main applies after.
vec3 agx(vec3 colour)
{
    const float kContrast[7] = TONE_AGX_CONTRAST;
    vec3 ev = clamp(log2(max(TONE_AGX_INSET * colour, vec3(1e-10))), TONE_AGX_MIN_EV,
                    TONE_AGX_MAX_EV);
    vec3 x = (ev - TONE_AGX_MIN_EV) / (TONE_AGX_MAX_EV - TONE_AGX_MIN_EV);
    vec3 sigmoid = vec3(0.0);
    for (int i = 0; i < 7; ++i)
        sigmoid = sigmoid * x + kContrast[i];
    return pow(max(TONE_AGX_OUTSET * sigmoid, vec3(0.0)), vec3(TONE_GAMMA));
}

// Khronos PBR Neutral.
vec3 pbrNeutral(vec3 colour)
{
    float x = min(colour.r, min(colour.g, colour.b));
    float offset = x < 2.0 * TONE_NEUTRAL_OFFSET ? x - x * x / (4.0 * TONE_NEUTRAL_OFFSET)
                                                 : TONE_NEUTRAL_OFFSET;
    colour -= offset;
    float peak = max(colour.r, max(colour.g, colour.b));
    if (peak < TONE_NEUTRAL_START_COMPRESSION)
        return colour;
    const float d = 1.0 - TONE_NEUTRAL_START_COMPRESSION;
    float newPeak = 1.0 - d * d / (peak + d - TONE_NEUTRAL_START_COMPRESSION);
    float g = 1.0 - 1.0 / (TONE_NEUTRAL_DESATURATION * (peak - newPeak) + 1.0);
    return mix(colour * (newPeak / peak), vec3(newPeak), g);
}

void main()
{
    // Nearest image pixel for this target pixel (the window may differ in size).
    ivec2 pixel = ivec2(floor(gl_FragCoord.xy * uImageSize / uTargetSize));
    vec3 radiance = max(texelFetch(uEstimate, pixel, 0).rgb, vec3(0.0));
    vec3 exposed = uExposure * radiance;
    vec3 mapped;
    if (uToneCurve == TONE_CURVE_CLAMP)
        mapped = exposed;
    else if (uToneCurve == TONE_CURVE_ACES)
        mapped = acesFilmic(exposed);
    else if (uToneCurve == TONE_CURVE_AGX)
        mapped = agx(exposed);
    else if (uToneCurve == TONE_CURVE_NEUTRAL)
        mapped = pbrNeutral(exposed);
    else
        mapped = hableFilmic(exposed) / hableFilmic(vec3(kWhitePoint));
    outColor = vec4(pow(clamp(mapped, 0.0, 1.0), vec3(1.0 / TONE_GAMMA)), 1.0);
}
