// What one pixel does in one frame, whichever kernel drives it (fragment_kernel.glsl: one
// fragment per pixel of a full-screen triangle; compute_kernel.glsl: one invocation per
// pixel of a compute dispatch): it takes its running estimate from the previous frame's
// targets, traces its paths, and the kernel writes the estimate anew (the two target sets are
// ping-ponged by the host; no texture is read and written in one pass). A path's numbers
// depend only on (seed, pixel, sample index) (sampler.glsl), so nothing else needs to
// persist between frames, and both kernels give a pixel the same samples.
//
// The estimate is a running mean, mean += (x - mean) / n, not a running sum: a sum in
// float32 loses the low digits of each new sample once it is large, the mean does not, so
// 100 000 samples do not drift. The second moment (Welford 1962) gives each pixel's
// variance for noise-aware comparisons. A sample that is NaN, infinite or negative is
// discarded and counted instead: one bad sample never poisons a pixel.

uniform sampler2D uPreviousEstimate;   // rgb: mean radiance, a: samples accumulated
uniform sampler2D uPreviousMoments;    // rgb: sum of squared deviations, a: samples discarded
uniform int uSamplesPerFrame;
uniform int uSampleTarget;  // samples (kept and discarded) a pixel stops at; 0: no limit
// Adaptive sampling (render/AdaptiveSampling.h): r = the samples the pixels of each
// uTileSize-pixel square tile stop at, tiles counted from the bottom left; uTileSize 0: none.
uniform sampler2D uTileSampleTargets;
uniform int uTileSize;

#if FEATURE_BUFFERS
// Feature buffers (film/Accumulation.h), means over the samples kept like the estimate's:
//   albedoDepth     rgb: first-hit albedo, a: camera distance (mean over the samples that hit)
//   normalCoverage  rgb: first-hit normal, a: fraction of the samples that hit
uniform sampler2D uPreviousAlbedoDepth;
uniform sampler2D uPreviousNormalCoverage;
vec4 accumulatedAlbedoDepth;
vec4 accumulatedNormalCoverage;

// Folds a kept sample's features in; `count`: the samples kept, this one included.
void accumulateFeatures(PathState path, float count)
{
    accumulatedAlbedoDepth.rgb += (path.featureAlbedo - accumulatedAlbedoDepth.rgb) / count;
    accumulatedNormalCoverage.rgb += (path.featureNormal - accumulatedNormalCoverage.rgb) / count;
    float hit = path.featureDepth >= 0.0 ? 1.0 : 0.0;
    accumulatedNormalCoverage.a += (hit - accumulatedNormalCoverage.a) / count;
    if (hit > 0.0) {
        float hits = max(1.0, floor(accumulatedNormalCoverage.a * count + 0.5));
        accumulatedAlbedoDepth.a += (path.featureDepth - accumulatedAlbedoDepth.a) / hits;
    }
}
#endif

bool isValidSample(vec3 value)
{
    return !any(isnan(value)) && !any(isinf(value)) && all(greaterThanEqual(value, vec3(0.0)));
}

// The pixel's estimate and moments as the previous frame left them.
void readPreviousAccumulation(ivec2 pixel, out vec4 estimate, out vec4 moments)
{
    estimate = texelFetch(uPreviousEstimate, pixel, 0);
    moments = texelFetch(uPreviousMoments, pixel, 0);
#if FEATURE_BUFFERS
    accumulatedAlbedoDepth = texelFetch(uPreviousAlbedoDepth, pixel, 0);
    accumulatedNormalCoverage = texelFetch(uPreviousNormalCoverage, pixel, 0);
#endif
}

// Adds this frame's paths of `pixel` to its estimate and moments.
void accumulatePaths(ivec2 pixel, inout vec4 estimate, inout vec4 moments)
{
    // uSamplesPerFrame paths, or fewer where the pixel would pass uSampleTarget (0: none),
    // one after the other, in one loop of path segments: a pixel whose path ends early
    // starts its next path at once instead of idling until its neighbours' longer paths
    // end. (Neighbouring pixels run in lockstep on SIMD hardware, llvmpipe included, so a
    // loop of whole paths costs the longest path of the group for every path.)
    // A uniformly distributed point inside the pixel for each path: box-filtered
    // anti-aliasing. Every path finished, kept or discarded, takes the next sample index.
    int traced = int(estimate.a + moments.a);
    int wanted = uSampleTarget > 0 ? min(uSamplesPerFrame, uSampleTarget - traced)
                                   : uSamplesPerFrame;
    // A converged tile's pixels all return here together, so its lanes are free at once.
    if (uTileSize > 0)
        wanted = min(wanted, int(texelFetch(uTileSampleTargets, pixel / uTileSize, 0).r) - traced);
    if (wanted <= 0)
        return;
    int cameraContaining = cameraContainingObject();
    // A camera inside a solid marches its rays from the eye (the cone is not clear there).
    float cameraClear = cameraContaining >= 0 ? 0.0 : cameraMarchStart(pixel);
    beginSample(pixel, uint(traced));
    PathState path = startPath(vec2(pixel) + sample2D(SAMPLE_PIXEL), cameraContaining,
                               cameraClear);
    int completed = 0;
    int segments = wanted * maxSegmentsPerPath();
    for (int segment = 0; segment < segments && loopIterationAllowed(); ++segment) {
        bool going = continuePath(path);
        // A path the loop budget cut short is abandoned (constants.glsl): the next frame
        // traces its sample index again.
        if (loopBudgetSpent())
            break;
        if (going)
            continue;
#if PROFILE_COUNTERS
        // Sums of the work per path, not radiance (work_counters.glsl).
        estimate += vec4(workCameraSteps, workBounceSteps, workShadowSteps, 1.0);
        moments.rgb += vec3(workShadowRays, workSegments, workEvaluations);
        workCameraSteps = workBounceSteps = workShadowSteps = 0;
        workShadowRays = workSegments = workEvaluations = 0;
        if (++completed == wanted)
            break;
        beginSample(pixel, uint(estimate.a + moments.a));
        path = startPath(vec2(pixel) + sample2D(SAMPLE_PIXEL), cameraContaining, cameraClear);
        continue;
#endif
        vec3 value = path.radiance;
        if (isValidSample(value)) {
            float count = estimate.a + 1.0;
            vec3 deviation = value - estimate.rgb;
            estimate.rgb += deviation / count;
            moments.rgb += deviation * (value - estimate.rgb);
            estimate.a = count;
#if FEATURE_BUFFERS
            accumulateFeatures(path, count);
#endif
        } else {
            moments.a += 1.0;
        }
        if (++completed == wanted)
            break;
        beginSample(pixel, uint(estimate.a + moments.a));
        path = startPath(vec2(pixel) + sample2D(SAMPLE_PIXEL), cameraContaining, cameraClear);
    }
}
