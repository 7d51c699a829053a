// No file lost or wrong: outputs are checked before the render starts, written all or not at
// all, never two into one file, and never an image without a sample in it.
#include "app/ProgramInFolder.h"
#include "io/ImageFile.h"
#include "support/ChildProcess.h"
#include "support/SmallDisk.h"
#include "support/TestPaths.h"

#include <gtest/gtest.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <memory>
#include <sstream>
#include <sys/wait.h>
#include <unistd.h>

namespace cli_tests {
namespace {

using namespace testing_support;
namespace fs = std::filesystem;

class Outputs : public ProgramInFolder {
protected:
    std::string scene1() const { return (sourceDirectory() / "scenes" / "scene1.in").string(); }

    std::string contents(const fs::path& name) const
    {
        std::ifstream file(folder_ / name, std::ios::binary);
        std::ostringstream text;
        text << file.rdbuf();
        return text.str();
    }

    // An interrupt before the first sample: status 130, soon, and out.exr as it was.
    void expectInterruptedWithTheOlderFileKept(const ProcessResult& result) const
    {
        ASSERT_TRUE(result.exited) << describe(result);
        EXPECT_EQ(result.exitStatus, 130) << describe(result);
        EXPECT_LT(result.seconds, 30.0) << "the render should stop soon after the interrupt";
        EXPECT_EQ(contents("out.exr"), "an earlier render") << "the older file must be kept";
        EXPECT_EQ(filesInFolder(), std::vector<std::string>{"out.exr"}) << "nothing else written";
    }
};

// --- checked before the render ------------------------------------------------------------

struct UnwritableOutput {
    const char* name;
    std::vector<std::string> outputOptions;  // the options naming the outputs
    const char* userPath;                    // the path the message must name
    int reason;                              // errno whose strerror the message must hold
};

void PrintTo(const UnwritableOutput& output, std::ostream* out)
{
    *out << output.name;
}

class UnwritableOutputPath : public Outputs,
                             public ::testing::WithParamInterface<UnwritableOutput> {};

// A 20-second render that reaches its end only if nothing was checked at the start.
TEST_P(UnwritableOutputPath, FailsAtOnceWithTheSystemsReasonAndTheUsersPath)
{
    write("plain-file", "not a folder");
    std::vector<std::string> arguments = {scene1(), "32", "24", "20"};
    for (const std::string& option : GetParam().outputOptions)
        arguments.push_back(option);
    const ProcessResult result = run(arguments);

    ASSERT_TRUE(result.exited) << describe(result);
    EXPECT_EQ(result.exitStatus, 1) << describe(result);
    EXPECT_LT(result.seconds, 10.0) << "the path must be refused before the 20-second render";
    const auto lines = nonEmptyLines(result.standardError);
    ASSERT_EQ(lines.size(), 1u) << describe(result);
    EXPECT_NE(lines[0].find(GetParam().userPath), std::string::npos) << lines[0];
    EXPECT_NE(lines[0].find(std::strerror(GetParam().reason)), std::string::npos) << lines[0];
    EXPECT_EQ(lines[0].find(".partial"), std::string::npos)
        << "the message must not name a temporary file: " << lines[0];
    EXPECT_EQ(filesInFolder(), std::vector<std::string>{"plain-file"}) << "nothing written";
}

INSTANTIATE_TEST_SUITE_P(
    Output, UnwritableOutputPath,
    ::testing::Values(
        UnwritableOutput{
            "PngInAMissingFolder", {"--output", "missing/x.png"}, "missing/x.png", ENOENT},
        UnwritableOutput{
            "PfmInAMissingFolder", {"--output", "missing/x.pfm"}, "missing/x.pfm", ENOENT},
        UnwritableOutput{
            "ExrUnderAPlainFile", {"--output", "plain-file/x.exr"}, "plain-file/x.exr", ENOTDIR},
        UnwritableOutput{"OutputThatIsAFolder", {"--output", "./"}, "./", EISDIR},
        UnwritableOutput{"StatisticsInAMissingFolder",
                         {"--output", "a.png", "--stats-output", "missing/s.exr"},
                         "missing/s.exr",
                         ENOENT}),
    [](const ::testing::TestParamInfo<UnwritableOutput>& info) {
        return std::string(info.param.name);
    });

TEST_F(Outputs, AFolderWithoutWritePermissionFailsAtOnceWithTheSystemsReason)
{
    if (::geteuid() == 0)
        GTEST_SKIP() << "root may write into any folder whatever its permissions";
    fs::create_directories(folder_ / "locked");
    fs::permissions(folder_ / "locked", fs::perms::owner_read | fs::perms::owner_exec);
    const ProcessResult result = run({scene1(), "32", "24", "20", "--output", "locked/x.png"});
    fs::permissions(folder_ / "locked", fs::perms::owner_all);
    ASSERT_TRUE(result.exited) << describe(result);
    EXPECT_EQ(result.exitStatus, 1) << describe(result);
    EXPECT_LT(result.seconds, 10.0);
    EXPECT_NE(result.standardError.find("locked/x.png"), std::string::npos) << describe(result);
    EXPECT_NE(result.standardError.find(std::strerror(EACCES)), std::string::npos)
        << describe(result);
}

TEST_F(Outputs, AnExtensionOutsideTheDocumentedListIsRefused)
{
    // OpenImageIO writes Targa; the program promises only the formats it documents.
    const ProcessResult result = run({scene1(), "8", "8", "--spp", "1", "--output", "x.tga"});
    ASSERT_TRUE(result.exited) << describe(result);
    EXPECT_EQ(result.exitStatus, 1) << describe(result);
    EXPECT_NE(result.standardError.find("x.tga"), std::string::npos) << describe(result);
    EXPECT_EQ(filesInFolder(), std::vector<std::string>{}) << "nothing written";
}

TEST_F(Outputs, StatisticsInAPictureFormatAreRefused)
{
    const ProcessResult result =
        run({scene1(), "8", "8", "--spp", "1", "--output", "a.exr", "--stats-output", "s.png"});
    ASSERT_TRUE(result.exited) << describe(result);
    EXPECT_EQ(result.exitStatus, 1) << describe(result);
    EXPECT_NE(result.standardError.find("s.png"), std::string::npos) << describe(result);
    EXPECT_EQ(filesInFolder(), std::vector<std::string>{}) << "nothing written";
}

// --- never two outputs in one file --------------------------------------------------------

TEST_F(Outputs, OutputAndStatisticsNamingOneFileAreRefused)
{
    const ProcessResult result = run(
        {scene1(), "8", "8", "--spp", "1", "--output", "same.exr", "--stats-output", "./same.exr"});
    ASSERT_TRUE(result.exited) << describe(result);
    EXPECT_EQ(result.exitStatus, 2) << describe(result);
    const auto lines = nonEmptyLines(result.standardError);
    ASSERT_EQ(lines.size(), 1u) << describe(result);
    EXPECT_NE(lines[0].find("same.exr"), std::string::npos) << lines[0];
    EXPECT_EQ(filesInFolder(), std::vector<std::string>{}) << "nothing written";
}

TEST_F(Outputs, OutputAndStatisticsNamingOneFileThroughALinkedFolderAreRefused)
{
    fs::create_directories(folder_ / "real");
    fs::create_directory_symlink(folder_ / "real", folder_ / "link");
    const ProcessResult result = run({scene1(), "8", "8", "--spp", "1", "--output", "real/same.exr",
                                      "--stats-output", "link/same.exr"});
    ASSERT_TRUE(result.exited) << describe(result);
    EXPECT_EQ(result.exitStatus, 2) << describe(result);
    EXPECT_TRUE(fs::is_empty(folder_ / "real")) << "nothing written";
}

// --- never an image without a sample -------------------------------------------------------

TEST_F(Outputs, InterruptBeforeTheFirstSampleWritesNothingAndKeepsTheOlderFile)
{
    write("out.exr", "an earlier render");
    // Sent at once, and held pending until the program watches for it: the interrupt comes
    // before the scene is even read.
    ProcessOptions options;
    options.signalAfterSeconds = 0.0;
    options.startWithSignalBlocked = true;
    options.signal = SIGINT;
    const ProcessResult result =
        run({scene1(), "64", "48", "--spp", "64", "--output", "out.exr"}, options);
    expectInterruptedWithTheOlderFileKept(result);
    const auto lines = nonEmptyLines(result.standardOutput);
    ASSERT_FALSE(lines.empty()) << describe(result);
    EXPECT_NE(lines.back().find("nothing written"), std::string::npos) << lines.back();
    EXPECT_NE(lines.back().find("interrupted"), std::string::npos) << lines.back();
}

TEST_F(Outputs, InterruptedImageIsMarkedAsInterrupted)
{
    ProcessOptions options;
    options.terminalColumns = 200;
    options.signalWhenErrorShows = " spp";  // the progress line: a first frame is done
    options.signal = SIGINT;
    const ProcessResult result =
        run({scene1(), "32", "24", "--spp", "16777216", "--output", "i.exr"}, options);
    ASSERT_TRUE(result.exited) << describe(result);
    EXPECT_EQ(result.exitStatus, 130) << describe(result);
    ASSERT_TRUE(fs::exists(folder_ / "i.exr")) << describe(result);
    const auto mark = io::readImageAttribute(folder_ / "i.exr", "raytracer:interrupted");
    ASSERT_TRUE(mark.has_value()) << "the file should say it was interrupted";
    EXPECT_NE(mark->find("of 16777216 samples per pixel"), std::string::npos) << *mark;
}

TEST_F(Outputs, ACompleteRenderIsNotMarkedAsInterrupted)
{
    const ProcessResult result = run({scene1(), "8", "8", "--spp", "2", "--output", "c.exr"});
    ASSERT_TRUE(result.exited && result.exitStatus == 0) << describe(result);
    EXPECT_FALSE(io::readImageAttribute(folder_ / "c.exr", "raytracer:interrupted").has_value());
}

TEST_F(Outputs, InterruptDuringALongFirstFrameStopsItAndWritesNothing)
{
    write("out.exr", "an earlier render");
    // One frame of 64 paths per pixel at 1280x960 takes minutes on a software rasteriser; the
    // render must stop within a band of it, not at its end.
    ProcessOptions options;
    options.signalAfterSeconds = 4.0;
    options.startWithSignalBlocked = true;
    options.signal = SIGINT;
    const ProcessResult result = run({scene1(), "1280", "960", "--spp", "64", "--samples-per-frame",
                                      "64", "--output", "out.exr"},
                                     options);
    expectInterruptedWithTheOlderFileKept(result);
}

TEST_F(Outputs, ATimedRenderTooShortForOneSampleWritesNothingAndSaysSo)
{
    write("out.png", "an earlier render");
    const ProcessResult result =
        run({scene1(), "640", "480", "0.001", "--samples-per-frame", "64", "--output", "out.png"});
    ASSERT_TRUE(result.exited) << describe(result);
    EXPECT_EQ(result.exitStatus, 1) << describe(result);
    EXPECT_EQ(contents("out.png"), "an earlier render") << "the older file must be kept";
    EXPECT_EQ(filesInFolder(), std::vector<std::string>{"out.png"});
    EXPECT_NE(result.standardError.find("nothing written"), std::string::npos) << describe(result);
}

// --- a full disk loses nothing ----------------------------------------------------------

// Renders onto a 64 KB tmpfs mounted in the test's folder as disk/, filled but for one page.
class FullDisk : public Outputs, public ::testing::WithParamInterface<std::string> {
protected:
    void SetUp() override
    {
        Outputs::SetUp();
        disk_ = std::make_unique<SmallDisk>(folder_ / "disk", "64k");
        if (!disk_->mounted())
            GTEST_SKIP() << disk_->whyNotMounted();
    }
    void TearDown() override
    {
        disk_.reset();
        Outputs::TearDown();
    }

