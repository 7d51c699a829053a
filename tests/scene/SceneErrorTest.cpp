// Every error the scene format lists: a scene::SceneError whose message names the file, the
// line, the token read and what was expected; nothing is returned half-read.
#include "scene/CameraLine.h"
#include "scene/SceneTestSupport.h"

namespace scene_tests {
namespace {

TEST(SceneErrors, TruncatedFileNamesTheEndOfTheFileOnTheLastLine)
{
    EXPECT_TRUE(failsAt(sceneWithObjects(1, "0 0 sphere 0 0\n"), 13, "", "sphere centre, z"));
}

TEST(SceneErrors, FileEndingInsideTheCameraNamesTheCamera)
{
    EXPECT_TRUE(failsAt("0 0 5\n0 0\n", 2, "", "camera target point, z"));
}

TEST(SceneErrors, EmptyFileIsAnError)
{
    EXPECT_TRUE(failsAt("", 1, "", "camera eye position"));
}

TEST(SceneErrors, FewerObjectsThanTheCountSaysIsAnError)
{
    EXPECT_TRUE(failsAt(sceneWithObjects(3, "0 0 sphere 0 0 0 1\n"
                                            "0 0 sphere 0 2 0 1\n"),
                        14, "", "pigment index"));
}

TEST(SceneErrors, MoreObjectsThanTheCountSaysIsAnError)
{
    EXPECT_TRUE(failsAt(sceneWithObjects(1, "0 0 sphere 0 0 0 1\n"
                                            "0 0 sphere 0 2 0 1\n"),
                        14, "0", "the end of the file"));
}

TEST(SceneErrors, MorePigmentsThanTheCountSaysIsAnError)
{
    // One pigment announced, two written: the second pigment's kind is read as the finish
    // count.
    EXPECT_TRUE(failsAt("0 0 5\n0 0 0\n0 1 0\n45\n0\n1\nsolid 1 1 1\nsolid 1 1 1\n0\n0\n", 8,
                        "solid", "number of finishes"));
}

TEST(SceneErrors, PigmentIndexOutOfRangeNamesTheIndex)
{
    EXPECT_TRUE(failsAt(sceneWithObjects(2, "0 0 sphere 0 0 0 1\n"
                                            "2 0 sphere 0 2 0 1\n"),
                        14, "2", "a pigment index from 0 to 1"));
}

TEST(SceneErrors, NegativePigmentIndexIsOutOfRange)
{
    EXPECT_TRUE(failsAt(sceneWithObjects(1, "-1 0 sphere 0 0 0 1\n"), 13, "-1",
                        "a pigment index from 0 to 1"));
}

TEST(SceneErrors, FinishIndexOutOfRangeNamesTheIndex)
{
    EXPECT_TRUE(failsAt(sceneWithObjects(1, "0\n7 sphere 0 0 0 1\n"), 14, "7",
                        "a finish index from 0 to 1"));
}

TEST(SceneErrors, IndexIntoAnEmptyListSaysThereIsNone)
{
    EXPECT_TRUE(failsAt("0 0 5\n0 0 0\n0 1 0\n45\n0\n0\n0\n1\n0 0 sphere 0 0 0 1\n", 9, "0",
                        "no pigment index"));
}

TEST(SceneErrors, UnknownObjectTypeThatCannotNameAFunctionIsAnError)
{
    EXPECT_TRUE(
        failsAt(sceneWithObjects(1, "0 0 3d-sphere 0 0 0 1\n"), 13, "3d-sphere", "an object type"));
}

TEST(SceneErrors, UnknownObjectTypeWithoutAShaderFileIsAMissingUserSdf)
{
    EXPECT_TRUE(failsAt(sceneWithObjects(1, "0 0 sphre 0 0 0 1\n"), 13, "sphre", "sphre.glsl"));
}

TEST(SceneErrors, MissingUserSdfFileNamesTheFoldersSearched)
{
    EXPECT_TRUE(failsAt(sceneWithObjects(1, "\n0 0 no_such_shape 1 2 3\n"), 14, "no_such_shape",
                        "looked in"));
}

TEST(SceneErrors, NegativeSphereRadiusIsAnError)
{
    EXPECT_TRUE(failsAt(sceneWithObjects(1, "0 0 sphere 0 0 0\n-1\n"), 14, "-1", "sphere radius"));
}

TEST(SceneErrors, NegativeTorusRadiusIsAnError)
{
    EXPECT_TRUE(
        failsAt(sceneWithObjects(1, "0 0 torus 0 0 0 -2 0.5\n"), 13, "-2", "torus major radius"));
}

TEST(SceneErrors, NegativeCylinderRadiusIsAnError)
{
    EXPECT_TRUE(
        failsAt(sceneWithObjects(1, "0 0 cylinder 0 0 0 -0.5 1\n"), 13, "-0.5", "cylinder radius"));
}

TEST(SceneErrors, NegativeDiskRadiusIsAnError)
{
    EXPECT_TRUE(
        failsAt(sceneWithObjects(1, "0 0 disk 0 0 0  0 1 0  -3\n"), 13, "-3", "disk radius"));
}

TEST(SceneErrors, NegativeBoxExtentIsAnError)
{
    EXPECT_TRUE(
        failsAt(sceneWithObjects(1, "0 0 box 0 0 0  1 -1 1\n"), 13, "-1", "box half-extent y"));
}

TEST(SceneErrors, MissingTextureFileNamesTheFile)
{
    EXPECT_TRUE(failsAt("0 0 5\n0 0 0\n0 1 0\n45\n0\n1\ntexmap\n  missing-texture.ppm 2\n", 8,
                        "missing-texture.ppm", "an existing texture file"));
}

TEST(SceneErrors, UnknownPigmentKindIsAnError)
{
    EXPECT_TRUE(failsAt("0 0 5\n0 0 0\n0 1 0\n45\n0\n2\nsolid 1 1 1\nmarble 1 1 1\n", 8, "marble",
                        "solid, checker or texmap"));
}

TEST(SceneErrors, EmissionOnANonSphereIsAnError)
{
    EXPECT_TRUE(failsAt(sceneWithObjects(2, "0 1 sphere 0 3 0 0.5\n"
                                            "0 1 box 0 0 0 1 1 1\n"),
                        14, "box", "only spheres may emit"));
}

TEST(SceneErrors, EmissionOnACsgBlockIsAnError)
{
    EXPECT_TRUE(failsAt(sceneWithObjects(1, "0 1 union { sphere 0 0 0 1 sphere 1 0 0 1 }\n"), 13,
                        "union", "only spheres may emit"));
}

TEST(SceneErrors, NonNumericTokenWhereANumberBelongsIsAnError)
{
    EXPECT_TRUE(failsAt("0 0 5\n0 zero 0\n", 2, "zero", "a number (camera target point, y)"));
}

TEST(SceneErrors, NumberWithTrailingCharactersIsNotANumber)
{
    EXPECT_TRUE(failsAt("0 0 5\n0 0 0\n0 1 0\n45deg\n", 4, "45deg", "vertical field of view"));
}

TEST(SceneErrors, FractionalCountIsAnError)
{
    EXPECT_TRUE(failsAt("0 0 5\n0 0 0\n0 1 0\n45\n1.5\n", 5, "1.5", "number of point lights"));
}

TEST(SceneErrors, NegativeCountIsAnError)
{
    EXPECT_TRUE(failsAt("0 0 5\n0 0 0\n0 1 0\n45\n-1\n", 5, "-1", "number of point lights"));
}

TEST(SceneErrors, NegativeLightIntensityIsAnError)
{
    EXPECT_TRUE(failsAt("0 0 5\n0 0 0\n0 1 0\n45\n1\n0 4 0  10 -10 10\n", 6, "-10", "intensity"));
}

TEST(SceneErrors, UpVectorParallelToTheViewDirectionIsAnError)
{
    EXPECT_TRUE(failsAt("0 0 5\n0 0 0\n0 0 -3\n45\n", 3, "0", "not parallel to the view"));
}

TEST(SceneErrors, ZeroUpVectorIsAnError)
{
    EXPECT_TRUE(failsAt("0 0 5\n0 0 0\n0 0 0\n45\n", 3, "0", "up vector"));
}

TEST(SceneErrors, TargetAtTheEyeIsAnError)
{
    EXPECT_TRUE(failsAt("1 2 3\n1 2 3\n0 1 0\n45\n", 2, "1", "different from the eye"));
}

TEST(SceneErrors, FieldOfViewOfZeroIsAnError)
{
    EXPECT_TRUE(failsAt("0 0 5\n0 0 0\n0 1 0\n0\n", 4, "0", "strictly between 0 and 180"));
}

TEST(SceneErrors, FieldOfViewOf180IsAnError)
{
    EXPECT_TRUE(failsAt("0 0 5\n0 0 0\n0 1 0\n180\n", 4, "180", "strictly between 0 and 180"));
}

TEST(SceneErrors, TransmissiveFinishWithoutAPositiveIndexIsAnError)
{
    EXPECT_TRUE(failsAt("0 0 5\n0 0 0\n0 1 0\n45\n0\n0\n1\n0 0 0 0 0 1\n0\n", 9, "0",
                        "positive index of refraction"));
}

TEST(SceneErrors, ErrorLineCountsLinesOfCommentsAndBlankLines)
{
    EXPECT_TRUE(failsAt("# a comment\n\n0 0 5 # eye\n# another\n0 0 0\n0 1 0\n\n-45\n", 8, "-45",
                        "strictly between 0 and 180"));
}

}  // namespace
}  // namespace scene_tests

