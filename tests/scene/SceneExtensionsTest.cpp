// Our extensions of the format: comments, the environment keyword, CSG blocks, transforms,
// and the declarations a user SDF file may make. A classic file never needs them.
#include "scene/SceneTestSupport.h"

#include <glm/gtc/epsilon.hpp>

#include <cctype>
#include <fstream>
#include <variant>

namespace scene_tests {
namespace {

using namespace scene;

::testing::AssertionResult near(const glm::vec3& actual, const glm::vec3& expected)
{
    if (glm::all(glm::epsilonEqual(actual, expected, 1e-5f)))
        return ::testing::AssertionSuccess();
    return ::testing::AssertionFailure()
           << "expected (" << expected.x << ", " << expected.y << ", " << expected.z << "), got ("
           << actual.x << ", " << actual.y << ", " << actual.z << ")";
}

const Shape& onlyShape(const Scene& scene)
{
    return scene.objects.at(0).shape;
}

// --- comments ---------------------------------------------------------------------------

TEST(SceneComments, RunFromTheHashToTheEndOfTheLine)
{
    const Scene scene = parse("# camera\n0 0 5 # eye\n0 0 0#target, no space\n0 1 0\n45\n"
                              "0 # no lights\n1 solid 1 1 1 # # #\n1 0 0 0 0 0 0 0\n"
                              "1 0 0 sphere 0 0 0 1#\n");
    EXPECT_TRUE(near(scene.camera.target, glm::vec3(0.0f)));
    ASSERT_EQ(scene.objects.size(), 1u);
}

TEST(SceneComments, HideWhatWouldBeAnError)
{
    EXPECT_NO_THROW(parse(sceneWithObjects(1, "0 0 sphere 0 0 0 1 # 0 0 sphere 0 0 0 -1\n")));
}

// --- environment --------------------------------------------------------------------------

std::string withEnvironment(const std::string& keyword)
{
    return keyword + "\n" + sceneWithObjects(1, "0 0 sphere 0 0 0 1\n");
}

TEST(SceneEnvironment, NoneMeansBlack)
{
    EXPECT_EQ(parse(withEnvironment("environment none")).environment.kind, EnvironmentKind::None);
}

TEST(SceneEnvironment, SkyIsTheDefaultGradient)
{
    EXPECT_EQ(parse(withEnvironment("environment sky")).environment.kind, EnvironmentKind::Sky);
}

TEST(SceneEnvironment, ThreeNumbersAreAConstantRadiance)
{
    const Environment environment = parse(withEnvironment("environment 1 0.5 .25")).environment;
    EXPECT_EQ(environment.kind, EnvironmentKind::Constant);
    EXPECT_TRUE(near(environment.color, {1.0f, 0.5f, 0.25f}));
}

TEST(SceneEnvironment, MayStandBetweenSections)
{
    const Scene scene = parse("0 0 5\n0 0 0\n0 1 0\n45\nenvironment 2 2 2\n0\n1 solid 1 1 1\n"
                              "1 0 0 0 0 0 0 0\n1 0 0 sphere 0 0 0 1\n");
    EXPECT_EQ(scene.environment.kind, EnvironmentKind::Constant);
    EXPECT_TRUE(near(scene.environment.color, glm::vec3(2.0f)));
}

TEST(SceneEnvironment, MayFollowTheLastObject)
{
    const Scene scene = parse(sceneWithObjects(1, "0 0 sphere 0 0 0 1\nenvironment none\n"));
    EXPECT_EQ(scene.environment.kind, EnvironmentKind::None);
}

TEST(SceneEnvironment, NegativeRadianceIsAnError)
{
    EXPECT_TRUE(failsAt("environment 1 -1 1\n" + sceneWithObjects(1, "0 0 sphere 0 0 0 1\n"), 1,
                        "-1", "environment radiance"));
}

TEST(SceneEnvironment, UnknownWordIsAnError)
{
    EXPECT_TRUE(failsAt("environment cloudy\n", 1, "cloudy", "environment radiance"));
}

TEST(SceneEnvironment, AMapIsAFileFoundAsATextureIsWithAnIntensityAndARotation)
{
    const Environment environment =
        parse(withEnvironment("environment map sky-sun.hdr rotate -30 intensity 0.5")).environment;
    EXPECT_EQ(environment.kind, EnvironmentKind::Map);
    EXPECT_EQ(environment.mapName, "sky-sun.hdr");
    EXPECT_EQ(environment.mapPath, FileLookup::dataDirectory() / "textures" / "sky-sun.hdr");
    EXPECT_EQ(environment.intensity, 0.5f);
    EXPECT_EQ(environment.rotationDegrees, -30.0f);
    EXPECT_EQ(environment.line, 1);
    EXPECT_TRUE(environment.importanceSampled);
}

TEST(SceneEnvironment, AMapTakesIntensityOneAndNoRotationUnlessTold)
{
    const Scene scene =
        parse(sceneWithObjects(1, "0 0 sphere 0 0 0 1\nenvironment map sky-sun.hdr\n"));
    EXPECT_EQ(scene.environment.intensity, 1.0f);
    EXPECT_EQ(scene.environment.rotationDegrees, 0.0f);
}

TEST(SceneEnvironment, AMissingMapFileIsAnErrorNamingTheFoldersSearched)
{
    EXPECT_TRUE(failsAt("\nenvironment map nowhere.exr\n", 2, "nowhere.exr",
                        "an existing environment map file (looked in "));
}

TEST(SceneEnvironment, ANegativeMapIntensityIsAnError)
{
    EXPECT_TRUE(failsAt("environment map sky-sun.hdr intensity -1\n", 1, "-1",
                        "environment map intensity"));
}

TEST(SceneEnvironment, AMapOptionGivenTwiceIsAnError)
{
    EXPECT_TRUE(failsAt("environment map sky-sun.hdr rotate 10 rotate 20\n", 1, "rotate",
                        "'rotate' only once"));
}

// --- CSG blocks ---------------------------------------------------------------------------

const CsgNode& csgOf(const Scene& scene)
{
    return std::get<CsgNode>(onlyShape(scene).geometry);
}

struct CsgSpelling {
    const char* written;
    CsgOperator op;
    float parameter;
};

class CsgBlock : public ::testing::TestWithParam<CsgSpelling> {};

TEST_P(CsgBlock, ParsesToItsOperatorAndParameter)
{
    const CsgSpelling spelling = GetParam();
    const Scene scene = parse(sceneWithObjects(1, std::string("0 0 ") + spelling.written +
                                                      " { sphere 0 0 0 1 box 1 0 0 1 1 1 }\n"));
    const CsgNode& node = csgOf(scene);
    EXPECT_EQ(node.op, spelling.op) << spelling.written;
    EXPECT_FLOAT_EQ(node.parameter, spelling.parameter);
    ASSERT_EQ(node.children.size(), 2u);
    EXPECT_TRUE(std::holds_alternative<Sphere>(node.children[0].geometry));
    EXPECT_TRUE(std::holds_alternative<Box>(node.children[1].geometry));
}

INSTANTIATE_TEST_SUITE_P(
    Operator, CsgBlock,
    ::testing::Values(
        CsgSpelling{"union", CsgOperator::Union, 0.0f},
        CsgSpelling{"intersection", CsgOperator::Intersection, 0.0f},
        CsgSpelling{"difference", CsgOperator::Difference, 0.0f},
        CsgSpelling{"smooth_union exp 8", CsgOperator::SmoothUnion, 8.0f},
        CsgSpelling{"smooth_intersection exp 4", CsgOperator::SmoothIntersection, 4.0f},
        CsgSpelling{"smooth_difference exp 16", CsgOperator::SmoothDifference, 16.0f},
        CsgSpelling{"smooth_union poly 0.3", CsgOperator::PolynomialSmoothUnion, 0.3f},
        CsgSpelling{"smooth_intersection poly 0.2", CsgOperator::PolynomialSmoothIntersection,
                    0.2f},
        CsgSpelling{"smooth_difference poly 0.1", CsgOperator::PolynomialSmoothDifference, 0.1f}),
    [](const ::testing::TestParamInfo<CsgSpelling>& info) {
        std::string name = info.param.written;
        for (char& c : name)
            if (!std::isalnum(static_cast<unsigned char>(c)))
                c = '_';
        return name;
    });

TEST(CsgBlocks, NestAndTakeAnyNumberOfChildren)
{
    const Scene scene = parse(sceneWithObjects(
        1, "0 0 difference {\n  union { sphere 0 0 0 1 sphere 1 0 0 1 sphere 2 0 0 1 }\n"
           "  intersection { box 0 0 0 1 1 1 sphere 0 0 0 1.2 }\n}\n"));
    const CsgNode& node = csgOf(scene);
    ASSERT_EQ(node.children.size(), 2u);
    EXPECT_EQ(std::get<CsgNode>(node.children[0].geometry).children.size(), 3u);
    EXPECT_EQ(std::get<CsgNode>(node.children[1].geometry).op, CsgOperator::Intersection);
}

TEST(CsgBlocks, BracesMayTouchWords)
{
    const Scene scene = parse(sceneWithObjects(1, "0 0 union{sphere 0 0 0 1 sphere 1 0 0 1}\n"));
    EXPECT_EQ(csgOf(scene).children.size(), 2u);
}

TEST(CsgBlocks, FewerThanTwoChildrenIsAnError)
{
    EXPECT_TRUE(failsAt(sceneWithObjects(1, "0 0 union {\n sphere 0 0 0 1\n}\n"), 15, "}",
                        "at least two shapes inside 'union'"));
}

TEST(CsgBlocks, UnclosedBlockNamesTheLineItOpened)
{
    EXPECT_TRUE(failsAt(sceneWithObjects(1, "0 0 union {\nsphere 0 0 0 1\nsphere 1 0 0 1\n"), 15,
                        "", "'}' closing the 'union' opened on line 13"));
}

TEST(CsgBlocks, UnknownSmoothKindIsAnError)
{
    EXPECT_TRUE(failsAt(sceneWithObjects(1, "0 0 smooth_union cubic 2 { sphere 0 0 0 1 "
                                            "sphere 1 0 0 1 }\n"),
                        13, "cubic", "exp (sharpness k) or poly (radius)"));
}

TEST(CsgBlocks, ExponentialSharpnessMustBePositive)
{
    EXPECT_TRUE(failsAt(sceneWithObjects(1, "0 0 smooth_union exp 0 { sphere 0 0 0 1 "
                                            "sphere 1 0 0 1 }\n"),
                        13, "0", "sharpness"));
}

// --- errors inside nested CSG blocks -------------------------------------------------------

// One object whose shape is `line` two blocks deep, on line 17 of the file.
std::string twoBlocksDeep(const std::string& line)
{
    return sceneWithObjects(1, "0 0 union {\n"          // 13
                               "  sphere 0 0 0 1\n"     // 14
                               "  difference {\n"       // 15
                               "    box 0 0 0 1 1 1\n"  // 16
                               "    " +
                                   line +
                                   "\n"     // 17
                                   "  }\n"  // 18
                                   "}\n");  // 19
}

// One object whose shape is `line` three blocks deep, on line 19 of the file, after one
// other shape in the innermost block (opened on line 17).
std::string threeBlocksDeep(const std::string& line)
{
    return sceneWithObjects(1, "0 0 smooth_union exp 4 {\n"  // 13
                               "  sphere 0 0 0 1\n"          // 14
                               "  union {\n"                 // 15
                               "    box 0 0 0 1 1 1\n"       // 16
                               "    intersection {\n"        // 17
                               "      sphere 0 0 0 1.2\n"    // 18
                               "      " +
                                   line +
                                   "\n"       // 19
                                   "    }\n"  // 20
                                   "  }\n"    // 21
                                   "}\n");    // 22
}

TEST(NestedCsgErrors, LayoutsAreValidAroundASoundShape)
{
    EXPECT_NO_THROW(parse(twoBlocksDeep("sphere 0 0 0 0.5")));
    EXPECT_NO_THROW(parse(threeBlocksDeep("cylinder 0 0 0 0.5 1")));
}

TEST(NestedCsgErrors, WordForANumberTwoBlocksDeepNamesItsLineAndToken)
{
    EXPECT_TRUE(
        failsAt(twoBlocksDeep("sphere 0 0 zero 1"), 17, "zero", "a number (sphere centre, z)"));
}

TEST(NestedCsgErrors, WordForANumberThreeBlocksDeepNamesItsLineAndToken)
{
    EXPECT_TRUE(
        failsAt(threeBlocksDeep("sphere 0 0 zero 1"), 19, "zero", "a number (sphere centre, z)"));
}

TEST(NestedCsgErrors, NegativeRadiusThreeBlocksDeepNamesItsLineAndToken)
{
    EXPECT_TRUE(failsAt(threeBlocksDeep("cylinder 0 0 0 -0.5 1"), 19, "-0.5",
                        "a positive number (cylinder radius)"));
}

TEST(NestedCsgErrors, StrayTokenThreeBlocksDeepNamesEveryEnclosingBlock)
{
    EXPECT_TRUE(failsAt(threeBlocksDeep("7"), 19, "7",
                        "an object type for object 1 of 1, inside 'smooth_union', inside "
                        "'union', inside 'intersection'"));
}

TEST(NestedCsgErrors, SmoothParameterTwoBlocksDeepNamesItsLineAndToken)
{
    EXPECT_TRUE(failsAt(twoBlocksDeep("smooth_difference poly -0.1 { sphere 0 0 0 1 "
                                      "box 0 0 0 1 1 1 }"),
                        17, "-0.1", "a number of at least 0 (smooth-min blend radius)"));
}

TEST(NestedCsgErrors, ZeroRotationAxisThreeBlocksDeepNamesTheAxisFirstToken)
{
    // The angle, read before the axis can be judged, stands on the next line.
    EXPECT_TRUE(failsAt(threeBlocksDeep("rotate 0 0 0\n      45 box 0 0 0 1 1 1"), 19, "0",
                        "a rotation axis that is not zero"));
}

TEST(NestedCsgErrors, MissingUserSdfThreeBlocksDeepNamesItsShaderFile)
{
    EXPECT_TRUE(failsAt(threeBlocksDeep("no_such_sdf 0 0 0"), 19, "no_such_sdf",
                        "a user SDF with a shader file no_such_sdf.glsl"));
}

TEST(NestedCsgErrors, LoneShapeThreeBlocksDeepNamesTheInnermostBlockAndItsLine)
{
    EXPECT_TRUE(failsAt(threeBlocksDeep(""), 20, "}",
                        "at least two shapes inside 'intersection' (opened on line 17)"));
}

TEST(NestedCsgErrors, FileEndingThreeBlocksDeepNamesTheInnermostOpenBlock)
{
    const std::string truncated = sceneWithObjects(1, "0 0 smooth_union exp 4 {\n"  // 13
                                                      "  sphere 0 0 0 1\n"          // 14
                                                      "  union {\n"                 // 15
                                                      "    box 0 0 0 1 1 1\n"       // 16
                                                      "    intersection {\n"        // 17
                                                      "      sphere 0 0 0 1.2\n"    // 18
                                                      "      box 0 0 0 1 1 1\n");   // 19
    EXPECT_TRUE(failsAt(truncated, 19, "", "'}' closing the 'intersection' opened on line 17"));
}

// --- transforms ---------------------------------------------------------------------------

TEST(Transforms, TranslateMovesTheShapeAndKeepsItsGeometry)
{
    const Scene scene = parse(sceneWithObjects(1, "0 0 translate 1 2 3 sphere 0 0 0 1\n"));
    const Shape& shape = onlyShape(scene);
    ASSERT_TRUE(shape.transform.has_value());
    EXPECT_FLOAT_EQ(std::get<Sphere>(shape.geometry).radius, 1.0f);
    EXPECT_TRUE(near(applyTransform(*shape.transform, {1.0f, 0.0f, 0.0f}), {2.0f, 2.0f, 3.0f}));
}

TEST(Transforms, RotateTurnsAboutTheAxisByDegreesRightHanded)
{
    const Scene scene = parse(sceneWithObjects(1, "0 0 rotate 0 2 0 90 box 0 0 0 1 1 1\n"));
    const Shape& shape = onlyShape(scene);
    ASSERT_TRUE(shape.transform.has_value());
    EXPECT_TRUE(near(applyTransform(*shape.transform, {1.0f, 0.0f, 0.0f}), {0.0f, 0.0f, -1.0f}))
        << "90 degrees about +y takes +x to -z";
}

TEST(Transforms, ScaleIsUniformAboutTheOrigin)
{
    const Scene scene = parse(sceneWithObjects(1, "0 0 scale 2 torus 1 0 0 1 0.5\n"));
    const Shape& shape = onlyShape(scene);
    ASSERT_TRUE(shape.transform.has_value());
    EXPECT_FLOAT_EQ(shape.transform->scale, 2.0f);
    EXPECT_TRUE(near(applyTransform(*shape.transform, {1.0f, 1.0f, 0.0f}), {2.0f, 2.0f, 0.0f}));
}

TEST(Transforms, WrittenOutermostFirstApplyInnermostFirst)
{
    const Scene scene =
        parse(sceneWithObjects(1, "0 0 translate 1 0 0 scale 2 rotate 0 0 1 90 sphere 0 0 0 1\n"));
    const Shape& shape = onlyShape(scene);
    ASSERT_TRUE(shape.transform.has_value());
    // (1, 0, 0) turned to (0, 1, 0), doubled, then moved by +x.
    EXPECT_TRUE(near(applyTransform(*shape.transform, {1.0f, 0.0f, 0.0f}), {1.0f, 2.0f, 0.0f}));
}

TEST(Transforms, ApplyToCsgBlocksAndInsideThem)
{
    const Scene scene = parse(sceneWithObjects(
        1, "0 0 scale 0.5 union { translate 0 1 0 sphere 0 0 0 1  box 0 0 0 1 1 1 }\n"));
    const Shape& shape = onlyShape(scene);
    ASSERT_TRUE(shape.transform.has_value());
    const CsgNode& node = std::get<CsgNode>(shape.geometry);
    ASSERT_TRUE(node.children[0].transform.has_value());
    EXPECT_FALSE(node.children[1].transform.has_value());
}

TEST(Transforms, NonPositiveScaleIsAnError)
{
    EXPECT_TRUE(failsAt(sceneWithObjects(1, "0 0 scale -2 sphere 0 0 0 1\n"), 13, "-2", "scale"));
}

TEST(Transforms, ZeroRotationAxisIsAnError)
{
    EXPECT_TRUE(failsAt(sceneWithObjects(1, "0 0 rotate 0 0 0 30 sphere 0 0 0 1\n"), 13, "0",
                        "rotation axis"));
}

TEST(Transforms, EmissiveSphereLightMovesWithItsTransform)
{
    const Scene scene =
        parse(sceneWithObjects(1, "0 1 translate 0 2 0 scale 3 sphere 1 0 0 0.5\n"));
    const auto lights = sphereLights(scene);
    ASSERT_EQ(lights.size(), 1u);
    EXPECT_TRUE(near(lights[0].center, {3.0f, 2.0f, 0.0f}));
    EXPECT_FLOAT_EQ(lights[0].radius, 1.5f);
}

// --- user SDF declarations ------------------------------------------------------------------

// A folder of scene and shader files written by the test, removed afterwards.
class UserSdfFiles : public ::testing::Test {
protected:
    void SetUp() override
    {
        folder_ =
            std::filesystem::temp_directory_path() /
            ("scene-tests-" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) +
             "-" + ::testing::UnitTest::GetInstance()->current_test_info()->name());
        std::filesystem::create_directories(folder_);
    }
    void TearDown() override { std::filesystem::remove_all(folder_); }

