// Display pass: linear radiance to a picture, as the original did: exposure 4 (the host's
// default for uExposure; the window's panel changes it), John Hable's filmic curve
// ("Uncharted 2", http://filmicgames.com/archives/75) normalised to a white point, then
// gamma. The curve's constants (TONE_*) are generated #defines from render/ToneCurve.h,
// which also computes the same curve on the host.

uniform sampler2D uEstimate;
uniform vec2 uImageSize;
uniform vec2 uTargetSize;
uniform float uExposure;

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

void main()
{
    // Nearest image pixel for this target pixel (the window may differ in size).
    ivec2 pixel = ivec2(floor(gl_FragCoord.xy * uImageSize / uTargetSize));
    vec3 radiance = max(texelFetch(uEstimate, pixel, 0).rgb, vec3(0.0));
    vec3 mapped = hableFilmic(uExposure * radiance) / hableFilmic(vec3(kWhitePoint));
    outColor = vec4(pow(clamp(mapped, 0.0, 1.0), vec3(1.0 / TONE_GAMMA)), 1.0);
}