// --- a misspelt keyword is answered with the nearest one, within two edits ----------------

namespace scene_tests {
namespace {

TEST(SceneErrorSuggestions, AMisspeltObjectTypeIsAnsweredWithTheNearestKeyword)
{
    EXPECT_TRUE(failsAt(sceneWithObjects(1, "0 0 sphre 0 0 0 1\n"), 13, "sphre",
                        "(did you mean 'sphere'?)"));
    EXPECT_TRUE(failsAt(sceneWithObjects(1, "0 0 unoin { sphere 0 0 0 1 sphere 0 1 0 1 }\n"), 13,
                        "unoin", "(did you mean 'union'?)"));
}

TEST(SceneErrorSuggestions, AMisspeltPigmentKindIsAnsweredWithTheNearestKeyword)
{
    EXPECT_TRUE(failsAt("0 0 5\n0 0 0\n0 1 0\n45\n0\n1\nsolit 1 1 1\n", 7, "solit",
                        "(did you mean 'solid'?)"));
}

TEST(SceneErrorSuggestions, AMisspeltEnvironmentIsAnsweredWithTheNearestKeyword)
{
    EXPECT_TRUE(failsAt("environment nnoe\n0 0 5\n", 1, "nnoe", "(did you mean 'none'?)"));
    EXPECT_TRUE(
        failsAt("enviroment none\n0 0 5\n", 1, "enviroment", "(did you mean 'environment'?)"));
}

TEST(SceneErrorSuggestions, AWordFarFromEveryKeywordIsOnlyRefused)
{
    try {
        parse(sceneWithObjects(1, "0 0 teapot 0 0 0 1\n"));
        FAIL() << "a teapot is no keyword";
    } catch (const scene::SceneError& error) {
        EXPECT_EQ(std::string(error.what()).find("did you mean"), std::string::npos)
            << error.what();
    }
}

// --camera's text (scene::parseCameraText): the file's camera line, its groups after their
// words or not, checked as the file's camera is.
TEST(CameraText, ReadsTheFilesCameraLineWithOrWithoutItsWords)
{
    const scene::Camera bare = scene::parseCameraText("1 2 3  4 5 6  0 0 1  40", "--camera");
    const scene::Camera worded =
        scene::parseCameraText("eye 1 2 3 look-at 4 5 6 up 0 0 1 fov 40 lens 0.1 5", "--camera");
    EXPECT_EQ(bare.eye, glm::vec3(1, 2, 3));
    EXPECT_EQ(bare.target, glm::vec3(4, 5, 6));
    EXPECT_EQ(bare.up, glm::vec3(0, 0, 1));
    EXPECT_EQ(bare.verticalFieldOfViewDegrees, 40.0f);
    EXPECT_EQ(worded.eye, bare.eye);
    EXPECT_EQ(worded.target, bare.target);
    ASSERT_TRUE(worded.lens.has_value());
    EXPECT_EQ(worded.lens->focusDistance, 5.0f);
}

// What the window's C key writes (scene::cameraLine) is what --camera reads back, exactly.
TEST(CameraText, ReadsTheWindowsCameraLineBackExactly)
{
    scene::Camera camera;
    camera.eye = {1.1f, -8.4f, 4.44f};
    camera.target = {1.0f / 3.0f, 10.0f, -2.0f};
    camera.up = {0.0f, 0.0f, 1.0f};
    camera.verticalFieldOfViewDegrees = 35.5f;
    camera.lens = scene::ThinLens{0.05f, 14.0f};
    const scene::Camera read = scene::parseCameraText(scene::cameraLine(camera), "--camera");
    EXPECT_TRUE(scene::sameCamera(read, camera)) << scene::cameraLine(read);
}

TEST(CameraText, AnErrorNamesTheSourceAndTheToken)
{
    try {
        scene::parseCameraText("1 2 3 4 5 6 0 0 1 200", "--camera");
        FAIL() << "a field of view of 200 degrees";
    } catch (const scene::SceneError& error) {
        EXPECT_EQ(error.file(), "--camera");
        EXPECT_EQ(error.token(), "200");
        EXPECT_NE(error.expected().find("strictly between 0 and 180"), std::string::npos);
    }
    EXPECT_THROW(scene::parseCameraText("1 2 3 4 5 6 0 0 1 40 99", "--camera"), scene::SceneError)
        << "nothing may follow the camera";
}

}  // namespace
}  // namespace scene_tests