    void write(const std::string& name, const std::string& text) const
    {
        std::ofstream(folder_ / name) << text;
    }

    UserSdf parseUserSdf(const std::string& name) const
    {
        write("scene.in", sceneWithObjects(1, "0 0 " + name + " 1 2 3\n"));
        const Scene scene = parseSceneFile(folder_ / "scene.in");
        return std::get<UserSdf>(scene.objects.at(0).shape.geometry);
    }

    // Each declaration, as the second line of a blob's file, is refused with an error naming
    // that file and line.
    void expectEachRefusedOnLineTwo(std::initializer_list<const char*> declarations) const
    {
        for (const char* declaration : declarations) {
            write("blob.glsl", std::string("// A blob.\n") + declaration +
                                   "float blob(vec3 p, vec3 x) { return length(p - x) - 1.0; }\n");
            try {
                parseUserSdf("blob");
                ADD_FAILURE() << declaration << " was accepted";
            } catch (const SceneError& error) {
                EXPECT_EQ(error.file(), (folder_ / "blob.glsl").string()) << declaration;
                EXPECT_EQ(error.line(), 2) << declaration;
            }
        }
    }

    std::filesystem::path folder_;
};

TEST_F(UserSdfFiles, DeclareABoundAndALipschitzFactorInComments)
{
    write("blob.glsl", "// A blob.\n// @bound 2.5\n// @lipschitz 3\n"
                       "float blob(vec3 p, vec3 x) { return length(p - x) - 1.0; }\n");
    const UserSdf user = parseUserSdf("blob");
    ASSERT_TRUE(user.boundingRadius.has_value());
    EXPECT_FLOAT_EQ(*user.boundingRadius, 2.5f);
    EXPECT_FLOAT_EQ(user.lipschitz, 3.0f);
}

TEST_F(UserSdfFiles, WithoutDeclarationsAreUnboundedAndOneLipschitz)
{
    write("blob.glsl", "float blob(vec3 p, vec3 x) { return length(p - x) - 1.0; }\n");
    const UserSdf user = parseUserSdf("blob");
    EXPECT_FALSE(user.boundingRadius.has_value());
    EXPECT_FLOAT_EQ(user.lipschitz, 1.0f);
}

TEST_F(UserSdfFiles, AreFoundBesideTheSceneBeforeTheProjectShaders)
{
    write("knot.glsl",
          "// @bound 0.75\nfloat knot(vec3 p, vec3 x) { return length(p - x) - 0.5; }\n");
    const UserSdf user = parseUserSdf("knot");
    EXPECT_EQ(user.sourcePath, folder_ / "knot.glsl");
    EXPECT_FLOAT_EQ(user.boundingRadius.value_or(0.0f), 0.75f);
}

TEST_F(UserSdfFiles, AreFoundInAShadersFolderBesideTheScene)
{
    std::filesystem::create_directories(folder_ / "shaders");
    write("shaders/blob.glsl", "float blob(vec3 p, vec3 x) { return length(p - x) - 1.0; }\n");
    EXPECT_EQ(parseUserSdf("blob").sourcePath, folder_ / "shaders" / "blob.glsl");
}

TEST_F(UserSdfFiles, DeclarationWrittenAgainstTheCommentMarkIsStillRead)
{
    write("blob.glsl",
          "//@bound 1.5\nfloat blob(vec3 p, vec3 x) { return length(p - x) - 1.0; }\n");
    EXPECT_FLOAT_EQ(parseUserSdf("blob").boundingRadius.value_or(0.0f), 1.5f);
}

TEST_F(UserSdfFiles, UnusableDeclarationIsAnErrorNamingTheShaderFileAndLine)
{
    write("blob.glsl", "// A blob.\n// @lipschitz 0.5\n"
                       "float blob(vec3 p, vec3 x) { return length(p - x) - 1.0; }\n");
    try {
        parseUserSdf("blob");
        FAIL() << "a Lipschitz factor below 1 was accepted";
    } catch (const SceneError& error) {
        EXPECT_EQ(error.file(), (folder_ / "blob.glsl").string());
        EXPECT_EQ(error.line(), 2);
        EXPECT_EQ(error.token(), "0.5");
    }
}

TEST_F(UserSdfFiles, DeclareHullPlanesThatTheSurfaceLiesBehind)
{
    write("blob.glsl", "// @bound 2\n// @hull 0 0 2 1.5\n// @hull -1 0 0 0.25\n"
                       "float blob(vec3 p, vec3 x) { return length(p - x) - 1.0; }\n");
    const UserSdf user = parseUserSdf("blob");
    ASSERT_EQ(user.hullPlanes.size(), 2u);
    // Unit normals; the offset measured along the declared normal (1.5 / |(0, 0, 2)|).
    EXPECT_EQ(user.hullPlanes[0], glm::vec4(0.0f, 0.0f, 1.0f, -0.75f));
    EXPECT_EQ(user.hullPlanes[1], glm::vec4(-1.0f, 0.0f, 0.0f, -0.25f));
}

TEST_F(UserSdfFiles, AHullPlaneThatIsNotFourNumbersIsAnErrorNamingTheShaderFileAndLine)
{
    expectEachRefusedOnLineTwo({"// @hull 0 0 1\n", "// @hull 0 0 1 2 3\n", "// @hull 0 0 0 1\n",
                                "// @hull 0 0 one 1\n", "// @hull\n"});
}

TEST_F(UserSdfFiles, DeclareTheFunctionThatIntersectsTheShape)
{
    write("blob.glsl", "// @intersect blobIntersect\n"
                       "float blob(vec3 p, vec3 x) { return length(p - x) - 1.0; }\n");
    EXPECT_EQ(parseUserSdf("blob").intersectFunction.value_or(""), "blobIntersect");
}

TEST_F(UserSdfFiles, AnIntersectionThatIsNoGlslNameIsAnErrorNamingTheShaderFileAndLine)
{
    expectEachRefusedOnLineTwo({"// @intersect 2blob\n", "// @intersect\n",
                                "// @intersect blob extra\n", "// @intersect gl_blob\n"});
}

TEST(UserSdfDeclarations, TheProjectKnotReturnsItsOwnSafeBound)
{
    const Scene scene = parseSceneFile(testing_support::sourceDirectory() / "scenes" / "scene4.in");
    const auto& knot = std::get<UserSdf>(scene.objects.at(0).shape.geometry);
    EXPECT_EQ(knot.name, "knot");
    EXPECT_FLOAT_EQ(knot.lipschitz, 1.0f);
    EXPECT_TRUE(knot.boundingRadius.has_value());
}

TEST(UserSdfDeclarations, ReservedWordsCannotNameAUserSdf)
{
    for (const char* word :
         {"sphere", "polyhedron", "box", "torus", "cone", "cylinder", "disk", "union",
          "intersection", "difference", "smooth_union", "translate", "rotate", "scale"})
        EXPECT_TRUE(isReservedShapeWord(word)) << word;
    EXPECT_FALSE(isReservedShapeWord("knot"));
}

}  // namespace
}  // namespace scene_tests

