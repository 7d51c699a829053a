// analyseFeatures: what a scene uses, so that its shader is built with that and nothing else.
#include "scene/SceneFeatures.h"
#include "scene/SceneTestSupport.h"

namespace scene_tests {
namespace {

using namespace scene;

SceneFeatures classicFeatures(int number)
{
    return analyseFeatures(parseSceneFile(testing_support::sourceDirectory() / "scenes" /
                                          ("scene" + std::to_string(number) + ".in")));
}

TEST(SceneFeatures, ClassicSceneThreeUsesBlinnPhongAndAPointLight)
{
    const SceneFeatures features = classicFeatures(3);
    EXPECT_EQ(features.materials, std::set<MaterialKind>{MaterialKind::BlinnPhong})
        << "scene 3's emissive finish is used by no object, so it adds no material";
    EXPECT_EQ(features.pigments, std::set<PigmentKind>{PigmentKind::Solid});
    EXPECT_EQ(features.lights, std::set<LightKind>{LightKind::Point});
    EXPECT_TRUE(features.userSdfs.empty());
    EXPECT_FALSE(features.transforms);
    EXPECT_EQ(features.environment, EnvironmentKind::Sky);
}

TEST(SceneFeatures, ClassicSceneFourUsesTheKnotAndATexture)
{
    const SceneFeatures features = classicFeatures(4);
    ASSERT_EQ(features.userSdfs.size(), 1u);
    EXPECT_EQ(features.userSdfs.begin()->first, "knot");
    EXPECT_TRUE(features.has(PigmentKind::Texture));
    EXPECT_TRUE(features.has(PigmentKind::Solid));
}

TEST(SceneFeatures, ClassicSceneOneUsesEveryMaterialItsFinishesNameAndASphereLight)
{
    const SceneFeatures features = classicFeatures(1);
    EXPECT_EQ(features.materials,
              (std::set<MaterialKind>{MaterialKind::Lambertian, MaterialKind::Dielectric}));
    EXPECT_EQ(features.lights, std::set<LightKind>{LightKind::Sphere});
    EXPECT_TRUE(features.has(PigmentKind::Checker));
    EXPECT_TRUE(features.has(PigmentKind::Texture));
}

TEST(SceneFeatures, UserSdfsAreCollectedFromNestedBlocks)
{
    const SceneFeatures features = analyseFeatures(parse(sceneWithObjects(
        1, "0 0 smooth_difference poly 0.2 { box 0 0 0 1 1 1 intersection { sphere 0 0 0 1 "
           "twisted_bar 0 0 0 } }\n")));
    EXPECT_EQ(features.userSdfs.count("twisted_bar"), 1u);
    EXPECT_FALSE(features.transforms);
}

TEST(SceneFeatures, TransformAnywhereInATreeCounts)
{
    const SceneFeatures features = analyseFeatures(
        parse(sceneWithObjects(1, "0 0 union { sphere 0 0 0 1 scale 2 sphere 1 0 0 1 }\n")));
    EXPECT_TRUE(features.transforms);
}

TEST(SceneFeatures, MaterialsComeOnlyFromFinishesObjectsUse)
{
    const std::string text = "0 0 5\n0 0 0\n0 1 0\n45\n0\n1 solid 1 1 1\n"
                             "3\n0 0 0 0 0 0 0\n0 0 0 0 1 0 0\n0 0 0 0 0 1 1.5\n"
                             "1\n0 1 sphere 0 0 0 1\n";
    EXPECT_EQ(analyseFeatures(parse(text)).materials, std::set<MaterialKind>{MaterialKind::Mirror});
}

TEST(SceneFeatures, EnvironmentIsTheScenes)
{
    const SceneFeatures features =
        analyseFeatures(parse("environment none\n" + sceneWithObjects(1, "0 0 sphere 0 0 0 1\n")));
    EXPECT_EQ(features.environment, EnvironmentKind::None);
}

TEST(SceneFeatures, EverythingHasEveryFeatureAndTheScenesUserSdfs)
{
    const Scene scene = parse(sceneWithObjects(1, "0 0 twisted_bar 0 0 0\n"));
    const SceneFeatures features = SceneFeatures::everything(scene);
    EXPECT_EQ(features.materials.size(), materialDescriptions().size());
    EXPECT_EQ(features.pigments.size(), pigmentDescriptions().size());
    EXPECT_TRUE(features.transforms);
    EXPECT_EQ(features.lights, (std::set<LightKind>{LightKind::Point, LightKind::Sphere}))
        << "every light kind but the environment's, whose code needs a map";
    EXPECT_EQ(features.userSdfs.count("twisted_bar"), 1u);
}

TEST(SceneFeatures, AnEnvironmentMapIsALightAndItsKind)
{
    const Scene scene =
        parse("environment map sky-sun.hdr\n" + sceneWithObjects(1, "0 0 sphere 0 0 0 1\n"));
    const SceneFeatures features = analyseFeatures(scene);
    EXPECT_EQ(features.environment, EnvironmentKind::Map);
    EXPECT_TRUE(features.has(EnvironmentKind::Map));
    EXPECT_EQ(features.lights, std::set<LightKind>{LightKind::Environment});
    EXPECT_TRUE(SceneFeatures::everything(scene).has(LightKind::Environment));
}

TEST(SceneFeatures, AMapLeftToTheEscapingRaysIsNoLight)
{
    Scene scene =
        parse("environment map sky-sun.hdr\n" + sceneWithObjects(1, "0 0 sphere 0 0 0 1\n"));
    scene.environment.importanceSampled = false;
    EXPECT_TRUE(analyseFeatures(scene).lights.empty());
    EXPECT_FALSE(SceneFeatures::everything(scene).has(LightKind::Environment));
}

}  // namespace
}  // namespace scene_tests

namespace scene_tests {
namespace {

TEST(SceneFeatures, RoughFinishesAreMicrofacetMaterials)
{
    const std::string text = "0 0 5\n0 0 0\n0 1 0\n45\n0\n1 solid 1 1 1\n"
                             "2\nrough_conductor 0.2\nrough_dielectric 0.2 1.5\n"
                             "1\n0 1 sphere 0 0 0 1\n";
    const SceneFeatures features = analyseFeatures(parse(text));
    EXPECT_EQ(features.materials, std::set<MaterialKind>{MaterialKind::RoughDielectric});
    EXPECT_TRUE(features.microfacets);
    EXPECT_FALSE(features.thinLens);
}

TEST(SceneFeatures, AClassicSceneHasNoMicrofacetsAndAPinhole)
{
    const SceneFeatures features =
        analyseFeatures(parse(sceneWithObjects(1, "0 0 sphere 0 0 0 1\n")));
    EXPECT_FALSE(features.microfacets);
    EXPECT_FALSE(features.thinLens);
}

TEST(SceneFeatures, ALensIsAFeature)
{
    const std::string text = "0 0 5\n0 0 0\n0 1 0\n45 lens 0.1 5\n0\n1 solid 1 1 1\n"
                             "1\n0 0 0 0 0 0 0\n1\n0 0 sphere 0 0 0 1\n";
    EXPECT_TRUE(analyseFeatures(parse(text)).thinLens);
    EXPECT_TRUE(SceneFeatures::everything(parse(text)).thinLens);
}

}  // namespace
}  // namespace scene_tests
