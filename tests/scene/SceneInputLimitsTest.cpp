// Inputs a careless or hostile file can hold: messages stay one readable line, numbers beyond
// a float are named for what they are, the camera's degenerate cases are told apart, and the
// parser bounds what it allocates (counts, nesting, file size) instead of crashing.
#include "scene/SceneTestSupport.h"

#include <glm/glm.hpp>

#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <random>
#include <unistd.h>

namespace scene_tests {
namespace {

namespace fs = std::filesystem;

std::string messageOf(const std::string& text)
{
    try {
        parse(text);
    } catch (const std::exception& error) {
        return error.what();
    }
    return "(the text parsed)";
}

// --- what a message shows of the token --------------------------------------------------

TEST(SceneMessages, AHugeTokenIsShownCutTo40CharactersWithAnEllipsis)
{
    const std::string huge(10 * 1024 * 1024, 'x');
    const std::string message = messageOf("0 0 5\n0 " + huge + " 0\n");
    EXPECT_LT(message.size(), 300u) << "the message holds " << message.size() << " characters";
    EXPECT_NE(message.find("read '" + std::string(40, 'x') + "...'"), std::string::npos)
        << message.substr(0, 300);
}

// The word is a valid identifier, so the parser takes it for a user SDF and names the shader
// file it looked for: that name, too, is cut.
TEST(SceneMessages, AHugeWordWhereAnObjectTypeBelongsIsShownCutInEveryPartOfTheMessage)
{
    const std::string huge(10 * 1024 * 1024, 'x');
    const std::string message = messageOf(sceneWithObjects(1, "0 0 " + huge + " 0 0 0\n"));
    EXPECT_LT(message.size(), 400u) << "the message holds " << message.size() << " characters";
    EXPECT_NE(message.find("read '" + std::string(40, 'x') + "...'"), std::string::npos)
        << message.substr(0, 400);
    EXPECT_NE(message.find("shader file " + std::string(40, 'x') + "....glsl"), std::string::npos)
        << message.substr(0, 400);
}

TEST(SceneMessages, ATokenOfExactly40CharactersIsShownWhole)
{
    const std::string token(40, 'y');
    const std::string message = messageOf("0 0 5\n0 " + token + " 0\n");
    EXPECT_NE(message.find("read '" + token + "',"), std::string::npos) << message;
}

TEST(SceneMessages, ControlAndNonAsciiBytesInATokenAreShownEscaped)
{
    const std::string message = messageOf("0 0 5\n0 \x1b[31m\xc3 0\n");
    EXPECT_NE(message.find("read '\\x1b[31m\\xc3'"), std::string::npos) << message;
    for (char c : message)
        EXPECT_TRUE(c >= 0x20 && c < 0x7f)
            << "byte " << int(static_cast<unsigned char>(c)) << " in: " << message;
}

// --- encodings --------------------------------------------------------------------------

TEST(SceneMessages, AUtf8ByteOrderMarkIsSkipped)
{
    const scene::Scene scene = parse("\xEF\xBB\xBF" + sceneWithObjects(1, "0 0 sphere 0 0 0 1\n"));
    EXPECT_EQ(scene.camera.eye, glm::vec3(0.0f, 0.0f, 5.0f));
    EXPECT_EQ(scene.objects.size(), 1u);
}

TEST(SceneMessages, AUtf16FileIsNamedForItsEncoding)
{
    const std::string message = messageOf(std::string("\xFF\xFE"
                                                      "0\0 \0"
                                                      "0\0",
                                                      8));
    EXPECT_NE(message.find("UTF-16"), std::string::npos) << message;
    EXPECT_NE(message.find(kFileName + ":1:"), std::string::npos) << message;
}

// --- numbers ----------------------------------------------------------------------------

TEST(SceneMessages, ANumberBeyondTheFloatRangeIsNamedAnOverflow)
{
    EXPECT_TRUE(failsAt("0 0 5\n0 1e39 0\n", 2, "1e39", "overflows"));
    EXPECT_TRUE(failsAt("0 0 5\n0 -1e39 0\n", 2, "-1e39", "overflows"));
}

TEST(SceneMessages, ANonZeroNumberBelowTheFloatRangeIsNamedAnUnderflow)
{
    EXPECT_TRUE(failsAt("0 0 5\n0 1e-50 0\n", 2, "1e-50", "underflows"));
}

TEST(SceneMessages, TheLargestFloatIsStillANumber)
{
    const scene::Scene scene =
        parse("0 0 5\n0 3.4e38 0\n0 0 1\n45\n0\n1 solid 1 1 1\n1 0 0 0 0 0 0 0\n0\n");
    EXPECT_FLOAT_EQ(scene.camera.target.y, 3.4e38f);
}

TEST(SceneMessages, ACountBeyondAWholeNumberIsNamedTooLarge)
{
    EXPECT_TRUE(failsAt("0 0 5\n0 0 0\n0 1 0\n45\n99999999999\n", 5, "99999999999", "at most"));
}

// --- the camera -------------------------------------------------------------------------

TEST(SceneMessages, AFarCameraTargetIsAcceptedAndGivesAFiniteFrame)
{
    // |target - eye| overflows a float; the direction is still well defined.
    const scene::Scene scene =
        parse("-3e38 0 0\n3e38 3e38 0\n0 0 1\n45\n0\n1 solid 1 1 1\n1 0 0 0 0 0 0 0\n0\n");
    const scene::CameraFrame frame = scene::cameraFrame(scene.camera);
    for (int i = 0; i < 3; ++i) {
        EXPECT_TRUE(std::isfinite(frame.forward[i])) << "forward " << i;
        EXPECT_TRUE(std::isfinite(frame.right[i])) << "right " << i;
        EXPECT_TRUE(std::isfinite(frame.trueUp[i])) << "up " << i;
    }
    EXPECT_NEAR(glm::length(frame.forward), 1.0f, 1e-5f);
    EXPECT_NEAR(frame.forward.x, 2.0f / std::sqrt(5.0f), 1e-5f);
}

TEST(SceneMessages, ZeroUpVectorSaysItIsZeroNotParallel)
{
    const std::string message = messageOf("0 0 5\n0 0 0\n0 0 0\n45\n");
    EXPECT_NE(message.find("not zero"), std::string::npos) << message;
    EXPECT_EQ(message.find("parallel"), std::string::npos) << message;
}

TEST(SceneMessages, UpVectorAlongTheViewSaysItIsParallelNotZero)
{
    const std::string message = messageOf("0 0 5\n0 0 0\n0 0 2\n45\n");
    EXPECT_NE(message.find("parallel to the view"), std::string::npos) << message;
    EXPECT_EQ(message.find("not zero"), std::string::npos) << message;
}

TEST(SceneMessages, TargetEqualToTheEyeSaysSo)
{
    EXPECT_TRUE(failsAt("1e38 2 3\n1e38 2 3\n0 1 0\n45\n", 2, "1e38",
                        "a camera target different from the eye"));
}

// --- bounds on what the parser allocates ------------------------------------------------

TEST(SceneLimits, AnObjectCountOfTwoBillionIsRefusedAtTheCount)
{
    EXPECT_TRUE(
        failsAt(sceneWithObjects(2000000000, "0 0 sphere 0 0 0 1\n"), 12, "2000000000", "at most"));
}

TEST(SceneLimits, APlaneCountOfTwoBillionIsRefusedAtTheCount)
{
    EXPECT_TRUE(failsAt(sceneWithObjects(1, "0 0 polyhedron 2000000000 0 1 0 0\n"), 13,
                        "2000000000", "at most"));
}

TEST(SceneLimits, TransformsNestedAMillionDeepAreRefusedNotACrash)
{
    std::string nested;
    for (int i = 0; i < 1000000; ++i)
        nested += "translate 0 0 0 ";
    const std::string message =
        messageOf(sceneWithObjects(1, "0 0 " + nested + "sphere 0 0 0 1\n"));
    EXPECT_NE(message.find("nest"), std::string::npos) << message.substr(0, 300);
}

TEST(SceneLimits, CsgBlocksNestedHalfAMillionDeepAreRefusedNotACrash)
{
    std::string nested;
    for (int i = 0; i < 500000; ++i)
        nested += "union { sphere 0 0 0 1 ";
    const std::string message = messageOf(sceneWithObjects(1, "0 0 " + nested));
    EXPECT_NE(message.find("nest"), std::string::npos) << message.substr(0, 300);
}

TEST(SceneLimits, NestingWithinTheLimitIsAccepted)
{
    std::string nested;
    for (int i = 0; i < 32; ++i)
        nested += "translate 0 0 0 union { sphere 0 0 0 1 ";
    nested += "sphere 0 0 0 1";
    for (int i = 0; i < 32; ++i)
        nested += " }";
    const scene::Scene scene = parse(sceneWithObjects(1, "0 0 " + nested + "\n"));
    EXPECT_EQ(scene.objects.size(), 1u);
}

// --- scene files the program cannot read ------------------------------------------------

class SceneFile : public ::testing::Test {
protected:
    void SetUp() override
    {
        folder_ = fs::temp_directory_path() /
                  ("raytracer-scene-file-" + std::to_string(std::random_device{}()));
        fs::create_directories(folder_);
    }
    void TearDown() override
    {
        fs::permissions(folder_, fs::perms::owner_all, fs::perm_options::add);
        fs::remove_all(folder_);
    }
    std::string messageOfFile(const fs::path& path) const
    {
        try {
            scene::parseSceneFile(path);
        } catch (const std::exception& error) {
            return error.what();
        }
        return "(the file parsed)";
    }
    fs::path folder_;
};

TEST_F(SceneFile, ADirectoryGivesTheSystemsReason)
{
    const std::string message = messageOfFile(folder_);
    EXPECT_EQ(message.rfind(folder_.string() + ": ", 0), 0u) << message;
    EXPECT_NE(message.find(std::strerror(EISDIR)), std::string::npos) << message;
}

TEST_F(SceneFile, AMissingFileGivesTheSystemsReason)
{
    const std::string message = messageOfFile(folder_ / "absent.in");
    EXPECT_NE(message.find((folder_ / "absent.in").string()), std::string::npos) << message;
    EXPECT_NE(message.find(std::strerror(ENOENT)), std::string::npos) << message;
}

TEST_F(SceneFile, APathThroughAFileGivesTheSystemsReason)
{
    std::ofstream(folder_ / "plain") << "x";
    const std::string message = messageOfFile(folder_ / "plain" / "scene.in");
    EXPECT_NE(message.find(std::strerror(ENOTDIR)), std::string::npos) << message;
}

TEST_F(SceneFile, AFileWithoutReadPermissionGivesTheSystemsReason)
{
    if (::geteuid() == 0)
        GTEST_SKIP() << "root reads any file whatever its permissions";
    const fs::path scene = folder_ / "locked.in";
    std::ofstream(scene) << "0 0 5";
    fs::permissions(scene, fs::perms::none);
    const std::string message = messageOfFile(scene);
    EXPECT_NE(message.find(std::strerror(EACCES)), std::string::npos) << message;
}

TEST_F(SceneFile, AFileLargerThanTheLimitIsRefusedBeforeItIsRead)
{
    const fs::path scene = folder_ / "huge.in";
    std::ofstream(scene).close();
    fs::resize_file(scene, 200u << 20);  // sparse: no disk is used
    const std::string message = messageOfFile(scene);
    EXPECT_NE(message.find("larger than"), std::string::npos) << message.substr(0, 300);
    EXPECT_LT(message.size(), 300u);
}

}  // namespace
}  // namespace scene_tests
