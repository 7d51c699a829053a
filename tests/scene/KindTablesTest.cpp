// The tables of CSG operators, materials, pigments, environments and lights
// (scene/CsgOperators.h, Materials.h, Pigments.h, Environments.h, Lights.h), walked row by row: what the compiler cannot
// check about a new kind (its words, its GLSL, its place in the shaders' dispatch) fails
// here. The primitives have their own walk (PrimitiveKindsTest.cpp).
#include "scene/KindCodes.h"
#include "scene/Lights.h"
#include "scene/SceneTestSupport.h"

#include <gtest/gtest.h>

#include <cctype>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace scene_tests {
namespace {

using namespace scene;

std::string readModule(const std::string& name)
{
    std::ifstream file(testing_support::sourceDirectory() / "shaders" / "modules" / name);
    std::stringstream text;
    text << file.rdbuf();
    return text.str();
}

bool uses(const std::string& glsl, const std::string& name)
{
    return std::regex_search(glsl, std::regex("\\b" + name + "\\b"));
}

// A scene of one object whose shape is `shape`, with pigment `pigment` and the given finish.
std::string oneObject(const std::string& shape, const std::string& pigment = "solid 1 1 1",
                      const std::string& finish = "0 0 0 0 0 0 1",
                      const std::string& environment = "")
{
    return "0 0 5\n0 0 0\n0 1 0\n45\n0\n1 " + pigment + "\n1 " + finish + "\n" + environment +
           "\n1 0 0 " + shape + "\n";
}

TEST(KindCodes, NameTheKindInCapitalsWithWordsSplit)
{
    EXPECT_EQ(codeName("MATERIAL_", "BlinnPhong"), "MATERIAL_BLINN_PHONG");
    EXPECT_EQ(codeName("CSG_", "Union"), "CSG_UNION");
}

TEST(KindCodes, NoShaderModuleDeclaresACodeOfItsOwn)
{
    const std::regex copiedCode(
        "const\\s+int\\s+(PRIMITIVE|OPCODE|CSG|MATERIAL|PIGMENT|ENVIRONMENT|LIGHT)_\\w+\\s*=");
    for (const char* module :
         {"csg_operators.glsl", "direct_lighting.glsl", "environment.glsl", "integrator.glsl",
          "lights.glsl", "materials.glsl", "pigments.glsl", "ray_queries_traced.glsl",
          "scene_data.glsl", "sdf_primitives.glsl", "shape_interpreter.glsl"})
        EXPECT_FALSE(std::regex_search(readModule(module), copiedCode))
            << module
            << " writes a kind's code as a number: it must come from the generated "
               "#defines (shadergen/ShaderCodes.h)";
}

// --- CSG operators ----------------------------------------------------------------------

TEST(CsgOperatorKinds, CodesAreTheirPlaceInTheList)
{
    const auto& operators = csgOperatorDescriptions();
    for (std::size_t i = 0; i < operators.size(); ++i) {
        EXPECT_EQ(operators[i].code, static_cast<int>(i)) << operators[i].identifier;
        EXPECT_EQ(static_cast<std::size_t>(operators[i].op), i) << operators[i].identifier;
        EXPECT_EQ(&describe(operators[i].op), &operators[i]) << operators[i].identifier;
    }
}

TEST(CsgOperatorKinds, EachIsParsedFromItsOwnWordsWhichTheParserReserves)
{
    std::set<std::string> spellings;
    for (const CsgOperatorDescription& op : csgOperatorDescriptions()) {
        const std::string words =
            std::string(op.keyword) +
            (op.hasParameter() ? " " + std::string(op.smoothingWord) + " 0.5" : "");
        EXPECT_TRUE(spellings.insert(words).second) << words << " twice";
        EXPECT_TRUE(isReservedShapeWord(op.keyword)) << op.keyword;
        EXPECT_EQ(op.hasParameter(), *op.smoothingWord != '\0') << op.identifier;
        const Scene scene = parse(oneObject(words + " { sphere 0 0 0 1 sphere 1 0 0 1 }"));
        const auto& node = std::get<CsgNode>(scene.objects.at(0).shape.geometry);
        EXPECT_EQ(node.op, op.op) << words;
        EXPECT_EQ(node.parameter, op.hasParameter() ? 0.5f : 0.0f) << words;
    }
}

TEST(CsgOperatorKinds, EachFunctionIsDefinedInCsgOperatorsWithItsOperands)
{
    const std::string glsl = readModule("csg_operators.glsl");
    for (const CsgOperatorDescription& op : csgOperatorDescriptions()) {
        const std::string signature = "float " + std::string(op.function) + "(float a, float b" +
                                      (op.hasParameter() ? ", float " : ")");
        EXPECT_NE(glsl.find(signature), std::string::npos)
            << op.identifier << ": no \"" << signature << "...\" in csg_operators.glsl";
    }
}

// --- materials --------------------------------------------------------------------------

TEST(MaterialKinds, CodesAreTheirPlaceInTheListAndNamesAreDistinct)
{
    std::set<std::string> names;
    const auto& materials = materialDescriptions();
    for (std::size_t i = 0; i < materials.size(); ++i) {
        EXPECT_EQ(materials[i].code, static_cast<int>(i)) << materials[i].name;
        EXPECT_EQ(static_cast<std::size_t>(materials[i].kind), i) << materials[i].name;
        EXPECT_TRUE(names.insert(materials[i].name).second) << materials[i].name << " twice";
    }
}

// The first material is the dispatchers' fallback, in every shader; each other one is
// compiled in by its switch. Each defines, under its prefix and with the others' signatures,
// the functions the generated dispatchers call (shadergen/KindDispatchers.cpp).
TEST(MaterialKinds, EachDefinesItsFunctionsInMaterialsGlslAndAllButTheFallbackHaveASwitch)
{
    const std::string glsl = readModule("materials.glsl");
    const auto& materials = materialDescriptions();
    EXPECT_EQ(materials.front().featureSwitch, nullptr);
    EXPECT_EQ(materials.front().scattering, Scattering::Spread)
        << "the fallback answers bsdfEvaluate and bsdfPdf";
    for (std::size_t i = 0; i < materials.size(); ++i) {
        const MaterialDescription& material = materials[i];
        if (i > 0) {
            ASSERT_NE(material.featureSwitch, nullptr) << material.name;
            EXPECT_NE(glsl.find(std::string("#if ") + material.featureSwitch), std::string::npos)
                << material.name << ": materials.glsl never tests " << material.featureSwitch;
        }
        const std::string prefix = material.glslPrefix;
        std::vector<std::string> signatures = {
            "BsdfSample " + prefix + "Sample(Surface s, vec3 wo, float uLobe, vec2 uDirection)"};
        if (material.scattering == Scattering::Spread) {
            signatures.push_back("vec3 " + prefix + "Evaluate(Surface s, vec3 wo, vec3 wi)");
            signatures.push_back("float " + prefix + "Pdf(Surface s, vec3 wo, vec3 wi)");
        }
        for (const std::string& signature : signatures)
            EXPECT_NE(glsl.find(signature), std::string::npos)
                << material.name << ": no \"" << signature << "\" in materials.glsl";
    }
}

// A material with a keyword is written with it (and its numbers) in place of the seven
// numbers of a classic finish, and parses into that material; one without is selected by the
// classic numbers alone (Finish::material).
TEST(MaterialKinds, EachKeywordFinishIsParsedFromItsKeywordAndHasAReader)
{
    const std::map<std::string, std::string> numbers = {{"rough_conductor", "0.3"},
                                                        {"rough_dielectric", "0.3 1.5"}};
    std::set<std::string> keywords;
    for (const MaterialDescription& material : materialDescriptions()) {
        if (material.keyword == nullptr) {
            EXPECT_EQ(material.read, nullptr) << material.name;
            EXPECT_EQ(material.model, Model::Classic) << material.name;
            continue;
        }
        EXPECT_NE(material.read, nullptr) << material.name;
        EXPECT_TRUE(keywords.insert(material.keyword).second) << material.keyword << " twice";
        EXPECT_EQ(findFinishKeyword(material.keyword), &material) << material.keyword;
        EXPECT_NE(finishKeywords().find(material.keyword), std::string::npos);
        const auto example = numbers.find(material.keyword);
        ASSERT_NE(example, numbers.end()) << material.keyword << ": this test has no example";
        const Scene scene = parse(
            oneObject("sphere 0 0 0 1", "solid 1 1 1", material.keyword + (" " + example->second)));
        EXPECT_EQ(scene.finishes.at(0).material(), material.kind) << material.keyword;
    }
}

// --- pigments ---------------------------------------------------------------------------

TEST(PigmentKinds, CodesAreTheirPlaceInTheListAndKeywordsAreDistinct)
{
    std::set<std::string> keywords;
    const auto& pigments = pigmentDescriptions();
    for (std::size_t i = 0; i < pigments.size(); ++i) {
        EXPECT_EQ(pigments[i].code, static_cast<int>(i)) << pigments[i].keyword;
        EXPECT_EQ(static_cast<std::size_t>(pigments[i].kind), i) << pigments[i].keyword;
        EXPECT_TRUE(keywords.insert(pigments[i].keyword).second) << pigments[i].keyword;
        EXPECT_EQ(findPigmentKind(pigments[i].keyword), &pigments[i]) << pigments[i].keyword;
        EXPECT_NE(pigmentKeywords().find(pigments[i].keyword), std::string::npos);
    }
}

// Each pigment kind defines its colour function, with pigmentColor's signature, for the
// generated pigmentColor to call; each but the fallback under its switch.
TEST(PigmentKinds, EachDefinesItsColourInPigmentsGlslAndAllButTheFallbackHaveASwitch)
{
    // Signatures are looked for with every run of white space (a wrapped line) as one space.
    std::string glsl;
    for (const char c : readModule("pigments.glsl"))
        if (!std::isspace(static_cast<unsigned char>(c)))
            glsl += c;
        else if (glsl.empty() || glsl.back() != ' ')
            glsl += ' ';
    const auto& pigments = pigmentDescriptions();
    EXPECT_EQ(pigments.front().featureSwitch, nullptr);
    for (std::size_t i = 0; i < pigments.size(); ++i) {
        const PigmentDescription& pigment = pigments[i];
        if (i > 0) {
            ASSERT_NE(pigment.featureSwitch, nullptr) << pigment.keyword;
            EXPECT_NE(glsl.find(std::string("#if ") + pigment.featureSwitch), std::string::npos)
                << pigment.keyword << ": pigments.glsl never tests " << pigment.featureSwitch;
        }
        const std::string signature = std::string("vec3 ") + pigment.glslFunction +
                                      "(int pigment, vec3 p, vec3 n, float footprint, "
                                      "float offSurface, float uPattern)";
        EXPECT_NE(glsl.find(signature), std::string::npos)
            << pigment.keyword << ": no \"" << signature << "\" in pigments.glsl";
    }
}

TEST(PigmentKinds, EachIsParsedFromItsKeyword)
{
    const std::map<std::string, std::string> numbers = {
        {"solid", "1 1 1"}, {"checker", "1 1 1 0 0 0 0.5"}, {"texmap", "brick.ppm 1"}};
    for (const PigmentDescription& pigment : pigmentDescriptions()) {
        const auto example = numbers.find(pigment.keyword);
        ASSERT_NE(example, numbers.end()) << pigment.keyword << ": this test has no example";
        const Scene scene =
            parse(oneObject("sphere 0 0 0 1", pigment.keyword + (" " + example->second)));
        EXPECT_EQ(scene.pigments.at(0).kind, pigment.kind) << pigment.keyword;
    }
}

// --- environments -----------------------------------------------------------------------

TEST(EnvironmentKinds, CodesAreTheirPlaceInTheListAndEachIsParsedFromItsWords)
{
    // What follows each kind's word in a file.
    const std::map<std::string, std::string> arguments = {
        {"none", ""}, {"sky", ""}, {"constant", " 0.5 0.5 0.5"}, {"map", " sky-sun.hdr"}};
    const auto& environments = environmentDescriptions();
    for (std::size_t i = 0; i < environments.size(); ++i) {
        const EnvironmentDescription& environment = environments[i];
        EXPECT_EQ(environment.code, static_cast<int>(i)) << environment.keyword;
        EXPECT_EQ(static_cast<std::size_t>(environment.kind), i) << environment.keyword;
        const auto example = arguments.find(environment.keyword);
        ASSERT_NE(example, arguments.end()) << environment.keyword << ": this test has no example";
        for (const std::string word : {environment.keyword, environment.alias}) {
            if (word.empty())
                continue;
            EXPECT_EQ(findEnvironmentKind(word), &environment) << word;
            const std::string written = "environment " + word + example->second;
            const Scene scene =
                parse(oneObject("sphere 0 0 0 1", "solid 1 1 1", "0 0 0 0 0 0 1", written));
            EXPECT_EQ(scene.environment.kind, environment.kind) << written;
        }
    }
}

// The first environment is the fallback (no radiance); each other one has its case, and a
// kind with a switch has its code under it.
TEST(EnvironmentKinds, EachButTheFallbackHasACaseInEnvironmentGlsl)
{
    const std::string glsl = readModule("environment.glsl");
    const auto& environments = environmentDescriptions();
    EXPECT_EQ(environments.front().featureSwitch, nullptr);
    for (std::size_t i = 1; i < environments.size(); ++i) {
        EXPECT_TRUE(uses(glsl, codeName(environments[i])))
            << environments[i].keyword << ": environment.glsl never tests "
            << codeName(environments[i]);
        if (environments[i].featureSwitch != nullptr) {
            EXPECT_NE(glsl.find(std::string("#if ") + environments[i].featureSwitch),
                      std::string::npos)
                << environments[i].keyword << ": environment.glsl never tests "
                << environments[i].featureSwitch;
        }
    }
}

// --- lights -----------------------------------------------------------------------------

TEST(LightKinds, CodesAreTheirPlaceInTheListAndNamesAreDistinct)
{
    std::set<std::string> names;
    const auto& lights = lightDescriptions();
    for (std::size_t i = 0; i < lights.size(); ++i) {
        EXPECT_EQ(lights[i].code, static_cast<int>(i)) << lights[i].name;
        EXPECT_EQ(static_cast<std::size_t>(lights[i].kind), i) << lights[i].name;
        EXPECT_EQ(&describe(lights[i].kind), &lights[i]) << lights[i].name;
        EXPECT_TRUE(names.insert(lights[i].name).second) << lights[i].name << " twice";
        EXPECT_EQ(codeName(lights[i]), codeName("LIGHT_", lights[i].identifier));
    }
}

// Each kind is compiled in by its switch, and defines, under its prefix and with the others'
// signatures, the functions the generated dispatchers call (render/KindDispatchers.cpp): a
// sampler, and a density where a BSDF-sampled ray can meet it.
TEST(LightKinds, EachDefinesItsFunctionsInLightsGlslUnderItsSwitch)
{
    const std::string glsl = readModule("lights.glsl");
    for (const LightDescription& light : lightDescriptions()) {
        ASSERT_NE(light.featureSwitch, nullptr) << light.name;
        const std::size_t guard = glsl.find(std::string("#if ") + light.featureSwitch);
        EXPECT_NE(guard, std::string::npos)
            << light.name << ": lights.glsl never tests " << light.featureSwitch;
        const std::string prefix = light.glslPrefix;
        std::vector<std::string> signatures = {
            "bool " + prefix +
            "Sample(int light, vec3 p, vec2 u, float selection, out LightSample chosen)"};
        if (light.emitter != Emitter::DeltaPosition)
            signatures.push_back("float " + prefix + "Pdf(int light, vec3 p, vec3 direction)");
        for (const std::string& signature : signatures) {
            const std::size_t at = glsl.find(signature);
            EXPECT_NE(at, std::string::npos)
                << light.name << ": no \"" << signature << "\" in lights.glsl";
            EXPECT_TRUE(at == std::string::npos || (guard != std::string::npos && at > guard))
                << light.name << ": " << signature << " stands before #if " << light.featureSwitch;
        }
    }
}

// One scene with a light of every kind: each kind's lister gives its own lights, the list
// runs kind by kind in table order, and each light's power follows its kind's formula.
TEST(LightKinds, EachListsTheScenesLightsOfItsKindInTableOrder)
{
    const Scene scene = parse("environment map sky-sun.hdr intensity 2\n"
                              "0 0 5\n0 0 0\n0 1 0\n45\n"
                              "2\n1 2 3  4 4 4\n-1 2 3  1 1 1\n"
                              "1 solid 1 1 1\n"
                              "2\n0 0 0 0 0 0 1\n3 3 3 0 0 0 1\n"
                              "3\n0 1 sphere 0 4 0 0.5\n0 0 sphere 0 0 0 1\n"
                              "0 1 sphere 2 4 0 0.25\n");
    const std::vector<Light> lights = sceneLights(scene);
    ASSERT_EQ(lights.size(), 5u);
    const LightKind expected[] = {LightKind::Point, LightKind::Point, LightKind::Sphere,
                                  LightKind::Sphere, LightKind::Environment};
    for (std::size_t i = 0; i < lights.size(); ++i)
        EXPECT_EQ(lights[i].kind, expected[i]) << "light " << i;
    EXPECT_EQ(lights[0].position, glm::vec3(1, 2, 3));
    EXPECT_EQ(lights[2].object, 0);
    EXPECT_EQ(lights[3].object, 2);
    EXPECT_EQ(lights[3].radius, 0.25f);
    EXPECT_EQ(lights[4].emission, glm::vec3(2.0f));
    EXPECT_EQ(lights[4].object, -1);

    constexpr double kPi = 3.14159265358979323846;
    LightPowerContext context;
    context.sceneRadius = 10.0;
    context.environmentIntegral = glm::dvec3(1.0, 2.0, 3.0);
    const std::vector<double> powers = lightPowers(lights, context);
    EXPECT_DOUBLE_EQ(powers[0], 4.0 * kPi * 4.0);
    EXPECT_DOUBLE_EQ(powers[2], 4.0 * kPi * kPi * 0.25 * 3.0);
    EXPECT_DOUBLE_EQ(powers[4], kPi * 100.0 * 2.0 * 2.0)
        << "pi R^2 times the intensity times the map's integral, channels averaged";
}

}  // namespace
}  // namespace scene_tests
