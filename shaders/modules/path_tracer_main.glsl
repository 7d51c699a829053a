// One frame of progressive rendering: each pixel reads its running estimate and random
// state from the previous frame's targets, traces one path, and writes both anew (the two
// target sets are ping-ponged by the host; no texture is read and written in one draw).
//
// The estimate is a running mean, mean += (x - mean) / n, not a running sum: a sum in
// float32 loses the low digits of each new sample once it is large, the mean does not, so
// 100 000 samples do not drift. The second moment (Welford 1962) gives each pixel's
// variance for noise-aware comparisons. A sample that is NaN, infinite or negative is
// discarded and counted instead: one bad sample never poisons a pixel.

uniform sampler2D uPreviousEstimate;   // rgb: mean radiance, a: samples accumulated
uniform sampler2D uPreviousMoments;    // rgb: sum of squared deviations, a: samples discarded
uniform usampler2D uPreviousRandomState;
uniform int uSamplesPerFrame;

layout(location = 0) out vec4 outEstimate;
layout(location = 1) out vec4 outMoments;
layout(location = 2) out uvec4 outRandomState;

bool isValidSample(vec3 value)
{
    return !any(isnan(value)) && !any(isinf(value)) && all(greaterThanEqual(value, vec3(0.0)));
}

void main()
{
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    vec4 estimate = texelFetch(uPreviousEstimate, pixel, 0);
    vec4 moments = texelFetch(uPreviousMoments, pixel, 0);
    rngState = texelFetch(uPreviousRandomState, pixel, 0);

    // uSamplesPerFrame paths, one after the other, in one loop of path segments: a pixel
    // whose path ends early starts its next path at once instead of idling until its
    // neighbours' longer paths end. (Neighbouring pixels run in lockstep on SIMD hardware,
    // llvmpipe included, so a loop of whole paths costs the longest path of the group for
    // every path.)
    // A uniformly random point inside the pixel for each path: box-filtered anti-aliasing.
    int cameraContaining = cameraContainingObject();
    // A camera inside a solid marches its rays from the eye (the cone is not clear there).
    float cameraClear = cameraContaining >= 0 ? 0.0 : cameraClearDistance(pixel);
    PathState path = startPath(vec2(pixel) + random2(), cameraContaining, cameraClear);
    int completed = 0;
    int segments = uSamplesPerFrame * maxSegmentsPerPath();
    for (int segment = 0; segment < segments; ++segment) {
        if (continuePath(path))
            continue;
        vec3 value = path.radiance;
        if (isValidSample(value)) {
            float count = estimate.a + 1.0;
            vec3 deviation = value - estimate.rgb;
            estimate.rgb += deviation / count;
            moments.rgb += deviation * (value - estimate.rgb);
            estimate.a = count;
        } else {
            moments.a += 1.0;
        }
        if (++completed == uSamplesPerFrame)
            break;
        path = startPath(vec2(pixel) + random2(), cameraContaining, cameraClear);
    }
    outEstimate = estimate;
    outMoments = moments;
    outRandomState = rngState;
}
