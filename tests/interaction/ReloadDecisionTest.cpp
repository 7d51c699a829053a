// render::decideReload: which edits of a scene file rebuild the shader and which only
// re-upload uniforms, judged from the code generated for the scene before and after.
#include "render/ReloadDecision.h"
#include "scene/SceneTestSupport.h"

#include <gtest/gtest.h>

namespace interaction_tests {
namespace {

using render::decideReload;
using render::ReloadDecision;
using scene_tests::parse;
using settings::ShaderVariant;
using shadergen::EnvironmentBinding;
using shadergen::generateSceneShaderCode;
namespace fs = std::filesystem;

// Camera, a point light, a red and a grey pigment, two finishes, a sphere on a floor, with
// the parts a test edits as parameters.
std::string scene(const std::string& eye = "0 1 4", const std::string& colour = "0.8 0.1 0.1",
                  const std::string& secondFinish = "0 0 0  0 0 0 0",
                  const std::string& sphere = "0 0 sphere 0 0.5 0  0.5",
                  const std::string& environment = "")
{
    return environment + eye +
           "\n0 0.5 0\n0 1 0\n45\n"
           "1\n2 5 3  40 40 40\n"
           "2\nsolid " +
           colour +
           "\nsolid 0.5 0.5 0.5\n"
           "2\n0 0 0  0 0 0 0\n" +
           secondFinish +
           "\n"
           "2\n" +
           sphere + "\n1 0 polyhedron 1\n    0 1 0 0\n";
}

ReloadDecision decide(const std::string& before, const std::string& after,
                      const std::vector<fs::path>& changedFiles = {},
                      EnvironmentBinding environment = EnvironmentBinding::BuiltIn)
{
    const scene::Scene shown = parse(before);
    const scene::Scene edited = parse(after);
    const auto shownCode =
        generateSceneShaderCode(shown, {ShaderVariant::Specialized, environment});
    const auto editedCode =
        generateSceneShaderCode(edited, {ShaderVariant::Specialized, environment});
    return decideReload(shownCode, render::packSceneUniforms(shown, shownCode), editedCode,
                        render::packSceneUniforms(edited, editedCode), changedFiles);
}

TEST(ReloadDecision, AColourIsAValue)
{
    const ReloadDecision decision = decide(scene(), scene("0 1 4", "0.1 0.1 0.8"));
    EXPECT_FALSE(decision.rebuildShader);
    EXPECT_FALSE(decision.reloadTextures);
}

TEST(ReloadDecision, PositionsSizesAndTheCameraAreValues)
{
    EXPECT_FALSE(decide(scene(), scene("3 2 5")).rebuildShader) << "the camera";
    EXPECT_FALSE(
        decide(scene(), scene("0 1 4", "0.8 0.1 0.1", "0 0 0  0 0 0 0", "0 0 sphere 1 2 0  0.7"))
            .rebuildShader)
        << "the sphere's centre and radius";
}

TEST(ReloadDecision, AnotherShapeIsStructure)
{
    EXPECT_TRUE(decide(scene(), scene("0 1 4", "0.8 0.1 0.1", "0 0 0  0 0 0 0",
                                      "0 0 box 0 0.5 0  0.5 0.5 0.5"))
                    .rebuildShader);
}

TEST(ReloadDecision, AMaterialOfAnotherKindIsStructure)
{
    // The sphere's finish made a mirror: the shader gains the mirror's code.
    EXPECT_TRUE(
        decide(scene(), scene("0 1 4", "0.8 0.1 0.1", "0 0 0  0 1 0 0", "1 1 sphere 0 0.5 0  0.5"))
            .rebuildShader);
}

TEST(ReloadDecision, TheEnvironmentIsStructureOnlyWhenBuiltIn)
{
    const std::string none = scene("0 1 4", "0.8 0.1 0.1", "0 0 0  0 0 0 0",
                                   "0 0 sphere 0 0.5 0  0.5", "environment none\n");
    EXPECT_TRUE(decide(scene(), none).rebuildShader);
    EXPECT_FALSE(decide(scene(), none, {}, EnvironmentBinding::FromUniform).rebuildShader)
        << "the window reads the environment's kind from a uniform";
}

TEST(ReloadDecision, AnEditedUserSdfFileIsStructure)
{
    const std::string withUserSdf =
        scene("0 1 4", "0.8 0.1 0.1", "0 0 0  0 0 0 0", "0 0 twisted_bar 0 0.4 0");
    const fs::path file = testing_support::testScenesDirectory() / "twisted_bar.glsl";
    EXPECT_FALSE(decide(withUserSdf, withUserSdf).rebuildShader);
    EXPECT_TRUE(decide(withUserSdf, withUserSdf, {file}).rebuildShader)
        << "the file's code is part of the shader";
    EXPECT_FALSE(decide(withUserSdf, withUserSdf, {fs::path("elsewhere.glsl")}).rebuildShader);
}

TEST(ReloadDecision, AnEditedTextureReloadsTexturesWithoutARebuild)
{
    std::string textured = scene();
    const std::string solid = "solid 0.8 0.1 0.1";
    textured.replace(textured.find(solid), solid.size(), "texmap brick.ppm 1");
    const fs::path brick = scene::FileLookup::dataDirectory() / "textures" / "brick.ppm";
    const ReloadDecision edited = decide(textured, textured, {brick});
    EXPECT_TRUE(edited.reloadTextures);
    EXPECT_FALSE(edited.rebuildShader);
    const ReloadDecision untouched = decide(textured, textured);
    EXPECT_FALSE(untouched.reloadTextures);
}

// An environment map's file is a texture: edited on disk or replaced, it is uploaded again;
// its intensity and rotation are values.
TEST(ReloadDecision, AnEditedEnvironmentMapReloadsTexturesAndItsIntensityIsAValue)
{
    auto withMap = [](const std::string& options) {
        return scene("0 1 4", "0.8 0.1 0.1", "0 0 0  0 0 0 0", "0 0 sphere 0 0.5 0  0.5",
                     "environment map sky-sun.hdr " + options + "\n");
    };
    const fs::path map = scene::FileLookup::dataDirectory() / "textures" / "sky-sun.hdr";
    const ReloadDecision edited = decide(withMap(""), withMap(""), {map});
    EXPECT_TRUE(edited.reloadTextures);
    EXPECT_FALSE(edited.rebuildShader);
    const ReloadDecision replaced =
        decide(withMap(""), scene("0 1 4", "0.8 0.1 0.1", "0 0 0  0 0 0 0",
                                  "0 0 sphere 0 0.5 0  0.5", "environment map octants.exr\n"));
    EXPECT_TRUE(replaced.reloadTextures);
    const ReloadDecision turned = decide(withMap(""), withMap("intensity 2 rotate 30"));
    EXPECT_FALSE(turned.reloadTextures);
    EXPECT_FALSE(turned.rebuildShader);
    EXPECT_FALSE(turned.changesNothing);
    EXPECT_TRUE(decide(withMap(""), withMap("")).changesNothing);
}

TEST(ReloadDecision, TheSameSceneWrittenAnotherWayChangesNothing)
{
    EXPECT_TRUE(decide(scene(), scene()).changesNothing) << "saved unchanged";
    const ReloadDecision decision =
        decide(scene(), "# a comment\n\n" + scene("0 1  4.0", "0.80 0.1 .1"));
    EXPECT_TRUE(decision.changesNothing) << "a comment, spacing, numbers written another way";
    EXPECT_FALSE(decision.rebuildShader);
    EXPECT_FALSE(decision.reloadTextures);
}

TEST(ReloadDecision, AnyChangeOfValueCodeOrFileIsAChange)
{
    EXPECT_FALSE(decide(scene(), scene("0 1 4", "0.1 0.1 0.8")).changesNothing) << "a colour";
    EXPECT_FALSE(decide(scene(), scene("0 1 5")).changesNothing) << "the camera";
    EXPECT_FALSE(
        decide(scene(), scene("0 1 4", "0.8 0.1 0.1", "0 0 0  0 0 0 0", "0 0 sphere 0 0.5 0  0.6"))
            .changesNothing)
        << "a radius";
    EXPECT_FALSE(decide(scene(), scene("0 1 4", "0.8 0.1 0.1", "0 0 0  0 0 0 0",
                                       "0 0 box 0 0.5 0  0.5 0.5 0.5"))
                     .changesNothing)
        << "another shape";
    const std::string withUserSdf =
        scene("0 1 4", "0.8 0.1 0.1", "0 0 0  0 0 0 0", "0 0 twisted_bar 0 0.4 0");
    const fs::path file = testing_support::testScenesDirectory() / "twisted_bar.glsl";
    EXPECT_TRUE(decide(withUserSdf, withUserSdf).changesNothing);
    EXPECT_FALSE(decide(withUserSdf, withUserSdf, {file}).changesNothing)
        << "the user SDF file's bytes changed";
    std::string textured = scene();
    const std::string solid = "solid 0.8 0.1 0.1";
    textured.replace(textured.find(solid), solid.size(), "texmap brick.ppm 1");
    const fs::path brick = scene::FileLookup::dataDirectory() / "textures" / "brick.ppm";
    EXPECT_TRUE(decide(textured, textured).changesNothing);
    EXPECT_FALSE(decide(textured, textured, {brick}).changesNothing)
        << "the texture's bytes changed";
}

TEST(ReloadDecision, TheCameraIsReplacedOnlyWhenItsLinesChanged)
{
    EXPECT_FALSE(render::cameraLinesChanged(parse(scene()).camera,
                                            parse(scene("0 1 4", "0.2 0.2 0.2")).camera));
    EXPECT_TRUE(render::cameraLinesChanged(parse(scene()).camera, parse(scene("0 1 5")).camera));
}

// The thin lens is written on the camera line: a lens added, removed or changed is the
// camera changed.
TEST(ReloadDecision, ALensEditedIsTheCameraChanged)
{
    auto withLens = [](const std::string& lens) {
        std::string text = scene();
        text.replace(text.find("45\n"), 3, "45 " + lens + "\n");
        return text;
    };
    EXPECT_TRUE(
        render::cameraLinesChanged(parse(scene()).camera, parse(withLens("lens 0.1 4")).camera));
    EXPECT_TRUE(render::cameraLinesChanged(parse(withLens("lens 0.1 4")).camera,
                                           parse(withLens("lens 0.2 4")).camera));
    EXPECT_FALSE(render::cameraLinesChanged(parse(withLens("lens 0.1 4")).camera,
                                            parse(withLens("lens 0.1 4")).camera));
}

}  // namespace
}  // namespace interaction_tests
