// generateSceneShaderCode: the per-ray culling it plans for a scene (ray_culling.glsl), the
// objects it leaves out of marches for exact intersection, and the kinds' codes it defines.
// Which bounds a scene's pieces get, and what numbers stand for them, is structure the host
// decides, read here from the plan (shadergen/SceneShaderPlan.h); whether the rays then meet
// the same surfaces is tested by rendering (RayCullingTest.cpp).
#include "shadergen/SceneShaderGenerator.h"
#include "scene/SceneParser.h"
#include "scene/SceneTestSupport.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <regex>
#include <stdexcept>
#include <vector>

namespace scene_tests {
namespace {

using settings::ShaderVariant;
using shadergen::generateSceneShaderCode;
using shadergen::SceneShaderCode;

// Specialised whatever the scene's weight: these tests judge the specialised plan.
SceneShaderCode specialized(const std::string& objects, int count)
{
    shadergen::ShaderBuild build;
    build.variant = ShaderVariant::Specialized;
    build.shapesByWeight = false;
    return generateSceneShaderCode(parse(sceneWithObjects(count, objects)), build);
}

int occurrences(const std::string& text, const std::string& pattern)
{
    const std::regex expression(pattern);
    return static_cast<int>(std::distance(
        std::sregex_iterator(text.begin(), text.end(), expression), std::sregex_iterator()));
}

// The bounding ball that stands for culling bit `bit` in the plan.
glm::vec4 culledBound(const SceneShaderCode& code, unsigned bit)
{
    for (const shadergen::ObjectPlan& object : code.plan.objects)
        if (object.culling && object.culling->bit == bit)
            return code.shapeParameters.at(object.culling->slot);
    throw std::runtime_error("no ball with bit " + std::to_string(bit) + " planned");
}

int culledObjects(const SceneShaderCode& code)
{
    int count = 0;
    for (const shadergen::ObjectPlan& object : code.plan.objects)
        count += object.culling ? 1 : 0;
    return count;
}

void expectNear(const glm::vec4& actual, const glm::vec4& expected)
{
    for (int i = 0; i < 4; ++i)
        EXPECT_NEAR(actual[i], expected[i], 1e-5f) << "component " << i;
}

// The planes the exact intersection clips by, in object order.
std::vector<glm::vec4> exactClipPlanes(const SceneShaderCode& code)
{
    std::vector<glm::vec4> planes;
    for (const shadergen::ObjectPlan& object : code.plan.objects)
        if (object.exactIntersection.find("clipOutsideHalfSpace") != std::string::npos)
            for (const int slot : object.exactSlots)
                planes.push_back(code.shapeParameters.at(slot));
    return planes;
}

// The text of one generated function, from its signature to its closing brace.
std::string functionBody(const std::string& code, const std::string& signature)
{
    const std::size_t start = code.find(signature);
    if (start == std::string::npos)
        throw std::runtime_error(signature + " not generated");
    return code.substr(start, code.find("\n}\n", start) - start);
}

TEST(RayCulling, PolyhedraAreMetByExactIntersectionInsteadOfMarched)
{
    const SceneShaderCode code = specialized("0 0 polyhedron 3  0 1 0 2  1 0 0 4  0 0 -2 6\n", 1);
    // The planes as the exact clip uses them: unit normals, in world space.
    const std::vector<glm::vec4> planes = exactClipPlanes(code);
    ASSERT_EQ(planes.size(), 3u);
    expectNear(planes[0], {0, 1, 0, 2});
    expectNear(planes[1], {1, 0, 0, 4});
    expectNear(planes[2], {0, 0, -1, 3});
    ASSERT_EQ(code.plan.objects.size(), 1u);
    EXPECT_TRUE(code.plan.objects[0].exact);
    EXPECT_FALSE(code.plan.objects[0].culling)
        << "a polyhedron needs no culling bits: marches leave it out";
    EXPECT_EQ(occurrences(functionBody(code.sceneFunctions, "float sceneDistanceCulled("),
                          R"(shape0\(p\))"),
              0)
        << "the marched distance leaves the polyhedron out";
    EXPECT_EQ(occurrences(functionBody(code.sceneFunctions, "float sceneDistance(vec3 p)"),
                          R"(shape0\(p\))"),
              1)
        << "point queries (which side a ray starts on) still see it";
}

TEST(RayCulling, FiniteObjectsAreCulledByTheirBoundingBalls)
{
    const SceneShaderCode code = specialized("0 0 rounded_box 0 0 0  1 2 2  0.1\n"
                                             "0 0 rounded_box 0 1 0  1.2 1.6 1.5  0.1\n",
                                             2);
    EXPECT_EQ(culledObjects(code), 2);
    expectNear(culledBound(code, 1), {0, 0, 0, 3});
    expectNear(culledBound(code, 2), {0, 1, 0, 2.5f});
}

// The spheres the exact intersection meets, in object order.
std::vector<glm::vec4> exactSpheres(const SceneShaderCode& code)
{
    std::vector<glm::vec4> spheres;
    for (const shadergen::ObjectPlan& object : code.plan.objects)
        if (object.exactIntersection.find("exactSphere(") != std::string::npos)
            spheres.push_back(code.shapeParameters.at(object.exactSlots.at(0)));
    return spheres;
}

TEST(RayCulling, SpheresAreMetByExactIntersectionInsteadOfMarched)
{
    const SceneShaderCode code =
        specialized("0 0 sphere 1 2 3 0.5\n0 0 translate 1 0 0 scale 2 sphere 0 1 0 0.25\n", 2);
    const std::vector<glm::vec4> spheres = exactSpheres(code);
    ASSERT_EQ(spheres.size(), 2u);
    expectNear(spheres[0], {1, 2, 3, 0.5f});
    expectNear(spheres[1], {1, 2, 0, 0.5f});  // in world space
    EXPECT_EQ(culledObjects(code), 0);
    EXPECT_TRUE(code.plan.objects.at(0).exact && code.plan.objects.at(1).exact)
        << "the marched distance leaves the spheres out";
    EXPECT_FALSE(code.marchesAnything) << "nothing is left to march";
    EXPECT_NE(code.defines.find("#define HAS_MARCHED_OBJECTS 0"), std::string::npos);
}

TEST(RayCulling, ASceneWithAShapeWithoutAClosedFormMarches)
{
    const SceneShaderCode code =
        specialized("0 0 sphere 1 2 3 0.5\n0 0 rounded_box 0 1 0  1 1 1  0.2\n", 2);
    EXPECT_TRUE(code.marchesAnything);
    EXPECT_NE(code.defines.find("#define HAS_MARCHED_OBJECTS 1"), std::string::npos);
}

// A normal backs off the surface where its stencil may reach another object's hidden face
// (sphere_tracing.glsl); with one marched object there is none, and a field whose gradient is
// not unit (a user SDF that returns a safe bound) would pay a second gradient at every hit.
TEST(NormalBackOff, OneMarchedObjectAmongExactOnesAndALightFormsNoUnion)
{
    const SceneShaderCode code = specialized(
        "0 0 rounded_box 0 1 0  1 1 1  0.2\n0 0 polyhedron 1\n 0 1 0 1\n0 1 sphere 0 3 0 0.5\n", 3);
    EXPECT_EQ(code.plan.marchedSurfaceCount, 1);
    EXPECT_NE(code.defines.find("#define HAS_MARCHED_UNION 0"), std::string::npos);
}

TEST(NormalBackOff, TwoMarchedObjectsFormAUnion)
{
    const SceneShaderCode code =
        specialized("0 0 rounded_box 0 1 0  1 1 1  0.2\n0 0 rounded_box 6 0 0  1 1 1  0.2\n", 2);
    EXPECT_EQ(code.plan.marchedSurfaceCount, 2);
    EXPECT_NE(code.defines.find("#define HAS_MARCHED_UNION 1"), std::string::npos);
}

TEST(RayCulling, BoxesCylindersDisksConesAndToriAreMetByExactIntersectionInsteadOfMarched)
{
    const SceneShaderCode code = specialized("0 0 box 0 0 0  1 2 2\n"
                                             "0 0 cylinder 4 0 0  1 2\n"
                                             "0 0 disk 0 3 0  0 1 0  1\n"
                                             "0 0 cone 0 2 -6  1 0.5\n"
                                             "0 0 rotate 0 1 0 30 box 8 0 0  1 1 1\n"
                                             "0 0 torus 0 1 0  2 0.5\n",
                                             6);
    ASSERT_EQ(code.plan.objects.size(), 6u);
    const char* calls[] = {"exactBox(", "exactCappedCylinder(", "exactDisk(", "exactCone(",
                           "exactBox(", "exactTorus("};
    for (std::size_t i = 0; i < code.plan.objects.size(); ++i) {
        EXPECT_TRUE(code.plan.objects[i].exact) << "object " << i;
        EXPECT_NE(code.plan.objects[i].exactIntersection.find(calls[i]), std::string::npos)
            << "object " << i;
        EXPECT_FALSE(code.plan.objects[i].culling) << "object " << i << ": never marched";
    }
    EXPECT_NE(code.plan.objects[4].exactIntersection.find("toLocalPoint(origin"), std::string::npos)
        << "a transformed box is met in its own frame";
    EXPECT_FALSE(code.marchesAnything) << "nothing is left to march";
    EXPECT_NE(code.defines.find("#define HAS_MARCHED_OBJECTS 0"), std::string::npos);
}

TEST(RayCulling, AUserSdfIsMetExactlyWhereItsFileDeclaresAnIntersection)
{
    // scenes/sdf/csg.glsl declares `// @intersect csgIntersect`; scenes/sdf/knot.glsl declares none.
    const SceneShaderCode code = specialized("0 0 csg 0 0 0\n0 0 knot 0 0 -8\n", 2);
    ASSERT_EQ(code.plan.objects.size(), 2u);
    EXPECT_TRUE(code.plan.objects[0].exact);
    EXPECT_NE(code.plan.objects[0].exactIntersection.find("csgIntersect(o, d, "),
              std::string::npos);
    EXPECT_FALSE(code.plan.objects[1].exact);
    EXPECT_TRUE(code.plan.objects[1].culling) << "the knot is marched, culled by its bound";
}

// The hull planes of the piece with culling bit `bit`, in world space.
std::vector<glm::vec4> culledHull(const SceneShaderCode& code, unsigned bit)
{
    for (const shadergen::ObjectPlan& object : code.plan.objects)
        if (object.culling && object.culling->bit == bit) {
            std::vector<glm::vec4> planes;
            for (int k = 0; k < object.culling->hullPlanes; ++k)
                planes.push_back(code.shapeParameters.at(object.culling->hullSlot + k));
            return planes;
        }
    throw std::runtime_error("no piece with bit " + std::to_string(bit) + " planned");
}

TEST(RayCulling, AUserSdfIsCulledByTheHullPlanesItsFileDeclares)
{
    // scenes/sdf/knot.glsl declares the slab |z| <= 2.4 about its position; the second knot is
    // turned a quarter about x and moved, so its slab is |y - 1| <= 2.4 (scaled by 2: 4.8).
    const SceneShaderCode code =
        specialized("0 0 knot 0 0 -8\n0 0 translate 0 1 0 scale 2 rotate 1 0 0 90 knot 0 0 0\n", 2);
    const std::vector<glm::vec4> slab = culledHull(code, 1);
    ASSERT_EQ(slab.size(), 2u);
    expectNear(slab[0], {0, 0, 1, -2.4f + 8.0f});
    expectNear(slab[1], {0, 0, -1, -2.4f - 8.0f});
    const std::vector<glm::vec4> turned = culledHull(code, 2);
    ASSERT_EQ(turned.size(), 2u);
    expectNear(turned[0], {0, -1, 0, -4.8f + 1.0f});
    expectNear(turned[1], {0, 1, 0, -4.8f - 1.0f});
    const std::string culling = functionBody(code.sceneFunctions, "RayCulling sceneRayCulling(");
    EXPECT_EQ(occurrences(culling, R"(clipChord\(chord, SHAPE_PARAMETER\([0-9]+\), )"), 4)
        << "each plane by a constant slot";
    EXPECT_EQ(occurrences(culling, R"(cullByBall\()"), 0);
}

TEST(RayCulling, AThinTorusIsStillMarched)
{
    const SceneShaderCode code = specialized("0 0 torus 0 1 0  2 0.1\n", 1);
    EXPECT_FALSE(code.plan.objects.at(0).exact)
        << "float32 leaves the quartic of a torus this thin too few digits";
    EXPECT_TRUE(code.marchesAnything);
}

TEST(RayCulling, AShapeInsideACsgNodeIsStillMarched)
{
    const SceneShaderCode code = specialized("0 0 union { box 0 0 0 1 1 1\n"
                                             "  cylinder 0 2 0 0.5 1 }\n",
                                             1);
    EXPECT_FALSE(code.plan.objects.at(0).exact);
    EXPECT_TRUE(code.marchesAnything);
}

SceneShaderCode exactReference(const std::string& objects, int count)
{
    shadergen::ShaderBuild build{ShaderVariant::Specialized};
    build.exactGeometry = true;
    return generateSceneShaderCode(parse(sceneWithObjects(count, objects)), build);
}

TEST(ExactReference, ASharpCsgBlockOfShapesWithAClosedFormIsWalkedOverItsLeavesCrossings)
{
    const SceneShaderCode code =
        exactReference("0 0 translate 0 1 0 difference {\n"
                       "  intersection { box 0 0 0 1 1 1  sphere 0 0 0 1.3 }\n"
                       "  rotate 1 0 0 90 cylinder 0 0 0 0.5 2\n"
                       "}\n",
                       1);
    EXPECT_EQ(occurrences(code.exactFunctions, R"(bool exactCsgCrossing0\()"), 1);
    EXPECT_EQ(
        occurrences(code.exactFunctions, R"(exactCsgCrossing0\(origin, direction, tMin, 0, hit\))"),
        1)
        << "exactSceneIntersect meets the object by its walk";
    EXPECT_EQ(occurrences(code.exactFunctions, R"(exact(Box|Sphere|CappedCylinder)\()"), 3)
        << "each of the three leaves is met by its own closed form";
}

TEST(ExactReference, ASmoothedCsgBlockIsRefusedWithItsFileAndLine)
{
    try {
        exactReference("0 0 sphere 0 0 0 1\n"
                       "0 0 smooth_union poly 0.2 { box 0 0 0 1 1 1  sphere 0 1 0 0.6 }\n",
                       2);
        FAIL() << "a smoothed block has no exact intersection";
    } catch (const std::runtime_error& error) {
        EXPECT_NE(std::string(error.what()).find(kFileName + ":14: --exact-geometry"),
                  std::string::npos)
            << error.what();
        EXPECT_NE(std::string(error.what()).find("smoothed operator"), std::string::npos)
            << error.what();
    }
}

TEST(ExactReference, ACsgBlockWithADiskIsRefused)
{
    // A disk has no inside for the walk to classify.
    EXPECT_THROW(exactReference("0 0 union { box 0 0 0 1 1 1  disk 0 2 0  0 1 0  1 }\n", 1),
                 std::runtime_error);
}

TEST(RayCulling, TransformedPolyhedronIsMetByItsPlanesInWorldSpace)
{
    // The solid y <= 0, scaled by 2, turned 90 degrees about z (the solid x >= 0, or
    // -x <= 0) and moved by 1 along x: the solid x >= 1.
    const SceneShaderCode code =
        specialized("0 0 translate 1 0 0 rotate 0 0 1 90 scale 2 polyhedron 1  0 1 0 0\n", 1);
    const std::vector<glm::vec4> planes = exactClipPlanes(code);
    ASSERT_EQ(planes.size(), 1u);
    expectNear(planes[0], {-1, 0, 0, 1});
}

TEST(RayCulling, ObjectsWithoutABoundMakeEveryRayMarchToTheFarDistance)
{
    // A CSG difference of two half-spaces is unbounded.
    const SceneShaderCode code = specialized("0 0 difference {\n"
                                             "  polyhedron 1  0 1 0 0\n"
                                             "  polyhedron 1  1 0 0 0\n"
                                             "}\n",
                                             1);
    EXPECT_EQ(culledObjects(code), 0);
    EXPECT_FALSE(code.plan.everyObjectCulled);
    EXPECT_EQ(occurrences(code.sceneFunctions, R"(escapeDistance = FLOAT_MAX)"), 1)
        << "the plan's decision is written into sceneRayCulling";
}

TEST(RayCulling, PiecesBeyondThirtyTwoAreNeverCulled)
{
    std::string objects;
    for (int i = 0; i < 40; ++i)
        objects += "0 0 rounded_box " + std::to_string(3 * i) + " 0 0  1 1 1  0.2\n";
    const SceneShaderCode code = specialized(objects, 40);
    EXPECT_EQ(culledObjects(code), 32);
    EXPECT_FALSE(code.plan.everyObjectCulled) << "rounded boxes without a bit may be met anywhere";
}

TEST(RayCulling, EditingAValueChangesOnlyUniforms)
{
    const SceneShaderCode before = specialized("0 0 polyhedron 1  0 1 0 2\n"
                                               "0 0 sphere 1 2 3 0.5\n"
                                               "0 0 cone 0 2 0  3 4\n"
                                               "0 0 rounded_box 0 1 0  1 1 1  0.2\n",
                                               4);
    const SceneShaderCode after = specialized("0 0 polyhedron 1  0 1 0.5 7\n"
                                              "0 0 sphere -1 0 3 2\n"
                                              "0 0 cone 1 1 1  1 2\n"
                                              "0 0 rounded_box 1 2 0  2 1 1  0.3\n",
                                              4);
    EXPECT_EQ(before.sceneFunctions, after.sceneFunctions);
    EXPECT_EQ(before.defines, after.defines);
    EXPECT_NE(before.shapeParameters, after.shapeParameters);
}

TEST(ScenePlan, EachObjectsFunctionNamesItsObjectAndSceneFileLine)
{
    const SceneShaderCode code = specialized("0 0 sphere 0 0 0 1\n"
                                             "0 0 union { box 0 0 0 1 1 1\n"
                                             "  torus 0 0 0 1 0.25 }\n",
                                             2);
    ASSERT_EQ(code.plan.objects.size(), 2u);
    // sceneWithObjects writes the objects from line 13 on.
    EXPECT_EQ(code.plan.objects[0].line, 13);
    EXPECT_EQ(code.plan.objects[1].line, 14);
    for (const shadergen::ObjectPlan& object : code.plan.objects) {
        const std::string comment = "// object " + std::to_string(object.object) + ", " +
                                    kFileName + ":" + std::to_string(object.line) + ": ";
        const std::size_t function = code.sceneFunctions.find("float " + object.function + "(");
        ASSERT_NE(function, std::string::npos) << object.function;
        EXPECT_EQ(code.sceneFunctions.rfind(comment, function),
                  code.sceneFunctions.rfind("\n//", function) + 1)
            << object.function << " is not under \"" << comment << "...\"";
    }
    EXPECT_NE(code.sceneFunctions.find(kFileName + ":14: union"), std::string::npos);
}

TEST(RayCulling, GeneralShaderCullsNothing)
{
    const SceneShaderCode code = generateSceneShaderCode(
        parse(sceneWithObjects(1, "0 0 sphere 0 0 0 1\n")), {ShaderVariant::General});
    EXPECT_EQ(occurrences(code.sceneFunctions, R"(cull(ByBall|ByHalfSpace)\()"), 0);
}

}  // namespace
}  // namespace scene_tests