namespace scene_tests {
namespace {

// --- rough finishes (GGX) -----------------------------------------------------------------

// One white ball with the given finishes (the object takes finish 0), written on line 6.
std::string withFinishes(int count, const std::string& finishes)
{
    return "0 0 5\n0 0 0\n0 1 0\n45\n0\n1 solid 1 1 1\n" + std::to_string(count) + "\n" + finishes +
           "\n1\n0 0 sphere 0 0 0 1\n";
}

TEST(RoughFinishes, ConductorTakesItsRoughnessAndThePigmentAsReflectance)
{
    const Scene scene = parse(withFinishes(1, "rough_conductor 0.25"));
    const Finish& finish = scene.finishes.at(0);
    EXPECT_EQ(finish.material(), MaterialKind::RoughConductor);
    EXPECT_EQ(finish.roughness, 0.25f);
    EXPECT_FALSE(finish.conductorIor.has_value());
    EXPECT_FALSE(finish.isEmissive());
}

TEST(RoughFinishes, ConductorMayNameAMetal)
{
    const Finish finish = parse(withFinishes(1, "rough_conductor 0.1 gold")).finishes.at(0);
    ASSERT_TRUE(finish.conductorIor.has_value());
    EXPECT_TRUE(near(finish.conductorIor->eta, findNamedMetal("gold")->ior.eta));
    EXPECT_TRUE(near(finish.conductorIor->k, findNamedMetal("gold")->ior.k));
    // Gold reflects red and green far more than blue at normal incidence.
    const glm::vec3 r0 = normalIncidenceReflectance(*finish.conductorIor);
    EXPECT_GT(r0.r, 0.9f);
    EXPECT_LT(r0.b, 0.4f);
}

TEST(RoughFinishes, ConductorMayGiveItsComplexIndex)
{
    const Finish finish =
        parse(withFinishes(1, "rough_conductor 0.1 ior 0.2 0.9 1.1  3.9 2.4 2.1")).finishes.at(0);
    ASSERT_TRUE(finish.conductorIor.has_value());
    EXPECT_TRUE(near(finish.conductorIor->eta, glm::vec3(0.2f, 0.9f, 1.1f)));
    EXPECT_TRUE(near(finish.conductorIor->k, glm::vec3(3.9f, 2.4f, 2.1f)));
}

TEST(RoughFinishes, DielectricTakesItsRoughnessAndIndex)
{
    const Finish finish = parse(withFinishes(1, "rough_dielectric 0.3 1.33")).finishes.at(0);
    EXPECT_EQ(finish.material(), MaterialKind::RoughDielectric);
    EXPECT_EQ(finish.roughness, 0.3f);
    EXPECT_EQ(finish.ior, 1.33f);
}

TEST(RoughFinishes, MixWithClassicFinishesInAnyOrder)
{
    const Scene scene = parse(withFinishes(
        4, "rough_conductor 0.5 copper\n0 0 0 0 0 0 0\nrough_dielectric 0.1 1.5\n0 0 0 0 1 0 0"));
    ASSERT_EQ(scene.finishes.size(), 4u);
    EXPECT_EQ(scene.finishes[0].material(), MaterialKind::RoughConductor);
    EXPECT_EQ(scene.finishes[1].material(), MaterialKind::Lambertian);
    EXPECT_EQ(scene.finishes[2].material(), MaterialKind::RoughDielectric);
    EXPECT_EQ(scene.finishes[3].material(), MaterialKind::Mirror);
}

TEST(RoughFinishes, RoughnessMustBeAboveZeroAndAtMostOne)
{
    EXPECT_TRUE(failsAt(withFinishes(1, "rough_conductor 0"), 8, "0",
                        "a roughness alpha greater than 0 and at most 1"));
    EXPECT_TRUE(failsAt(withFinishes(1, "rough_dielectric 1.5 1.5"), 8, "1.5",
                        "a roughness alpha greater than 0 and at most 1"));
    EXPECT_TRUE(failsAt(withFinishes(1, "rough_conductor -0.1"), 8, "-0.1", "roughness alpha"));
}

TEST(RoughFinishes, AnUnknownMetalIsNamedWithTheMetalsThereAre)
{
    EXPECT_TRUE(failsAt(withFinishes(1, "rough_conductor 0.1 gld"), 8, "gld",
                        "a metal (gold, silver, copper"));
}

TEST(RoughFinishes, DielectricIndexMustBePositiveAndNotOne)
{
    EXPECT_TRUE(failsAt(withFinishes(1, "rough_dielectric 0.1 1"), 8, "1",
                        "a positive index of refraction other than 1"));
    EXPECT_TRUE(failsAt(withFinishes(1, "rough_dielectric 0.1 0"), 8, "0",
                        "a positive index of refraction other than 1"));
}

TEST(RoughFinishes, AConductorsComplexIndexNeedsAPositiveEta)
{
    EXPECT_TRUE(failsAt(withFinishes(1, "rough_conductor 0.1 ior 0 1 1 1 1 1"), 8, "0",
                        "a positive index of refraction eta"));
}

TEST(RoughFinishes, AMisspeltKeywordIsReadAsAClassicFinishAndNamesTheKeywords)
{
    EXPECT_TRUE(failsAt(withFinishes(1, "rough_conductr 0.1"), 8, "rough_conductr",
                        "or a finish keyword: rough_conductor or rough_dielectric"));
}

TEST(RoughFinishes, EmitNothingSoCannotMakeALight)
{
    const Scene scene = parse(withFinishes(1, "rough_dielectric 0.2 1.5"));
    EXPECT_TRUE(sphereLights(scene).empty());
}

// --- the thin lens --------------------------------------------------------------------------

std::string withCamera(const std::string& camera)
{
    return camera + "\n0\n1 solid 1 1 1\n1 0 0 0 0 0 0 0\n1 0 0 sphere 0 0 0 1\n";
}

TEST(ThinLensCamera, FollowsTheFieldOfView)
{
    const Scene scene = parse(withCamera("0 0 5\n0 0 0\n0 1 0\n45 lens 0.1 4.5"));
    ASSERT_TRUE(scene.camera.lens.has_value());
    EXPECT_EQ(scene.camera.lens->apertureRadius, 0.1f);
    EXPECT_EQ(scene.camera.lens->focusDistance, 4.5f);
}

TEST(ThinLensCamera, AbsentIsThePinhole)
{
    EXPECT_FALSE(parse(withCamera("0 0 5\n0 0 0\n0 1 0\n45")).camera.lens.has_value());
}

TEST(ThinLensCamera, ApertureZeroIsThePinhole)
{
    EXPECT_FALSE(parse(withCamera("0 0 5\n0 0 0\n0 1 0\n45 lens 0 3")).camera.lens.has_value());
}

TEST(ThinLensCamera, NeedsANonNegativeApertureAndAPositiveFocusDistance)
{
    EXPECT_TRUE(
        failsAt(withCamera("0 0 5\n0 0 0\n0 1 0\n45 lens -1 3"), 4, "-1", "lens aperture radius"));
    EXPECT_TRUE(
        failsAt(withCamera("0 0 5\n0 0 0\n0 1 0\n45 lens 0.1 0"), 4, "0", "lens focus distance"));
    EXPECT_TRUE(
        failsAt(withCamera("0 0 5\n0 0 0\n0 1 0\n45 lens 0.1"), 5, "0", "lens focus distance"));
}

}  // namespace
}  // namespace scene_tests
