#pragma once
// Where the next samples go when a render aims at an error instead of a time
// (--target-error): the samples each tile of pixels should reach for the image to get there
// at the least cost.
//
// The image's squared error is the mean of its pixels' variances of the mean, s_p^2 / n_p
// (film/ConvergenceEstimate.h). For a given sum of n_p it is least when n_p is in
// proportion to s_p (a Lagrange multiplier: every pixel's last sample then lowers the error
// by as much), so pixel p should reach
//
//     n_p = s_p * mean(s) / (E * mean radiance)^2,
//
// where its variance of the mean is s_p * (E mean radiance)^2 / mean(s) and the image's is
// (E mean radiance)^2: the target. Uniform sampling spends mean(s^2) / mean(s)^2 times as
// many samples for the same error, a factor that is large where noise is uneven (caustics,
// glass, penumbrae) and 1 where it is even.
//
// The s_p are estimates, from the pixel's own samples, and a pixel whose samples understate
// its noise (its rare bright paths not met yet) would stop early with an error the image's
// estimate cannot see. So shares follow max(s_p, the mean s of p's 3x3 neighbourhood), with
// the factor recomputed so that the plan still lands on the target:
//
//     n_p = planned_p * mean(s^2 / planned) / (E * mean radiance)^2.
//
// Pixels are planned in square tiles: on a GPU, and on llvmpipe's 8-wide lanes, neighbouring
// pixels run in lockstep, so a pixel stopping alone saves nothing while its neighbours go on;
// a whole tile stopping does. Each tile takes the largest of its pixels' counts (a pixel
// whose noise is underestimated by a neighbour's better-sampled tail is covered), and no
// pixel stops before minimumSamples: a rare bright path never drawn in a pixel's first
// samples would make it look converged.
#include "film/Accumulation.h"

#include <vector>

namespace film {

struct AdaptiveSampling {
    double targetError = 0.01;  // relative RMSE, ConvergenceEstimate.h
    int minimumSamples = 32;
    int tileSize = 1;     // pixels along a tile's side; 1 plans every pixel alone
    int sampleLimit = 0;  // most samples a pixel may take (--spp); 0: no limit
};

// The sample count each tile's pixels stop at, for the shader (path_tracer_main.glsl):
// `columns` x `rows` tiles, rows bottom first as GL's are, tile (i, j) covering pixels
// [i tileSize, (i + 1) tileSize) x [j tileSize, (j + 1) tileSize) counted from the bottom left.
struct TileSampleTargets {
    int tileSize = 0;
    int columns = 0;
    int rows = 0;
    std::vector<float> samples;  // per tile, row by row
};

struct AdaptivePlan {
    TileSampleTargets targets;
    // Tiles with a pixel below its tile's count.
    int activeTiles = 0;
};

// The plan for `accumulation` (kept and discarded samples count alike: a discarded sample
// still took its path's time).
AdaptivePlan planAdaptiveSampling(const Accumulation& accumulation,
                                  const AdaptiveSampling& sampling);

}  // namespace film
