// The window's preview denoiser: one pass of the edge-avoiding à-trous wavelet filter
// (Dammertz, Sewtz, Hanika and Lensch, "Edge-Avoiding À-Trous Wavelet Transform for fast
// Global Illumination Filtering", HPG 2010), run five times with steps 1, 2, 4, 8, 16: a
// 5 x 5 B3-spline kernel (1/16, 1/4, 3/8, 1/4, 1/16) whose taps lie `uStep` pixels apart, each
// weighted down where the colour, the normal or the depth differs from the centre's. As in
// SVGF (Schied et al. 2017) the colour weight's scale follows the pixel's own noise (the
// variance of its mean, from the accumulation's second moments), so the filter fades as the
// render converges, and the illumination is filtered apart from the albedo (divided out in
// the first pass, multiplied back in the last), so that textures stay sharp. Display only:
// never written to a file.

uniform sampler2D uSource;          // first pass: the estimate (rgb: mean, a: samples kept)
uniform sampler2D uMoments;         // rgb: sum of squared deviations
uniform sampler2D uAlbedoDepth;     // rgb: first-hit albedo, a: camera distance
uniform sampler2D uNormalCoverage;  // rgb: first-hit normal, a: fraction of samples that hit
uniform int uStep;                  // 1, 2, 4, 8, 16
uniform ivec2 uSize;                // the pixels filtered, from (0, 0)
uniform bool uFirstPass;            // uSource is the estimate: demodulate it
uniform bool uLastPass;             // write radiance: modulate the albedo back in
uniform float uColorSigma;          // colour weight's scale, in standard deviations
uniform float uNormalSigma;
uniform float uDepthSigma;          // relative depth difference per pixel of step

// rgb: illumination (radiance / albedo), a: variance of its luminance's mean.
out vec4 outFiltered;

const float kMinimumAlbedo = 0.02;

float luminance(vec3 c)
{
    return dot(c, vec3(0.2126, 0.7152, 0.0722));
}

vec3 safeAlbedo(vec3 albedo)
{
    return max(albedo, vec3(kMinimumAlbedo));
}

// The tap's illumination and the variance of its luminance.
vec4 illumination(ivec2 pixel)
{
    vec4 value = texelFetch(uSource, pixel, 0);
    if (!uFirstPass)
        return value;
    vec3 albedo = safeAlbedo(texelFetch(uAlbedoDepth, pixel, 0).rgb);
    float kept = value.a;
    float variance = kept > 1.0 ? luminance(texelFetch(uMoments, pixel, 0).rgb) /
                                      (kept * (kept - 1.0))
                                : 1.0;
    float scale = luminance(albedo);
    return vec4(value.rgb / albedo, variance / (scale * scale));
}

void main()
{
    ivec2 size = uSize;
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    const float kernel[3] = float[3](3.0 / 8.0, 1.0 / 4.0, 1.0 / 16.0);
    vec4 centre = illumination(pixel);
    vec4 features = texelFetch(uNormalCoverage, pixel, 0);
    vec3 normal = features.rgb;
    float depth = texelFetch(uAlbedoDepth, pixel, 0).a;
    float colorScale = uColorSigma * sqrt(max(centre.a, 1e-8)) + 1e-4;

    vec3 sum = vec3(0.0);
    float sumVariance = 0.0;
    float sumWeight = 0.0;
    for (int dy = -2; dy <= 2; ++dy)
        for (int dx = -2; dx <= 2; ++dx) {
            ivec2 tap = pixel + uStep * ivec2(dx, dy);
            if (any(lessThan(tap, ivec2(0))) || any(greaterThanEqual(tap, size)))
                continue;
            vec4 value = illumination(tap);
            vec3 tapNormal = texelFetch(uNormalCoverage, tap, 0).rgb;
            float tapDepth = texelFetch(uAlbedoDepth, tap, 0).a;
            float colorDistance = abs(luminance(value.rgb) - luminance(centre.rgb)) / colorScale;
            vec3 normalDifference = tapNormal - normal;
            float normalDistance = dot(normalDifference, normalDifference) / uNormalSigma;
            float depthDistance = abs(tapDepth - depth) /
                                  (uDepthSigma * float(uStep) * max(depth, 1e-3) + 1e-6);
            float h = kernel[abs(dx)] * kernel[abs(dy)];
            float w = h * exp(-colorDistance - normalDistance - depthDistance);
            sum += w * value.rgb;
            sumVariance += w * w * value.a;
            sumWeight += w;
        }
    vec3 filtered = sum / sumWeight;
    float variance = sumVariance / (sumWeight * sumWeight);
    if (uLastPass)
        filtered *= safeAlbedo(texelFetch(uAlbedoDepth, pixel, 0).rgb);
    outFiltered = vec4(filtered, variance);
}
