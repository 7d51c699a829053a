#pragma once
// The settings that take one of a few named values (--sampler, --fresnel, --masking, --kernel,
// --tone-curve, the shader variant),
// each with its names, its codes and what each value means, in one place. The command line,
// the files' metadata and --help read the names from here, and the shader receives the codes
// as generated #defines (PREFIX_NAME, settings/SettingsTable.h writes them): no code is
// written twice.
#include <array>
#include <cstddef>

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

// The dielectric's reflectance (shaders/modules/fresnel.glsl).
enum class FresnelModel { Schlick, Exact };

// Smith's masking-shadowing of the microfacet materials (shaders/modules/microfacet.glsl):
// height-correlated (Heitz 2014, the default) or the separable product G1(wo) G1(wi), which
// renderers such as Mitsuba 3 use; the second only to compare with them.
enum class MaskingModel { HeightCorrelated, Separable };

// Which GPU kernel drives the path tracer (--kernel): both run the same per-pixel code
// (shaders/modules/path_tracer_main.glsl), so they give a pixel the same samples; they differ
// in how the GPU is asked to run it, and so in speed, device by device. Which one Automatic
// stands for on a renderer is render/KernelChoice.h's decision.
enum class PathKernel {
    // The kernel measured faster on the renderer at hand (render::automaticKernel).
    Automatic,
    // A full-screen triangle's fragments (OpenGL 3.3): fragment_kernel.glsl.
    Fragment,
    // A compute dispatch (OpenGL 4.3): compute_kernel.glsl.
    Compute,
};

// Where a path's random decisions come from (shaders/modules/sampler.glsl): every one from
// the sample's own random stream, or the first bounces' from Owen-scrambled Sobol points.
enum class SamplerKind { Independent, Sobol };

// The curve that maps exposed radiance to the pictures' display values (the tone-mapped
// outputs and the window; shaders/modules/tone_map.frag and film/ToneCurve.h compute each).
enum class ToneCurveKind { Clamp, Hable, Aces, Agx, Neutral };

template <typename Enum>
struct Choice {
    Enum value;
    const char* name;     // on the command line and in files
    const char* meaning;  // for --help; empty where the option's own help says it
};

// Choices<E>::values lists every value of E in the order of its codes (a value's code is its
// enumerator's number), and glslPrefix names its #defines; nullptr where the shader never
// sees E. Only declared: an enumeration used as a setting without a list fails to compile.
template <typename Enum>
struct Choices;

template <>
struct Choices<ShaderVariant> {
    static constexpr const char* glslPrefix = nullptr;  // it shapes the code, never read
    static constexpr std::array<Choice<ShaderVariant>, 4> values = {{
        {ShaderVariant::Specialized, "specialized", ""},
        {ShaderVariant::General, "general", ""},
        {ShaderVariant::FeaturesOnly, "features-only", ""},
        {ShaderVariant::ShapesOnly, "shapes-only", ""},
    }};
};

template <>
struct Choices<FresnelModel> {
    static constexpr const char* glslPrefix = "FRESNEL_";
    static constexpr std::array<Choice<FresnelModel>, 2> values = {{
        {FresnelModel::Schlick, "schlick", "Schlick's approximation (the seed's)"},
        {FresnelModel::Exact, "exact", "the exact dielectric equations"},
    }};
};

template <>
struct Choices<SamplerKind> {
    static constexpr const char* glslPrefix = "SAMPLER_";
    static constexpr std::array<Choice<SamplerKind>, 2> values = {{
        {SamplerKind::Independent, "independent", "random numbers for every decision"},
        {SamplerKind::Sobol, "sobol",
         "Owen-scrambled Sobol points for the pixel and the first four bounces"},
    }};
};

template <>
struct Choices<MaskingModel> {
    static constexpr const char* glslPrefix = "MASKING_";
    static constexpr std::array<Choice<MaskingModel>, 2> values = {{
        {MaskingModel::HeightCorrelated, "correlated", "height-correlated Smith"},
        {MaskingModel::Separable, "separable", "G1 G1, as Mitsuba 3 has it"},
    }};
};

template <>
struct Choices<PathKernel> {
    static constexpr const char* glslPrefix = nullptr;  // it picks the kernel, never read
    static constexpr std::array<Choice<PathKernel>, 3> values = {{
        {PathKernel::Automatic, "auto",
         "the one measured faster on this renderer (--features says which and why)"},
        {PathKernel::Fragment, "fragment", "a full-screen triangle"},
        {PathKernel::Compute, "compute", "OpenGL 4.3"},
    }};
};

template <>
struct Choices<ToneCurveKind> {
    static constexpr const char* glslPrefix = "TONE_CURVE_";
    static constexpr std::array<Choice<ToneCurveKind>, 5> values = {{
        {ToneCurveKind::Clamp, "clamp", "linear, clipped at 1"},
        {ToneCurveKind::Hable, "hable",
         "John Hable's filmic curve, white at 11.2 (the original program's)"},
        {ToneCurveKind::Aces, "aces", "Narkowicz's fit of the ACES filmic curve"},
        {ToneCurveKind::Agx, "agx", "AgX (Sobotka; Wrensch's minimal fit), hues kept"},
        {ToneCurveKind::Neutral, "neutral",
         "Khronos PBR Neutral: base colours shown as they are up to 0.76"},
    }};
};

// The code the shader sees for `value`.
template <typename Enum>
constexpr int choiceCode(Enum value)
{
    return static_cast<int>(value);
}

// Each list holds every value once, in code order: the code is the position.
template <typename Enum>
constexpr bool listedInCodeOrder()
{
    for (std::size_t i = 0; i < Choices<Enum>::values.size(); ++i)
        if (choiceCode(Choices<Enum>::values[i].value) != static_cast<int>(i))
            return false;
    return true;
}
static_assert(listedInCodeOrder<ShaderVariant>() && listedInCodeOrder<FresnelModel>() &&
                  listedInCodeOrder<SamplerKind>() && listedInCodeOrder<MaskingModel>() &&
                  listedInCodeOrder<PathKernel>() && listedInCodeOrder<ToneCurveKind>(),
              "each choice list names every value in the order of its codes");

}  // namespace settings