    // Exit status 1, one line on standard error naming the user's path and the system's
    // reason, the older file as it was and nothing else on the disk.
    void expectRefusedKeepingTheOlderFile(const ProcessResult& result,
                                          const std::vector<std::string>& paths) const
    {
        ASSERT_TRUE(result.exited) << describe(result);
        EXPECT_EQ(result.exitStatus, 1) << describe(result);
        const auto lines = nonEmptyLines(result.standardError);
        ASSERT_EQ(lines.size(), 1u) << describe(result);
        EXPECT_EQ(lines[0].rfind("raytracer: cannot write disk/", 0), 0u) << lines[0];
        EXPECT_NE(lines[0].find(std::strerror(ENOSPC)), std::string::npos) << lines[0];
        std::vector<std::string> onDisk = {"filler"};
        for (const std::string& path : paths) {
            EXPECT_EQ(contents("disk/" + path), "an earlier render")
                << "disk/" << path << " must be kept as it was";
            onDisk.push_back(path);
        }
        std::sort(onDisk.begin(), onDisk.end());
        std::vector<std::string> found;
        for (const auto& entry : fs::directory_iterator(folder_ / "disk"))
            found.push_back(entry.path().filename().string());
        std::sort(found.begin(), found.end());
        EXPECT_EQ(found, onDisk) << "no temporary file may be left";
    }

