// The classic part of the scene format: every classic scene parses, and every value lands
// where ../shared/SCENE_FORMAT.md says.
#include "scene/SceneTestSupport.h"

#include <glm/gtc/epsilon.hpp>

#include <variant>

namespace scene_tests {
namespace {

using namespace scene;

::testing::AssertionResult near(const glm::vec3& actual, const glm::vec3& expected,
                                float tolerance = 1e-6f)
{
    if (glm::all(glm::epsilonEqual(actual, expected, tolerance)))
        return ::testing::AssertionSuccess();
    return ::testing::AssertionFailure()
           << "expected (" << expected.x << ", " << expected.y << ", " << expected.z << "), got ("
           << actual.x << ", " << actual.y << ", " << actual.z << ")";
}

// --- the classic scenes -------------------------------------------------------------------

class ClassicScene : public ::testing::TestWithParam<int> {};

TEST_P(ClassicScene, ParsesWithEveryIndexInRange)
{
    const auto path = testing_support::sourceDirectory() / "scenes" /
                      ("scene" + std::to_string(GetParam()) + ".in");
    Scene scene;
    ASSERT_NO_THROW(scene = parseSceneFile(path)) << path;
    EXPECT_FALSE(scene.objects.empty());
    for (const SceneObject& object : scene.objects) {
        EXPECT_LT(object.pigment, static_cast<int>(scene.pigments.size()));
        EXPECT_LT(object.finish, static_cast<int>(scene.finishes.size()));
    }
}

INSTANTIATE_TEST_SUITE_P(Scene, ClassicScene, ::testing::Range(1, 8),
                         [](const ::testing::TestParamInfo<int>& info) {
                             return "scene" + std::to_string(info.param);
                         });

TEST(ClassicSceneOne, HoldsTheValuesWrittenInIt)
{
    const Scene scene = parseSceneFile(testing_support::sourceDirectory() / "scenes" / "scene1.in");
    EXPECT_TRUE(near(scene.camera.eye, {1.0f, -8.4f, 4.44f}));
    EXPECT_TRUE(near(scene.camera.target, {1.0f, 10.0f, -2.0f}));
    EXPECT_TRUE(near(scene.camera.up, {0.0f, 0.0f, 1.0f}));
    EXPECT_FLOAT_EQ(scene.camera.verticalFieldOfViewDegrees, 35.0f);
    EXPECT_TRUE(scene.pointLights.empty());
    ASSERT_EQ(scene.pigments.size(), 6u);
    EXPECT_EQ(scene.pigments[4].kind, PigmentKind::Checker);
    EXPECT_EQ(scene.pigments[5].kind, PigmentKind::Texture);
    EXPECT_EQ(scene.pigments[5].textureName, "blur.ppm");
    EXPECT_FLOAT_EQ(scene.pigments[5].size, 3.0f);
    ASSERT_EQ(scene.finishes.size(), 3u);
    EXPECT_EQ(scene.finishes[1].material(), MaterialKind::Dielectric);
    EXPECT_FLOAT_EQ(scene.finishes[1].ior, 1.45f);
    ASSERT_EQ(scene.objects.size(), 7u);
    const auto lights = sphereLights(scene);
    ASSERT_EQ(lights.size(), 1u) << "scene 1 has one emissive sphere";
    EXPECT_EQ(lights[0].object, 6);
    EXPECT_TRUE(near(lights[0].center, {1.0f, 4.0f, 3.0f}));
    EXPECT_FLOAT_EQ(lights[0].radius, 0.5f);
    EXPECT_TRUE(near(lights[0].radiance, {40.0f, 40.0f, 40.0f}));
}

// --- each section of the format -----------------------------------------------------------

const char* const kEveryObjectType = R"(-1 .5 8
0 0 -1e1
0 2 0
50
2
1 2 3  10 20 30
-4 5 -6  .5 .25 1e-1
3
solid 0.1 0.2 0.3
checker 1 0 0  0 0 1  0.75
texmap brick.ppm 2.5
4
0 0 0  0 0 0 0
0 0 0  12 0 0 0
0 0 0  12 1 0 0
0 0 0  12 1 1 1.33
9
0 0 sphere 1 2 3 0.5
1 1 polyhedron 2
   0 1 0 1
   2 0 0 -4
2 2 box 1 2 3  0.5 0.25 0.125
0 3 torus -1 0 2  1.5 0.25
1 0 cone 0 3 0  1 0.5
2 1 cylinder 4 0 -1  0.5 2
0 0 disk 0 1 0  0 0 2  3
1 0 twisted_bar 7 8 9
0 0 sphere 0 0 0 1
)";

TEST(SceneFormat, CameraLinesAreEyeTargetUpAndFieldOfView)
{
    const Scene scene = parse(kEveryObjectType);
    EXPECT_TRUE(near(scene.camera.eye, {-1.0f, 0.5f, 8.0f}));
    EXPECT_TRUE(near(scene.camera.target, {0.0f, 0.0f, -10.0f}));
    EXPECT_TRUE(near(scene.camera.up, {0.0f, 2.0f, 0.0f}));
    EXPECT_FLOAT_EQ(scene.camera.verticalFieldOfViewDegrees, 50.0f);
}

TEST(SceneFormat, CameraFrameIsForwardRightAndTrueUp)
{
    Camera camera;
    camera.eye = {0.0f, 0.0f, 5.0f};
    camera.target = {0.0f, 0.0f, 0.0f};
    camera.up = {0.0f, 3.0f, 1.0f};  // neither unit nor orthogonal to the view
    const CameraFrame frame = cameraFrame(camera);
    EXPECT_TRUE(near(frame.forward, {0.0f, 0.0f, -1.0f}));
    EXPECT_TRUE(near(frame.right, {1.0f, 0.0f, 0.0f}));
    EXPECT_TRUE(near(frame.trueUp, {0.0f, 1.0f, 0.0f}));
}

TEST(SceneFormat, PointLightsArePositionThenIntensity)
{
    const Scene scene = parse(kEveryObjectType);
    ASSERT_EQ(scene.pointLights.size(), 2u);
    EXPECT_TRUE(near(scene.pointLights[0].position, {1.0f, 2.0f, 3.0f}));
    EXPECT_TRUE(near(scene.pointLights[0].intensity, {10.0f, 20.0f, 30.0f}));
    EXPECT_TRUE(near(scene.pointLights[1].position, {-4.0f, 5.0f, -6.0f}));
    EXPECT_TRUE(near(scene.pointLights[1].intensity, {0.5f, 0.25f, 0.1f}));
}

TEST(SceneFormat, PigmentsOfEveryKindKeepTheirValues)
{
    const Scene scene = parse(kEveryObjectType);
    ASSERT_EQ(scene.pigments.size(), 3u);
    EXPECT_EQ(scene.pigments[0].kind, PigmentKind::Solid);
    EXPECT_TRUE(near(scene.pigments[0].color, {0.1f, 0.2f, 0.3f}));
    EXPECT_EQ(scene.pigments[1].kind, PigmentKind::Checker);
    EXPECT_TRUE(near(scene.pigments[1].color, {1.0f, 0.0f, 0.0f}));
    EXPECT_TRUE(near(scene.pigments[1].secondColor, {0.0f, 0.0f, 1.0f}));
    EXPECT_FLOAT_EQ(scene.pigments[1].size, 0.75f);
    EXPECT_EQ(scene.pigments[2].kind, PigmentKind::Texture);
    EXPECT_EQ(scene.pigments[2].textureName, "brick.ppm");
    EXPECT_FLOAT_EQ(scene.pigments[2].size, 2.5f);
    EXPECT_EQ(scene.pigments[2].line, 11);
}

TEST(SceneFormat, TextureIsFoundInTheProjectTexturesWhenNotBesideTheScene)
{
    const Scene scene = parse(kEveryObjectType);
    EXPECT_EQ(
        std::filesystem::weakly_canonical(scene.pigments[2].texturePath),
        std::filesystem::weakly_canonical(FileLookup::dataDirectory() / "textures" / "brick.ppm"));
}

TEST(SceneFormat, FinishesAreEmissionExponentReflectionTransmissionAndIndex)
{
    const Scene scene = parse(kEveryObjectType);
    ASSERT_EQ(scene.finishes.size(), 4u);
    const Finish& glass = scene.finishes[3];
    EXPECT_TRUE(near(glass.emission, glm::vec3(0.0f)));
    EXPECT_FLOAT_EQ(glass.phongExponent, 12.0f);
    EXPECT_FLOAT_EQ(glass.reflection, 1.0f);
    EXPECT_FLOAT_EQ(glass.transmission, 1.0f);
    EXPECT_FLOAT_EQ(glass.ior, 1.33f);
}

TEST(SceneFormat, MaterialIsChosenDielectricThenMirrorThenBlinnPhongThenLambertian)
{
    const Scene scene = parse(kEveryObjectType);
    EXPECT_EQ(scene.finishes[0].material(), MaterialKind::Lambertian);
    EXPECT_EQ(scene.finishes[1].material(), MaterialKind::BlinnPhong);
    EXPECT_EQ(scene.finishes[2].material(), MaterialKind::Mirror) << "kr > 0 wins over alpha";
    EXPECT_EQ(scene.finishes[3].material(), MaterialKind::Dielectric)
        << "kt > 0 wins over kr and alpha";
}

TEST(SceneFormat, ObjectsKeepPigmentFinishAndTheLineTheyStartOn)
{
    const Scene scene = parse(kEveryObjectType);
    ASSERT_EQ(scene.objects.size(), 9u);
    EXPECT_EQ(scene.objects[2].pigment, 2);
    EXPECT_EQ(scene.objects[2].finish, 2);
    EXPECT_EQ(scene.objects[0].line, 18);
    EXPECT_EQ(scene.objects[1].line, 19);
    EXPECT_EQ(scene.objects[2].line, 22);
}

TEST(SceneFormat, SphereIsCentreAndRadius)
{
    const Scene scene = parse(kEveryObjectType);
    const auto& sphere = std::get<Sphere>(scene.objects[0].shape.geometry);
    EXPECT_TRUE(near(sphere.center, {1.0f, 2.0f, 3.0f}));
    EXPECT_FLOAT_EQ(sphere.radius, 0.5f);
}

TEST(SceneFormat, PolyhedronIsItsPlanesAsWritten)
{
    const Scene scene = parse(kEveryObjectType);
    const auto& polyhedron = std::get<Polyhedron>(scene.objects[1].shape.geometry);
    ASSERT_EQ(polyhedron.planes.size(), 2u);
    EXPECT_EQ(polyhedron.planes[0], glm::vec4(0.0f, 1.0f, 0.0f, 1.0f));
    EXPECT_EQ(polyhedron.planes[1], glm::vec4(2.0f, 0.0f, 0.0f, -4.0f))
        << "planes are kept as written, not normalised";
}

TEST(SceneFormat, BoxIsCentreAndHalfExtents)
{
    const Scene scene = parse(kEveryObjectType);
    const auto& box = std::get<Box>(scene.objects[2].shape.geometry);
    EXPECT_TRUE(near(box.center, {1.0f, 2.0f, 3.0f}));
    EXPECT_TRUE(near(box.halfExtents, {0.5f, 0.25f, 0.125f}));
}

TEST(SceneFormat, RoundedBoxIsCentreHalfExtentsAndEdgeRadius)
{
    const Scene scene = parse(sceneWithObjects(1, "0 0 rounded_box 1 2 3  0.5 0.25 0.75  0.2\n"));
    const auto& box = std::get<RoundedBox>(scene.objects[0].shape.geometry);
    EXPECT_TRUE(near(box.center, {1.0f, 2.0f, 3.0f}));
    EXPECT_TRUE(near(box.halfExtents, {0.5f, 0.25f, 0.75f}));
    EXPECT_FLOAT_EQ(box.radius, 0.2f);
}

TEST(SceneFormat, RoundedBoxEdgeRadiusIsAtMostItsSmallestHalfExtent)
{
    EXPECT_TRUE(failsAt(sceneWithObjects(1, "0 0 rounded_box 0 0 0  0.5 0.25 0.75  0.3\n"), 13,
                        "0.3", "an edge radius of at most the smallest half-extent, 0.25"));
}

TEST(SceneFormat, TorusIsCentreMajorAndMinorRadius)
{
    const Scene scene = parse(kEveryObjectType);
    const auto& torus = std::get<Torus>(scene.objects[3].shape.geometry);
    EXPECT_TRUE(near(torus.center, {-1.0f, 0.0f, 2.0f}));
    EXPECT_FLOAT_EQ(torus.majorRadius, 1.5f);
    EXPECT_FLOAT_EQ(torus.minorRadius, 0.25f);
}

TEST(SceneFormat, ConeIsApexAndSlope)
{
    const Scene scene = parse(kEveryObjectType);
    const auto& cone = std::get<Cone>(scene.objects[4].shape.geometry);
    EXPECT_TRUE(near(cone.apex, {0.0f, 3.0f, 0.0f}));
    EXPECT_EQ(cone.slope, glm::vec2(1.0f, 0.5f));
}

TEST(SceneFormat, CylinderIsCentreRadiusAndHalfHeight)
{
    const Scene scene = parse(kEveryObjectType);
    const auto& cylinder = std::get<Cylinder>(scene.objects[5].shape.geometry);
    EXPECT_TRUE(near(cylinder.center, {4.0f, 0.0f, -1.0f}));
    EXPECT_FLOAT_EQ(cylinder.radius, 0.5f);
    EXPECT_FLOAT_EQ(cylinder.halfHeight, 2.0f);
}

TEST(SceneFormat, DiskIsCentreNormalAndRadius)
{
    const Scene scene = parse(kEveryObjectType);
    const auto& disk = std::get<Disk>(scene.objects[6].shape.geometry);
    EXPECT_TRUE(near(disk.center, {0.0f, 1.0f, 0.0f}));
    EXPECT_TRUE(near(disk.normal, {0.0f, 0.0f, 2.0f}));
    EXPECT_FLOAT_EQ(disk.radius, 3.0f);
}

TEST(SceneFormat, AnyOtherWordIsAUserSdfWithItsPosition)
{
    const Scene scene = parse(kEveryObjectType);
    const auto& user = std::get<UserSdf>(scene.objects[7].shape.geometry);
    EXPECT_EQ(user.name, "twisted_bar");
    EXPECT_TRUE(near(user.position, {7.0f, 8.0f, 9.0f}));
    EXPECT_EQ(user.sourcePath.filename(), "twisted_bar.glsl");
}

TEST(SceneFormat, LineBreaksCarryNoMeaning)
{
    std::string oneLine = kEveryObjectType;
    for (char& c : oneLine)
        if (c == '\n')
            c = ' ';
    const Scene split = parse(kEveryObjectType);
    const Scene joined = parse(oneLine);
    ASSERT_EQ(joined.objects.size(), split.objects.size());
    EXPECT_TRUE(near(joined.camera.eye, split.camera.eye));
    EXPECT_EQ(std::get<Polyhedron>(joined.objects[1].shape.geometry).planes,
              std::get<Polyhedron>(split.objects[1].shape.geometry).planes);
}

TEST(SceneFormat, DefaultEnvironmentIsTheSky)
{
    EXPECT_EQ(parse(kEveryObjectType).environment.kind, EnvironmentKind::Sky);
}

TEST(SceneFormat, OnlyEmissiveSpheresAreSphereLights)
{
    const Scene scene = parse(sceneWithObjects(3, "0 1 sphere 0 1 0 0.5\n"
                                                  "0 0 sphere 0 3 0 0.5\n"
                                                  "1 1 sphere 2 1 0 0.25\n"));
    const auto lights = sphereLights(scene);
    ASSERT_EQ(lights.size(), 2u);
    EXPECT_EQ(lights[0].object, 0);
    EXPECT_EQ(lights[1].object, 2);
    EXPECT_FLOAT_EQ(lights[1].radius, 0.25f);
    EXPECT_TRUE(near(lights[1].radiance, glm::vec3(5.0f)));
}

}  // namespace
}  // namespace scene_tests
