#pragma once
#include <cstdint>

namespace settings {

// How the fragment shader is built for a scene.
enum class ShaderVariant {
    // Only the features the scene uses, and its shapes as straight-line generated code.
    Specialized,
    // Every feature, and the shapes interpreted from uniforms (`--no-specialize`).
    General,
    // The two halves of specialisation on their own, so that benchmarks can tell what
    // each one buys: only the features the scene uses but shapes interpreted, and every
    // feature but shapes generated.
    FeaturesOnly,
    ShapesOnly,
};

enum class FresnelModel { Schlick, Exact };

// Where a path's random decisions come from (shaders/modules/sampler.glsl): every one from
// the sample's own random stream, or the first bounces' from Owen-scrambled Sobol points.
enum class SamplerKind { Independent, Sobol };

// Every setting that trades accuracy for time, and the environment switch. All are uniforms
// except the two that shape the shader (variant, switchableEnvironment): changing one never
// recompiles. Defaults are the seed's choices where it made one.
struct RenderSettings {
    // A hit is accepted when the distance is below this fraction of the ray cone's width.
    // Rays passing that close to a surface count as meeting it, which dilates silhouettes
    // and occluders: 0.25 leaves a bias of about 1.5 % in the worst classic scene (mirrors
    // and glass, scene 2) where 0.5 left 4 %, for 5-10 % more time (docs/ACCURACY.md).
    float hitTolerance = 0.25f;
    int maxMarchSteps = 512;
    // Keinert et al.'s omega; 1 turns over-relaxation off.
    float overRelaxation = 1.2f;
    // Every sphere-tracing step is multiplied by this (at most 1): below 1 the steps are
    // conservative, for distance functions that overestimate and declare no @lipschitz.
    float stepScale = 1.0f;
    // Scattering events after the camera ray (the seed: 16 path vertices).
    int maxBounces = 16;
    // Scattering events before Russian roulette may end a path (the seed: 4).
    int russianRouletteDepth = 4;
    bool multipleImportanceSampling = true;
    // Rays skip the objects they cannot come near (shaders/modules/ray_culling.glsl). Exact:
    // it changes the time a march takes, not what it meets.
    bool rayCulling = true;
    FresnelModel dielectricFresnel = FresnelModel::Schlick;
    SamplerKind sampler = SamplerKind::Sobol;
    // Rays that escape see the scene's environment; off, they see black. Takes effect only
    // in a shader that reads the environment from a uniform (switchableEnvironment).
    bool environmentLight = true;
    ShaderVariant variant = ShaderVariant::Specialized;
    // The shader reads the environment's kind from a uniform instead of building it in, so
    // that environmentLight can change without a recompile (the window's panel).
    bool switchableEnvironment = false;
    // Find surfaces by exact intersection instead of sphere tracing, for the shapes that
    // have a closed form (shaders/modules/ray_queries_exact.glsl): the reference that the
    // tests and docs/ACCURACY.md judge the sphere tracer's geometric error against.
    bool exactGeometry = false;
    // Count work instead of light (ShaderBuild::profileCounters), for bench_throughput.
    bool profileCounters = false;
    // March boxes, cylinders and disks (ShaderBuild::marchBoxesCylindersAndDisks), for
    // tests of the sphere tracer against exact intersection.
    bool marchBoxesCylindersAndDisks = false;
    std::uint64_t seed = 1;
    // Paths per pixel in one frame (one draw); the running mean is updated after each, so
    // the result is the same as that many frames of one.
    int samplesPerFrame = 1;
    // A frame is drawn in horizontal bands sized to take about this long each, so that a
    // render can stop (or a window respond) between them; 0 draws whole frames at once.
    double secondsPerBand = 0.25;
};

}  // namespace settings