    std::unique_ptr<SmallDisk> disk_;
};

TEST_P(FullDisk, ARenderThatDoesNotFitSaysSoAndKeepsTheOlderFile)
{
    // PNG and TIFF were renamed over the older file cut short, with exit status 0; JPEG's
    // library ended the process, leaving its temporary file.
    const std::string name = "out" + GetParam();
    write("disk/" + name, "an earlier render");
    ASSERT_TRUE(disk_->fillLeaving(4096));
    // 160x30: more than a page in each format, and one strip of TIFF, written as it closes.
    const ProcessResult result =
        run({scene1(), "160", "30", "--spp", "1", "--quiet", "--output", "disk/" + name});
    expectRefusedKeepingTheOlderFile(result, {name});
}

INSTANTIATE_TEST_SUITE_P(PictureFormats, FullDisk, ::testing::Values(".png", ".jpg", ".tif"),
                         [](const ::testing::TestParamInfo<std::string>& info) {
                             return info.param.substr(1);
                         });

TEST_F(Outputs, AMergeWhosePictureDoesNotFitWritesNeitherFile)
{
    // The EXR fitted and the PNG did not: the PNG was renamed over the older one, 0 bytes
    // long, with exit status 0.
    SmallDisk disk(folder_ / "disk", "256k");
    if (!disk.mounted())
        GTEST_SKIP() << disk.whyNotMounted();
    for (const char* seed : {"1", "2"}) {
        const ProcessResult rendered = run({scene1(), "48", "36", "--spp", "1", "--seed", seed,
                                            "--quiet", "--output", std::string(seed) + ".exr"});
        ASSERT_TRUE(rendered.exited && rendered.exitStatus == 0) << describe(rendered);
    }
    // The sizes of the two files, from the same merge where there is room.
    const ProcessResult measured = run({"merge", "m.exr", "1.exr", "2.exr", "--png", "m.png"});
    ASSERT_TRUE(measured.exited && measured.exitStatus == 0) << describe(measured);
    const std::uintmax_t exrPages = (fs::file_size(folder_ / "m.exr") + 4095) / 4096;
    ASSERT_GT(fs::file_size(folder_ / "m.png"), 4096u) << "the PNG must need more than a page";
    write("disk/m.png", "an earlier render");
    ASSERT_TRUE(disk.fillLeaving(exrPages * 4096));  // room for the EXR, none for the PNG
    const ProcessResult result =
        run({"merge", "disk/m.exr", "1.exr", "2.exr", "--png", "disk/m.png"});
    ASSERT_TRUE(result.exited) << describe(result);
    EXPECT_EQ(result.exitStatus, 1) << describe(result);
    EXPECT_NE(
        result.standardError.find("cannot write disk/m.png: " + std::string(std::strerror(ENOSPC))),
        std::string::npos)
        << describe(result);
    EXPECT_EQ(contents("disk/m.png"), "an earlier render");
    std::vector<std::string> onDisk;
    for (const auto& entry : fs::directory_iterator(folder_ / "disk"))
        onDisk.push_back(entry.path().filename().string());
    std::sort(onDisk.begin(), onDisk.end());
    EXPECT_EQ(onDisk, (std::vector<std::string>{"filler", "m.png"}))
        << "neither file written, no temporary file left";
}

// --- temporary files a killed render left -----------------------------------------------

TEST_F(Outputs, ARenderRemovesTheTemporaryFilesOfItsOutputThatAnEndedProcessLeftAndSaysSo)
{
    const pid_t ended = ::fork();
    if (ended == 0)
        ::_exit(0);
    ::waitpid(ended, nullptr, 0);
    char host[256] = {};
    ::gethostname(host, sizeof host - 1);
    const std::string left =
        ".out.partial-" + std::string(host) + "-" + std::to_string(ended) + "-0.exr";
    write(left, std::string(100000, 'x'));
    write("other.exr", "another render's");
    const ProcessResult result = run({scene1(), "8", "6", "--spp", "1", "--output", "out.exr"});
    ASSERT_TRUE(result.exited && result.exitStatus == 0) << describe(result);
    const auto lines = nonEmptyLines(result.standardOutput);
    ASSERT_GE(lines.size(), 2u) << describe(result);
    EXPECT_NE(lines[0].find("removed ./" + left + ", a temporary file left by process " +
                            std::to_string(ended) + ", which no longer runs"),
              std::string::npos)
        << lines[0];
    EXPECT_EQ(filesInFolder(), (std::vector<std::string>{"other.exr", "out.exr"}));
}

}  // namespace
}  // namespace cli_tests
