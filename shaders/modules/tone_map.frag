// Display pass: linear radiance to a picture, as the original did: exposure 4 (the host's
// default for uExposure; the window's panel changes it), John Hable's filmic curve
// ("Uncharted 2", http://filmicgames.com/archives/75) normalised to a white point of 11.2,
// then gamma 2.2.

uniform sampler2D uEstimate;
uniform vec2 uImageSize;
uniform vec2 uTargetSize;
uniform float uExposure;

out vec4 outColor;

const float kWhitePoint = 11.2;

vec3 hableFilmic(vec3 x)
{
    const float A = 0.15;  // shoulder strength
    const float B = 0.50;  // linear strength
    const float C = 0.10;  // linear angle
    const float D = 0.20;  // toe strength
    const float E = 0.02;  // toe numerator
    const float F = 0.30;  // toe denominator
    return ((x * (A * x + C * B) + D * E) / (x * (A * x + B) + D * F)) - E / F;
}

void main()
{
    // Nearest image pixel for this target pixel (the window may differ in size).
    ivec2 pixel = ivec2(floor(gl_FragCoord.xy * uImageSize / uTargetSize));
    vec3 radiance = max(texelFetch(uEstimate, pixel, 0).rgb, vec3(0.0));
    vec3 mapped = hableFilmic(uExposure * radiance) / hableFilmic(vec3(kWhitePoint));
    outColor = vec4(pow(clamp(mapped, 0.0, 1.0), vec3(1.0 / 2.2)), 1.0);
}
