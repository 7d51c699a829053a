#include "shadergen/KindDispatchers.h"

#include "scene/Lights.h"
#include "scene/Materials.h"
#include "scene/Pigments.h"

#include <sstream>

namespace shadergen {

using namespace scene;

namespace {

// `call` under `#if featureSwitch` when the kind has one.
void guardedCase(std::ostringstream& out, const char* featureSwitch, const std::string& test,
                 const std::string& call)
{
    if (featureSwitch != nullptr)
        out << "#if " << featureSwitch << "\n";
    out << "    if (" << test << ")\n        return " << call << ";\n";
    if (featureSwitch != nullptr)
        out << "#endif\n";
}

// One case per material but the fallback (the deltas left out where `spreadOnly`), then the
// fallback: returned unconditionally where `none` is empty (a sample: every material has
// one), or tested, with `none` the answer for the materials not dispatched (zero for the
// deltas' evaluation and density).
void materialDispatcher(std::ostringstream& out, const std::string& signature,
                        const std::string& suffix, const std::string& arguments, bool spreadOnly,
                        const std::string& none)
{
    const std::vector<MaterialDescription>& materials = materialDescriptions();
    out << signature << "\n{\n";
    // Last row first, the order of the hand-written dispatchers these replaced: the same
    // cases in the same order compile to the same instructions (docs/PERFORMANCE.md).
    for (std::size_t i = materials.size() - 1; i >= 1; --i) {
        const MaterialDescription& material = materials[i];
        if (spreadOnly && material.scattering == Scattering::Delta)
            continue;
        guardedCase(out, material.featureSwitch, "s.material == " + codeName(material),
                    material.glslPrefix + suffix + "(" + arguments + ")");
    }
    const MaterialDescription& fallback = materials.front();
    const std::string fallbackCall = fallback.glslPrefix + suffix + "(" + arguments + ")";
    if (none.empty())
        out << "    return " << fallbackCall << ";\n";
    else
        out << "    if (s.material == " << codeName(fallback) << ")\n        return "
            << fallbackCall << ";\n    return " << none << ";\n";
    out << "}\n\n";
}

}  // namespace

std::string materialDispatchers()
{
    std::ostringstream out;
    out << "// Generated from the material table (scene/Materials.h).\n\n";
    std::string deltaTest;
    for (const MaterialDescription& material : materialDescriptions())
        if (material.scattering == Scattering::Delta)
            deltaTest += (deltaTest.empty() ? "" : " || ") + ("material == " + codeName(material));
    out << "bool isDeltaMaterial(int material)\n{\n    return "
        << (deltaTest.empty() ? "false" : deltaTest) << ";\n}\n\n";
    out << "// f(wo, wi) for the materials that are not deltas (zero for the deltas).\n";
    materialDispatcher(out, "vec3 bsdfEvaluate(Surface s, vec3 wo, vec3 wi)", "Evaluate",
                       "s, wo, wi", true, "vec3(0.0)");
    out << "// The density of bsdfSample's direction wi, for the materials that are not deltas.\n";
    materialDispatcher(out, "float bsdfPdf(Surface s, vec3 wo, vec3 wi)", "Pdf", "s, wo, wi", true,
                       "0.0");
    out << "// `uLobe` chooses between lobes (or reflection and refraction), `uDirection` the\n"
           "// direction within one: both uniform on [0, 1), from the sampler.\n";
    materialDispatcher(out,
                       "BsdfSample bsdfSample(Surface s, vec3 wo, float uLobe, vec2 uDirection)",
                       "Sample", "s, wo, uLobe, uDirection", false, "");
    return out.str();
}

std::string pigmentDispatcher()
{
    const std::vector<PigmentDescription>& pigments = pigmentDescriptions();
    std::ostringstream out;
    out << "// Generated from the pigment table (scene/Pigments.h). The pigment's colour at\n"
           "// surface point p with outward normal n; `footprint` is the ray cone's width there\n"
           "// and `offSurface` how far outside the surface p may lie (0 for a point met on it);\n"
           "// `uPattern`, uniform on [0, 1) from the sampler, makes a random pattern's choice\n"
           "// (a texture's projection): the colour is then right in expectation.\n"
           "// The fallback's colour comes first and unconditionally, so that a record read\n"
           "// the other kinds repeat (the first colour) is read once: llvmpipe runs every\n"
           "// branch some pixel of its 8 takes, each with its own reads.\n"
           "vec3 pigmentColor(int pigment, vec3 p, vec3 n, float footprint, float offSurface,\n"
           "                  float uPattern)\n"
           "{\n";
    const std::string arguments = "(pigment, p, n, footprint, offSurface, uPattern)";
    out << "    vec3 color = " << pigments.front().glslFunction << arguments << ";\n";
    if (pigments.size() > 1)
        out << "    int kind = pigmentKind(pigment);\n";
    for (std::size_t i = 1; i < pigments.size(); ++i) {
        const PigmentDescription& pigment = pigments[i];
        out << "#if " << pigment.featureSwitch << "\n    if (kind == " << codeName(pigment)
            << ")\n        color = " << pigment.glslFunction << arguments << ";\n#endif\n";
    }
    out << "    return color;\n}\n";
    return out.str();
}

// The dispatch over the light kinds compiled in: a test of the light's kind for each, left
// out where the shader has only one kind that could answer (every classic scene), so that the
// kind is not even read there.
std::string lightDispatchers()
{
    const std::vector<LightDescription>& lights = lightDescriptions();
    std::ostringstream out;
    out << "// Generated from the light table (scene/Lights.h).\n\n";
    auto countOf = [&](bool densityOnly) {
        std::string sum;
        for (const LightDescription& light : lights)
            if (!densityOnly || light.emitter != Emitter::DeltaPosition)
                sum += (sum.empty() ? "" : " + ") + std::string(light.featureSwitch);
        return "(" + (sum.empty() ? std::string("0") : sum) + ")";
    };
    out << "#define LIGHT_KINDS_COMPILED " << countOf(false) << "\n";
    out << "#define LIGHT_KINDS_WITH_DENSITY_COMPILED " << countOf(true) << "\n\n";
    auto test = [&](bool densityOnly, const LightDescription& light) {
        return std::string("    if (") +
               (densityOnly ? "LIGHT_KINDS_WITH_DENSITY_COMPILED" : "LIGHT_KINDS_COMPILED") +
               " == 1 || kind == " + codeName(light) + ")\n";
    };
    out << "// Chooses a direction towards `light` from p by its kind's sampler (`selection`: the\n"
           "// light's selection probability; `u` uniform on [0, 1)^2, from the sampler); false\n"
           "// where the kind has none to give (p inside a sphere light).\n"
           "bool lightSample(int light, vec3 p, vec2 u, float selection, out LightSample chosen)\n"
           "{\n"
           "    int kind = lightKind(light);\n";
    for (const LightDescription& light : lights)
        out << "#if " << light.featureSwitch << "\n"
            << test(false, light) << "        return " << light.glslPrefix
            << "Sample(light, p, u, selection, chosen);\n#endif\n";
    out << "    return false;\n}\n\n";
    out << "// The solid-angle density with which light sampling picks `direction` from p,\n"
           "// selection included: what MIS weighs a BSDF-sampled ray that meets `light` against\n"
           "// (never asked of a delta).\n"
           "float lightPdf(int light, vec3 p, vec3 direction)\n{\n"
           "    float pdf = 0.0;\n"
           "    int kind = lightKind(light);\n";
    for (const LightDescription& light : lights)
        if (light.emitter != Emitter::DeltaPosition)
            out << "#if " << light.featureSwitch << "\n"
                << test(true, light) << "        pdf = " << light.glslPrefix
                << "Pdf(light, p, direction);\n#endif\n";
    out << "    return lightSelectionProbability(light) * pdf;\n}\n";
    return out.str();
}

}  // namespace shadergen
