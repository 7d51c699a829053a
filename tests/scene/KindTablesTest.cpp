// The tables of CSG operators, materials, pigments and environments (scene/CsgOperators.h,
// Materials.h, Pigments.h, Environments.h), walked row by row: what the compiler cannot
// check about a new kind (its words, its GLSL, its place in the shaders' dispatch) fails
// here. The primitives have their own walk (PrimitiveKindsTest.cpp).
#include "scene/KindCodes.h"
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
        "const\\s+int\\s+(PRIMITIVE|OPCODE|CSG|MATERIAL|PIGMENT|ENVIRONMENT)_\\w+\\s*=");
    for (const char* module :
         {"csg_operators.glsl", "environment.glsl", "integrator.glsl", "lights.glsl",
          "materials.glsl", "pigments.glsl", "ray_queries_traced.glsl", "scene_data.glsl",
          "sdf_primitives.glsl", "shape_interpreter.glsl"})
        EXPECT_FALSE(std::regex_search(readModule(module), copiedCode))
            << module << " writes a kind's code as a number: it must come from the generated "
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
        const std::string words = std::string(op.keyword) +
                                  (op.hasParameter() ? " " + std::string(op.smoothingWord) + " 0.5"
                                                     : "");
        EXPECT_TRUE(spellings.insert(words).second) << words << " twice";
        EXPECT_TRUE(isReservedShapeWord(op.keyword)) << op.keyword;
        EXPECT_EQ(op.hasParameter(), *op.smoothingWord != '\0') << op.identifier;
        const Scene scene =
            parse(oneObject(words + " { sphere 0 0 0 1 sphere 1 0 0 1 }"));
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
        const Scene scene = parse(oneObject("sphere 0 0 0 1", "solid 1 1 1",
                                            material.keyword + (" " + example->second)));
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
    const auto& environments = environmentDescriptions();
    for (std::size_t i = 0; i < environments.size(); ++i) {
        const EnvironmentDescription& environment = environments[i];
        EXPECT_EQ(environment.code, static_cast<int>(i)) << environment.keyword;
        EXPECT_EQ(static_cast<std::size_t>(environment.kind), i) << environment.keyword;
        for (const std::string word : {environment.keyword, environment.alias}) {
            if (word.empty())
                continue;
            EXPECT_EQ(findEnvironmentKind(word), &environment) << word;
            const std::string written =
                "environment " + word + (environment.hasColour ? " 0.5 0.5 0.5" : "");
            const Scene scene =
                parse(oneObject("sphere 0 0 0 1", "solid 1 1 1", "0 0 0 0 0 0 1", written));
            EXPECT_EQ(scene.environment.kind, environment.kind) << written;
        }
    }
}

// The first environment is the fallback (no radiance); each other one has its case.
TEST(EnvironmentKinds, EachButTheFallbackHasACaseInEnvironmentGlsl)
{
    const std::string glsl = readModule("environment.glsl");
    const auto& environments = environmentDescriptions();
    for (std::size_t i = 1; i < environments.size(); ++i)
        EXPECT_TRUE(uses(glsl, codeName(environments[i])))
            << environments[i].keyword << ": environment.glsl never tests "
            << codeName(environments[i]);
}

}  // namespace
}  // namespace scene_tests
