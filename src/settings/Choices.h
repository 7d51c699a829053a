#pragma once
// The settings that take one of a few named values (--sampler, --fresnel, the shader variant),
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

// Where a path's random decisions come from (shaders/modules/sampler.glsl): every one from
// the sample's own random stream, or the first bounces' from Owen-scrambled Sobol points.
enum class SamplerKind { Independent, Sobol };

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
                  listedInCodeOrder<SamplerKind>(),
              "each choice list names every value in the order of its codes");

}  // namespace settings
