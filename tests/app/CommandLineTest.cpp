// The raytracer program run as a user runs it: errors give one line on standard error and a
// non-zero status and write nothing; renders write the files they promise.
#include "app/ProgramInFolder.h"
#include "io/ImageFile.h"
#include "support/ChildProcess.h"
#include "support/TestPaths.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <random>
#include <sstream>

namespace cli_tests {
namespace {

using namespace testing_support;
namespace fs = std::filesystem;

class CommandLine : public ProgramInFolder {
protected:
    std::string scene1() const { return (sourceDirectory() / "scenes" / "scene1.in").string(); }
};

// --- malformed scenes ---------------------------------------------------------------------

struct MalformedScene {
    const char* name;
    const char* text;
    int line;           // where the error is
    const char* token;  // what was read; empty: the end of the file
};

// Test names in ctest show the case's name rather than its bytes.
void PrintTo(const MalformedScene& malformed, std::ostream* out)
{
    *out << malformed.name;
}

class MalformedSceneFile : public CommandLine,
                           public ::testing::WithParamInterface<MalformedScene> {};

TEST_P(MalformedSceneFile, GivesOneLineNamingFileAndLineAndWritesNothing)
{
    const MalformedScene& malformed = GetParam();
    const fs::path scene = write("bad.in", malformed.text);
    const ProcessResult result =
        run({scene.string(), "32", "24", "--spp", "4", "--output", "out.png"});

    ASSERT_TRUE(result.exited) << describe(result);
    EXPECT_NE(result.exitStatus, 0) << describe(result);
    const auto lines = nonEmptyLines(result.standardError);
    ASSERT_EQ(lines.size(), 1u) << "exactly one line on standard error; " << describe(result);
    const std::string where = scene.string() + ":" + std::to_string(malformed.line) + ":";
    EXPECT_NE(lines[0].find(where), std::string::npos)
        << "the line should name " << where << "; it is: " << lines[0];
    const std::string read = *malformed.token == '\0' ? std::string("end of the file")
                                                      : std::string("'") + malformed.token + "'";
    EXPECT_NE(lines[0].find(read), std::string::npos)
        << "the line should name what was read (" << read << "): " << lines[0];
    EXPECT_NE(lines[0].find("expected"), std::string::npos) << lines[0];
    EXPECT_EQ(filesInFolder(), std::vector<std::string>{"bad.in"})
        << "no output (or partial output) file may appear";
}

INSTANTIATE_TEST_SUITE_P(
    Error, MalformedSceneFile,
    ::testing::Values(MalformedScene{"TruncatedFile", "0 0 5\n0 0 0\n0 1", 3, ""},
                      MalformedScene{"TooFewObjects",
                                     "0 0 5\n0 0 0\n0 1 0\n45\n0\n1 solid 1 1 1\n"
                                     "1 0 0 0 0 0 0 0\n2\n0 0 sphere 0 0 0 1\n",
                                     9, ""},
                      MalformedScene{"TooManyObjects",
                                     "0 0 5\n0 0 0\n0 1 0\n45\n0\n1 solid 1 1 1\n"
                                     "1 0 0 0 0 0 0 0\n1\n0 0 sphere 0 0 0 1\n"
                                     "0 0 sphere 0 2 0 1\n",
                                     10, "0"},
                      MalformedScene{"PigmentIndexOutOfRange",
                                     "0 0 5\n0 0 0\n0 1 0\n45\n0\n1 solid 1 1 1\n"
                                     "1 0 0 0 0 0 0 0\n1\n4 0 sphere 0 0 0 1\n",
                                     9, "4"},
                      MalformedScene{"FinishIndexOutOfRange",
                                     "0 0 5\n0 0 0\n0 1 0\n45\n0\n1 solid 1 1 1\n"
                                     "1 0 0 0 0 0 0 0\n1\n0 3 sphere 0 0 0 1\n",
                                     9, "3"},
                      MalformedScene{"UnknownObjectType",
                                     "0 0 5\n0 0 0\n0 1 0\n45\n0\n1 solid 1 1 1\n"
                                     "1 0 0 0 0 0 0 0\n1\n0 0 sphear 0 0 0 1\n",
                                     9, "sphear"},
                      MalformedScene{"NegativeRadius",
                                     "0 0 5\n0 0 0\n0 1 0\n45\n0\n1 solid 1 1 1\n"
                                     "1 0 0 0 0 0 0 0\n1\n0 0 sphere 0 0 0 -2\n",
                                     9, "-2"},
                      MalformedScene{"MissingTexture",
                                     "0 0 5\n0 0 0\n0 1 0\n45\n0\n1\n"
                                     "texmap no-such-texture.ppm 1\n",
                                     7, "no-such-texture.ppm"},
                      MalformedScene{"EmissionOnANonSphere",
                                     "0 0 5\n0 0 0\n0 1 0\n45\n0\n1 solid 1 1 1\n"
                                     "1 3 3 3 0 0 0 0\n1\n0 0 box 0 0 0 1 1 1\n",
                                     9, "box"},
                      MalformedScene{"UnknownPigmentKind",
                                     "0 0 5\n0 0 0\n0 1 0\n45\n0\n1\nwood 1 1 1\n", 7, "wood"},
                      MalformedScene{"NonNumericToken", "0 0 5\n0 0 O\n", 2, "O"}),
    [](const ::testing::TestParamInfo<MalformedScene>& info) {
        return std::string(info.param.name);
    });

TEST_F(CommandLine, UnreadableTextureIsOneLineNamingThePigmentAndWritesNothing)
{
    write("broken.ppm", "this is not an image");
    const fs::path scene = write("bad.in", "0 0 5\n0 0 0\n0 1 0\n45\n0\n1\ntexmap broken.ppm 1\n"
                                           "1\n0 0 0 0 0 0 0\n1\n0 0 sphere 0 0 0 1\n");
    const ProcessResult result =
        run({scene.string(), "32", "24", "--spp", "4", "--output", "out.png"});
    ASSERT_TRUE(result.exited) << describe(result);
    EXPECT_NE(result.exitStatus, 0) << describe(result);
    const auto lines = nonEmptyLines(result.standardError);
    ASSERT_EQ(lines.size(), 1u) << describe(result);
    EXPECT_NE(lines[0].find(scene.string() + ":7:"), std::string::npos) << lines[0];
    EXPECT_NE(lines[0].find("broken.ppm"), std::string::npos) << lines[0];
    const auto files = filesInFolder();
    EXPECT_EQ(std::count(files.begin(), files.end(), "out.png"), 0) << "no output file";
}

TEST_F(CommandLine, MissingSceneFileIsOneLineAndNonZeroStatus)
{
    const ProcessResult result = run({"no-such-scene.in", "32", "24", "--spp", "1"});
    ASSERT_TRUE(result.exited) << describe(result);
    EXPECT_NE(result.exitStatus, 0);
    const auto lines = nonEmptyLines(result.standardError);
    ASSERT_EQ(lines.size(), 1u) << describe(result);
    EXPECT_NE(lines[0].find("no-such-scene.in"), std::string::npos) << lines[0];
}

// --- outputs ----------------------------------------------------------------------------

TEST_F(CommandLine, SppRenderWritesFiniteNonBlackExrOfTheRequestedSize)
{
    const ProcessResult result =
        run({scene1(), "160", "120", "--spp", "16", "--output", "a.exr", "--headless"});
    ASSERT_TRUE(result.exited && result.exitStatus == 0) << describe(result);
    const io::Image image = io::readImage(folder_ / "a.exr");
    EXPECT_EQ(image.width, 160);
    EXPECT_EQ(image.height, 120);
    ASSERT_GE(image.channels, 3);
    int nonFinite = 0;
    double sum = 0.0;
    for (float value : image.pixels) {
        nonFinite += std::isfinite(value) ? 0 : 1;
        sum += std::isfinite(value) ? value : 0.0;
    }
    EXPECT_EQ(nonFinite, 0);
    EXPECT_GT(sum / image.pixels.size(), 0.01) << "the image should not be black";
}

// Reads a binary PPM's header and checks the pixel data is all there.
void expectValidPpm(const fs::path& path, int width, int height)
{
    std::ifstream file(path, std::ios::binary);
    ASSERT_TRUE(file) << path << " was not written";
    std::string magic;
    int fileWidth = 0;
    int fileHeight = 0;
    int maximum = 0;
    file >> magic >> fileWidth >> fileHeight >> maximum;
    file.get();  // the one whitespace byte before the pixels
    EXPECT_EQ(magic, "P6");
    EXPECT_EQ(fileWidth, width);
    EXPECT_EQ(fileHeight, height);
    EXPECT_EQ(maximum, 255);
    const std::string pixels((std::istreambuf_iterator<char>(file)),
                             std::istreambuf_iterator<char>());
    EXPECT_EQ(pixels.size(), static_cast<std::size_t>(width) * height * 3)
        << "a P6 file of " << width << "x" << height << " holds exactly that many RGB bytes";
    EXPECT_NE(pixels.find_first_not_of('\0'), std::string::npos) << "the picture is all black";
}

TEST_F(CommandLine, PpmOutputIsAValidBinaryPpm)
{
    const ProcessResult result =
        run({scene1(), "40", "30", "--spp", "4", "--output", "b.ppm", "--headless"});
    ASSERT_TRUE(result.exited && result.exitStatus == 0) << describe(result);
    expectValidPpm(folder_ / "b.ppm", 40, 30);
}

TEST_F(CommandLine, TimedRenderWritesScenePpmInTheWorkingFolderAfterItsSeconds)
{
    const ProcessResult result = run({scene1(), "160", "120", "2"});
    ASSERT_TRUE(result.exited && result.exitStatus == 0) << describe(result);
    EXPECT_GE(result.seconds, 1.5) << "a 2-second render ended after " << result.seconds << " s";
    EXPECT_LE(result.seconds, 30.0) << "a 2-second render took " << result.seconds << " s";
    expectValidPpm(folder_ / "scene1.ppm", 160, 120);
}

TEST_F(CommandLine, SummaryLineEndsEveryRender)
{
    const ProcessResult result =
        run({scene1(), "32", "24", "--spp", "3", "--output", "c.png", "--headless"});
    ASSERT_TRUE(result.exited && result.exitStatus == 0) << describe(result);
    const auto lines = nonEmptyLines(result.standardOutput);
    ASSERT_FALSE(lines.empty()) << describe(result);
    EXPECT_NE(lines.back().find("32x24, 3 spp"), std::string::npos) << lines.back();
}

TEST_F(CommandLine, InterruptDuringTimedRenderWritesTheImageAndExits130)
{
    // Sent once the progress line (on a terminal) shows a first frame done: an interrupt
    // before the first sample writes nothing (OutputSafetyTest.cpp).
    ProcessOptions options;
    options.terminalColumns = 200;
    options.signalWhenErrorShows = " spp";
    options.signal = SIGINT;
    const ProcessResult result = run({scene1(), "64", "48", "30", "--output", "i.exr"}, options);
    ASSERT_TRUE(result.exited) << "the program should catch SIGINT, write the image and exit; "
                               << describe(result);
    EXPECT_EQ(result.exitStatus, 130) << describe(result);
    EXPECT_LT(result.seconds, 15.0) << "the program should stop soon after the interrupt";
    ASSERT_TRUE(fs::exists(folder_ / "i.exr")) << "the image so far should be written";
    const io::Image image = io::readImage(folder_ / "i.exr");
    EXPECT_EQ(image.width, 64);
    EXPECT_EQ(image.height, 48);
}

// --- argument validation ------------------------------------------------------------------

struct BadArguments {
    const char* name;
    std::vector<std::string> arguments;  // after the scene
    const char* mentioned;               // the message must contain this
};

void PrintTo(const BadArguments& bad, std::ostream* out)
{
    *out << bad.name;
}

class InvalidArgument : public CommandLine, public ::testing::WithParamInterface<BadArguments> {};

TEST_P(InvalidArgument, IsRefusedWithAClearMessageAndNonZeroStatus)
{
    std::vector<std::string> arguments = {scene1()};
    for (const std::string& argument : GetParam().arguments)
        arguments.push_back(argument);
    const ProcessResult result = run(arguments);
    ASSERT_TRUE(result.exited) << describe(result);
    EXPECT_NE(result.exitStatus, 0) << describe(result);
    const auto lines = nonEmptyLines(result.standardError);
    ASSERT_EQ(lines.size(), 1u) << describe(result);
    EXPECT_NE(lines[0].find(GetParam().mentioned), std::string::npos)
        << "the message should mention '" << GetParam().mentioned << "': " << lines[0];
    EXPECT_EQ(filesInFolder(), std::vector<std::string>{}) << "nothing may be written";
}

INSTANTIATE_TEST_SUITE_P(
    Value, InvalidArgument,
    ::testing::Values(
        BadArguments{"WidthZero", {"0", "48", "--spp", "1"}, "WIDTH"},
        BadArguments{"WidthNegative", {"-64", "48", "--spp", "1"}, "WIDTH"},
        BadArguments{"WidthNotANumber", {"wide", "48", "--spp", "1"}, "WIDTH"},
        BadArguments{"WidthFractional", {"64.5", "48", "--spp", "1"}, "WIDTH"},
        BadArguments{"WidthAboveTheGlMaximum", {"40000", "4", "--spp", "1"}, "40000"},
        BadArguments{"HeightZero", {"64", "0", "--spp", "1"}, "HEIGHT"},
        BadArguments{"HeightNegative", {"64", "-1", "--spp", "1"}, "HEIGHT"},
        BadArguments{"HeightNotANumber", {"64", "tall", "--spp", "1"}, "HEIGHT"},
        BadArguments{"HeightAboveTheGlMaximum", {"4", "40000", "--spp", "1"}, "40000"},
        BadArguments{"SideAboveAnyLimit", {"64", "100000", "--spp", "1"}, "HEIGHT"},
        BadArguments{"SecondsZero", {"64", "48", "0"}, "SECONDS"},
        BadArguments{"SecondsNegative", {"64", "48", "-2"}, "SECONDS"},
        BadArguments{"SecondsNotANumber", {"64", "48", "soon"}, "SECONDS"},
        BadArguments{"SppZero", {"64", "48", "--spp", "0"}, "--spp"},
        BadArguments{"SppNegative", {"64", "48", "--spp", "-8"}, "--spp"},
        BadArguments{"SppNotANumber", {"64", "48", "--spp", "many"}, "--spp"},
        BadArguments{"SppAboveTheLimit", {"64", "48", "--spp", "99999999999"}, "--spp"},
        BadArguments{"SppWithoutValue", {"64", "48", "--spp"}, "--spp"},
        BadArguments{"WidthWithoutHeight", {"64", "--spp", "1"}, "HEIGHT"},
        BadArguments{"UnknownOption", {"--fast"}, "--fast"},
        BadArguments{"UnknownOutputFormat", {"8", "8", "--spp", "1", "--output", "x.doc"}, "x.doc"},
        BadArguments{"SppGivenTwice", {"8", "8", "--spp", "4", "--spp", "8"}, "--spp"},
        BadArguments{"OutputGivenTwiceUnderTwoNames",
                     {"8", "8", "--spp", "1", "-o", "a.png", "--output", "b.png"},
                     "--output"},
        BadArguments{"FlagGivenTwice", {"8", "8", "--spp", "1", "--quiet", "--quiet"}, "--quiet"}),
    [](const ::testing::TestParamInfo<BadArguments>& info) {
        return std::string(info.param.name);
    });

TEST_F(CommandLine, HelpPrintsUsageAndSucceeds)
{
    const ProcessResult result = run({"--help"});
    ASSERT_TRUE(result.exited) << describe(result);
    EXPECT_EQ(result.exitStatus, 0);
    EXPECT_NE(result.standardOutput.find("usage: raytracer SCENE"), std::string::npos)
        << result.standardOutput;
    EXPECT_NE(result.standardOutput.find("--spp"), std::string::npos);
    EXPECT_TRUE(result.standardError.empty()) << result.standardError;
}

TEST_F(CommandLine, HelpLinesFitIn100Columns)
{
    const ProcessResult result = run({"--help"});
    ASSERT_TRUE(result.exited && result.exitStatus == 0) << describe(result);
    std::istringstream lines(result.standardOutput);
    std::string line;
    while (std::getline(lines, line))
        EXPECT_LE(line.size(), 100u) << "a --help line of " << line.size() << " columns: " << line;
}

// Every extension --output accepts, with what it holds.
const std::vector<std::string> kOutputExtensions = {".ppm", ".png", ".jpg", ".tif",
                                                    ".exr", ".pfm", ".hdr"};

TEST_F(CommandLine, HelpNamesEveryAcceptedOutputExtension)
{
    const ProcessResult result = run({"--help"});
    ASSERT_TRUE(result.exited && result.exitStatus == 0) << describe(result);
    for (const std::string& extension : kOutputExtensions)
        EXPECT_NE(result.standardOutput.find(extension), std::string::npos)
            << "--help should name " << extension;
    EXPECT_NE(result.standardOutput.find("linear"), std::string::npos) << result.standardOutput;
}

TEST_F(CommandLine, ReadmeNamesEveryAcceptedOutputExtension)
{
    std::ifstream readme(sourceDirectory() / "README.md");
    std::ostringstream text;
    text << readme.rdbuf();
    for (const std::string& extension : kOutputExtensions)
        EXPECT_NE(text.str().find("`" + extension + "`"), std::string::npos)
            << "README.md should name `" << extension << "`";
}

TEST_F(CommandLine, EveryDocumentedOutputExtensionIsWritten)
{
    for (const std::string& extension : kOutputExtensions) {
        const std::string name = "x" + extension;
        const ProcessResult result =
            run({scene1(), "8", "6", "--spp", "1", "--quiet", "--output", name});
        ASSERT_TRUE(result.exited && result.exitStatus == 0) << name << ": " << describe(result);
        const io::Image image = io::readImage(folder_ / name);
        EXPECT_EQ(image.width, 8) << name;
        EXPECT_EQ(image.height, 6) << name;
    }
}

TEST_F(CommandLine, VersionPrintsTheVersionAndSucceeds)
{
    const ProcessResult result = run({"--version"});
    ASSERT_TRUE(result.exited) << describe(result);
    EXPECT_EQ(result.exitStatus, 0);
    const auto lines = nonEmptyLines(result.standardOutput);
    ASSERT_EQ(lines.size(), 1u) << result.standardOutput;
    EXPECT_EQ(lines[0].rfind("raytracer ", 0), 0u) << lines[0];
    EXPECT_NE(lines[0].find_first_of("0123456789"), std::string::npos) << lines[0];
}

TEST_F(CommandLine, WithoutArgumentsSaysASceneIsNeeded)
{
    const ProcessResult result = run({});
    ASSERT_TRUE(result.exited) << describe(result);
    EXPECT_NE(result.exitStatus, 0);
    EXPECT_EQ(nonEmptyLines(result.standardError).size(), 1u) << describe(result);
}

TEST_F(CommandLine, SameSeedAndSampleCountGiveTheSameImage)
{
    for (const char* name : {"first.exr", "second.exr"}) {
        const ProcessResult result =
            run({scene1(), "32", "24", "--spp", "4", "--seed", "9", "--output", name});
        ASSERT_TRUE(result.exited && result.exitStatus == 0) << describe(result);
    }
    const io::Image first = io::readImage(folder_ / "first.exr");
    const io::Image second = io::readImage(folder_ / "second.exr");
    EXPECT_EQ(first.pixels, second.pixels) << "--spp with --seed must be deterministic";
}

}  // namespace
}  // namespace cli_tests
