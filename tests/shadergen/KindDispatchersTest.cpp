// The shaders' dispatchers over materials, pigments and lights, generated from the kinds' tables
// (shadergen/KindDispatchers.h): every kind reached by its code, under its switch, and nothing
// asked of a delta material that it does not have. That they compile and choose right is
// the render tests' part (furnaces, dielectrics, the regression scenes).
#include "shadergen/KindDispatchers.h"
#include "scene/KindCodes.h"
#include "scene/Lights.h"
#include "scene/Materials.h"
#include "scene/Pigments.h"

#include <gtest/gtest.h>

#include <string>
#include <tuple>

namespace render_tests {
namespace {

using namespace shadergen;
using namespace scene;

// The text of the generated function whose signature starts with `head`, to its closing brace.
std::string functionText(const std::string& glsl, const std::string& head)
{
    const std::size_t start = glsl.find(head);
    if (start == std::string::npos)
        return "";
    const std::size_t end = glsl.find("\n}\n", start);
    return glsl.substr(start, end == std::string::npos ? std::string::npos : end - start + 3);
}

std::string guardedCase(const char* featureSwitch, const std::string& test, const std::string& call)
{
    return std::string("#if ") + featureSwitch + "\n    if (" + test + ")\n        return " + call +
           ";\n#endif\n";
}

TEST(MaterialDispatchers, EveryMaterialButTheFallbackIsSampledByItsCodeUnderItsSwitch)
{
    const std::string sample = functionText(materialDispatchers(), "BsdfSample bsdfSample(");
    ASSERT_FALSE(sample.empty());
    const auto& materials = materialDescriptions();
    for (std::size_t i = 1; i < materials.size(); ++i)
        EXPECT_NE(sample.find(guardedCase(
                      materials[i].featureSwitch, "s.material == " + codeName(materials[i]),
                      std::string(materials[i].glslPrefix) + "Sample(s, wo, uLobe, uDirection)")),
                  std::string::npos)
            << materials[i].name << " in\n"
            << sample;
    EXPECT_NE(sample.find(std::string("    return ") + materials.front().glslPrefix +
                          "Sample(s, wo, uLobe, uDirection);\n}"),
              std::string::npos)
        << "the fallback is not the last, unconditional answer:\n"
        << sample;
}

TEST(MaterialDispatchers, EvaluationAndDensityLeaveOutTheDeltasAndAnswerZeroForThem)
{
    const std::string glsl = materialDispatchers();
    for (const auto& [head, suffix, zero] : {std::tuple<std::string, std::string, std::string>{
                                                 "vec3 bsdfEvaluate(", "Evaluate", "vec3(0.0)"},
                                             {"float bsdfPdf(", "Pdf", "0.0"}}) {
        const std::string function = functionText(glsl, head);
        ASSERT_FALSE(function.empty()) << head;
        for (const MaterialDescription& material : materialDescriptions()) {
            const bool called =
                function.find(material.glslPrefix + suffix + "(s, wo, wi)") != std::string::npos;
            const bool tested = function.find(codeName(material)) != std::string::npos;
            const bool delta = material.scattering == Scattering::Delta;
            EXPECT_EQ(called, !delta) << material.name << " in\n" << function;
            EXPECT_EQ(tested, !delta) << material.name << " in\n" << function;
        }
        EXPECT_NE(function.find("    return " + zero + ";\n}"), std::string::npos) << function;
    }
}

TEST(MaterialDispatchers, IsDeltaMaterialNamesExactlyTheDeltas)
{
    const std::string isDelta =
        functionText(materialDispatchers(), "bool isDeltaMaterial(int material)");
    ASSERT_FALSE(isDelta.empty());
    int deltas = 0;
    for (const MaterialDescription& material : materialDescriptions()) {
        const bool delta = material.scattering == Scattering::Delta;
        deltas += delta ? 1 : 0;
        EXPECT_EQ(isDelta.find("material == " + codeName(material)) != std::string::npos, delta)
            << material.name << " in\n"
            << isDelta;
    }
    EXPECT_GT(deltas, 0) << "mirror and glass are deltas";
}

TEST(PigmentDispatcher, EveryKindButTheFallbackIsColouredByItsCodeUnderItsSwitch)
{
    const std::string color = functionText(pigmentDispatcher(), "vec3 pigmentColor(");
    ASSERT_FALSE(color.empty());
    const auto& pigments = pigmentDescriptions();
    const std::string arguments = "(pigment, p, n, footprint, offSurface, uPattern)";
    EXPECT_NE(color.find("    vec3 color = " + (pigments.front().glslFunction + arguments) + ";"),
              std::string::npos)
        << "the fallback is not the colour every other kind replaces:\n"
        << color;
    for (std::size_t i = 1; i < pigments.size(); ++i)
        EXPECT_NE(color.find(std::string("#if ") + pigments[i].featureSwitch +
                             "\n    if (kind == " + codeName(pigments[i]) + ")\n        color = " +
                             pigments[i].glslFunction + arguments + ";\n#endif\n"),
                  std::string::npos)
            << pigments[i].keyword << " in\n"
            << color;
    EXPECT_NE(color.find("    return color;\n}"), std::string::npos) << color;
}

// Each light kind is sampled by its code under its switch, its test left out where the shader
// has one kind only (every classic scene: the kind is then not even read).
TEST(LightDispatchers, EveryKindIsSampledByItsCodeUnderItsSwitch)
{
    const std::string glsl = lightDispatchers();
    const std::string sample = functionText(glsl, "bool lightSample(");
    ASSERT_FALSE(sample.empty()) << glsl;
    for (const LightDescription& light : lightDescriptions())
        EXPECT_NE(sample.find(std::string("#if ") + light.featureSwitch +
                              "\n    if (LIGHT_KINDS_COMPILED == 1 || kind == " + codeName(light) +
                              ")\n        return " + light.glslPrefix +
                              "Sample(light, p, u, selection, chosen);\n#endif\n"),
                  std::string::npos)
            << light.name << " in\n"
            << sample;
    EXPECT_NE(sample.find("    return false;\n}"), std::string::npos) << sample;
    std::string sum;
    for (const LightDescription& light : lightDescriptions())
        sum += (sum.empty() ? "" : " + ") + std::string(light.featureSwitch);
    EXPECT_NE(glsl.find("#define LIGHT_KINDS_COMPILED (" + sum + ")\n"), std::string::npos) << glsl;
}

// A BSDF-sampled ray never meets a point: lightPdf leaves the deltas out, and includes the
// light's selection probability for every other kind.
TEST(LightDispatchers, TheDensityLeavesOutTheDeltasAndIncludesTheSelection)
{
    const std::string pdf = functionText(lightDispatchers(), "float lightPdf(");
    ASSERT_FALSE(pdf.empty());
    for (const LightDescription& light : lightDescriptions()) {
        const bool delta = light.emitter == Emitter::DeltaPosition;
        EXPECT_EQ(pdf.find(light.glslPrefix + std::string("Pdf(light, p, direction)")) !=
                      std::string::npos,
                  !delta)
            << light.name << " in\n"
            << pdf;
        EXPECT_EQ(pdf.find(codeName(light)) != std::string::npos, !delta) << light.name << " in\n"
                                                                          << pdf;
    }
    EXPECT_NE(pdf.find("    return lightSelectionProbability(light) * pdf;\n}"), std::string::npos)
        << pdf;
}

}  // namespace
}  // namespace render_tests