namespace scene_tests {
namespace {

// Every kind's code reaches every shader as a #define, with the value the host packs, and
// every kind's feature switch is defined (0 or 1).
TEST(KindCodesInTheShader, EveryKindHasItsDefineAndEverySwitchIsSet)
{
    const scene::Scene scene = parse(sceneWithObjects(1, "0 0 sphere 0 0 0 1"));
    for (const ShaderVariant variant : {ShaderVariant::Specialized, ShaderVariant::General}) {
        const SceneShaderCode code = generateSceneShaderCode(scene, {variant});
        auto defines = [&](const std::string& name, int value) {
            return code.defines.find("#define " + name + " " + std::to_string(value) + "\n") !=
                   std::string::npos;
        };
        for (const auto& op : scene::csgOperatorDescriptions())
            EXPECT_TRUE(defines(scene::codeName(op), op.code)) << scene::codeName(op);
        for (const auto& material : scene::materialDescriptions()) {
            EXPECT_TRUE(defines(scene::codeName(material), material.code))
                << scene::codeName(material);
            if (material.featureSwitch != nullptr) {
                EXPECT_NE(code.defines.find(std::string("#define ") + material.featureSwitch),
                          std::string::npos)
                    << material.featureSwitch;
            }
        }
        for (const auto& pigment : scene::pigmentDescriptions()) {
            EXPECT_TRUE(defines(scene::codeName(pigment), pigment.code))
                << scene::codeName(pigment);
            if (pigment.featureSwitch != nullptr) {
                EXPECT_NE(code.defines.find(std::string("#define ") + pigment.featureSwitch),
                          std::string::npos)
                    << pigment.featureSwitch;
            }
        }
        for (const auto& environment : scene::environmentDescriptions()) {
            EXPECT_TRUE(defines(scene::codeName(environment), environment.code))
                << scene::codeName(environment);
            if (environment.featureSwitch != nullptr) {
                EXPECT_NE(code.defines.find(std::string("#define ") + environment.featureSwitch),
                          std::string::npos)
                    << environment.featureSwitch;
            }
        }
        for (const auto& light : scene::lightDescriptions()) {
            EXPECT_TRUE(defines(scene::codeName(light), light.code)) << scene::codeName(light);
            EXPECT_NE(code.defines.find(std::string("#define ") + light.featureSwitch),
                      std::string::npos)
                << light.featureSwitch;
        }
    }
}

// A scene without an environment map compiles none of its code: its switches are off (the
// map's code in environment.glsl and lights.glsl stands under them: KindTablesTest).
TEST(EnvironmentMapInTheShader, OnlyASceneWithAMapHasItsCodeAndItsLightIsTheLast)
{
    auto defined = [](const SceneShaderCode& code, const std::string& line) {
        return code.defines.find("#define " + line + "\n") != std::string::npos;
    };
    const SceneShaderCode without = specialized("0 1 sphere 0 0 0 1", 1);
    EXPECT_TRUE(defined(without, "HAS_ENVIRONMENT_MAP 0")) << without.defines;
    EXPECT_TRUE(defined(without, "HAS_ENVIRONMENT_LIGHT 0")) << without.defines;
    EXPECT_TRUE(defined(without, "ENVIRONMENT_LIGHT_INDEX -1")) << without.defines;
    for (const ShaderVariant variant : {ShaderVariant::Specialized, ShaderVariant::General}) {
        const SceneShaderCode with = generateSceneShaderCode(
            parse("environment map sky-sun.hdr\n" +
                  sceneWithObjects(2, "0 1 sphere 0 0 0 1\n0 0 sphere 3 0 0 1\n")),
            {variant});
        EXPECT_TRUE(defined(with, "HAS_ENVIRONMENT_MAP 1")) << with.defines;
        EXPECT_TRUE(defined(with, "HAS_ENVIRONMENT_LIGHT 1")) << with.defines;
        EXPECT_TRUE(defined(with, "LIGHT_COUNT 2")) << "the emissive sphere and the map";
        EXPECT_TRUE(defined(with, "ENVIRONMENT_LIGHT_INDEX 1")) << with.defines;
    }
}

TEST(KindCodesInTheShader, TheGeneralShaderCombinesByEveryOperatorsCode)
{
    const SceneShaderCode code = generateSceneShaderCode(
        parse(sceneWithObjects(1, "0 0 sphere 0 0 0 1")), {ShaderVariant::General});
    const auto& operators = scene::csgOperatorDescriptions();
    // The last operator is combine's fallthrough; every other one has its branch.
    for (std::size_t i = 0; i + 1 < operators.size(); ++i)
        EXPECT_NE(code.sceneFunctions.find("if (op == " + scene::codeName(operators[i]) +
                                           ")\n        return " + operators[i].function),
                  std::string::npos)
            << operators[i].identifier;
    EXPECT_NE(code.sceneFunctions.find(std::string("    return ") + operators.back().function),
              std::string::npos);
}

}  // namespace
// Scenes whose shapes weigh more than kMostShapeCodeWeight get the general shader's shapes
// (found through the hierarchy over the objects); the scenes the project ships stay
// specialised, their images as they were.
TEST(ShaderVariantForScene, TheProjectsScenesStaySpecialisedAndLargeScenesDoNot)
{
    namespace fs = std::filesystem;
    for (const fs::directory_entry& entry :
         fs::directory_iterator(fs::path(RAYTRACER_SOURCE_DIR) / "scenes")) {
        if (entry.path().extension() != ".in")
            continue;
        scene::Scene scene;
        try {
            scene = scene::parseSceneFile(entry.path());
        } catch (const std::exception& error) {
            // A scene that names a file this machine lacks (an environment map of Blender's).
            std::printf("%-40s not read here: %s\n", entry.path().filename().c_str(), error.what());
            continue;
        }
        std::printf("%-40s %3zu objects, shape code weight %3zu\n", entry.path().filename().c_str(),
                    scene.objects.size(), shadergen::shapeCodeWeight(scene));
        EXPECT_EQ(shadergen::variantForScene(scene, ShaderVariant::Specialized),
                  ShaderVariant::Specialized)
            << entry.path();
    }
    std::string spheres;
    for (int i = 0; i <= static_cast<int>(shadergen::kMostShapeCodeWeight); ++i)
        spheres += "0 0 sphere " + std::to_string(i) + " 0 0 0.4\n";
    const scene::Scene large =
        parse(sceneWithObjects(static_cast<int>(shadergen::kMostShapeCodeWeight) + 1, spheres));
    EXPECT_EQ(shadergen::shapeCodeWeight(large), shadergen::kMostShapeCodeWeight + 1);
    EXPECT_EQ(shadergen::variantForScene(large, ShaderVariant::Specialized),
              ShaderVariant::FeaturesOnly);
    EXPECT_EQ(shadergen::variantForScene(large, ShaderVariant::ShapesOnly), ShaderVariant::General);
    EXPECT_EQ(shadergen::variantForScene(large, ShaderVariant::General), ShaderVariant::General);
    const SceneShaderCode code = generateSceneShaderCode(large);
    EXPECT_EQ(code.variant, ShaderVariant::FeaturesOnly);
    EXPECT_NE(code.defines.find("#define HIERARCHY_UNBOUNDED_COUNT 0\n"), std::string::npos);
}

}  // namespace scene_tests
