// The output files' promise (io/OutputFiles.h): checked before any work, written all or none,
// never two into one file, never a temporary name in a message.
#include "io/OutputFiles.h"
#include "io/ImageFile.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cerrno>
#include <csignal>
#include <cstring>
#include <fstream>
#include <random>
#include <sstream>
#include <sys/wait.h>
#include <unistd.h>

namespace io_tests {
namespace {

namespace fs = std::filesystem;

class OutputFiles : public ::testing::Test {
protected:
    void SetUp() override
    {
        folder_ = fs::temp_directory_path() /
                  ("raytracer-output-files-" + std::to_string(std::random_device{}()));
        fs::create_directories(folder_);
    }
    void TearDown() override { fs::remove_all(folder_); }

    std::string messageOfCheck(const std::vector<io::OutputRequest>& outputs) const
    {
        try {
            io::checkOutputsCanBeWritten(outputs);
        } catch (const std::exception& error) {
            return error.what();
        }
        return "(accepted)";
    }
    std::vector<std::string> files() const
    {
        std::vector<std::string> names;
        for (const auto& entry : fs::directory_iterator(folder_))
            names.push_back(entry.path().filename().string());
        std::sort(names.begin(), names.end());
        return names;
    }
    std::string contents(const fs::path& path) const
    {
        std::ifstream file(path, std::ios::binary);
        std::ostringstream text;
        text << file.rdbuf();
        return text.str();
    }
    static io::Image gradient(int channels)
    {
        io::Image image(4, 3, channels);
        for (std::size_t i = 0; i < image.pixels.size(); ++i)
            image.pixels[i] = 0.1f * static_cast<float>(i % 10);
        return image;
    }
    fs::path folder_;
};

TEST_F(OutputFiles, EveryDocumentedFormatPassesTheCheck)
{
    for (const char* name : {"a.ppm", "a.png", "a.jpg", "a.jpeg", "a.tif", "a.tiff", "a.exr",
                             "a.pfm", "a.hdr", "A.EXR"})
        EXPECT_EQ(messageOfCheck({{folder_ / name, io::OutputKind::Image}}), "(accepted)") << name;
}

TEST_F(OutputFiles, AMissingFolderIsRefusedWithTheReasonAndTheUsersPath)
{
    const fs::path path = folder_ / "missing" / "x.png";
    const std::string message = messageOfCheck({{path, io::OutputKind::Image}});
    EXPECT_NE(message.find(path.string()), std::string::npos) << message;
    EXPECT_NE(message.find(std::strerror(ENOENT)), std::string::npos) << message;
}

TEST_F(OutputFiles, StatisticsOnlyInThirtyTwoBitFloatFormats)
{
    EXPECT_EQ(messageOfCheck({{folder_ / "s.exr", io::OutputKind::Statistics}}), "(accepted)");
    EXPECT_EQ(messageOfCheck({{folder_ / "s.pfm", io::OutputKind::Statistics}}), "(accepted)");
    for (const char* name : {"s.png", "s.hdr", "s.ppm"})
        EXPECT_NE(
            messageOfCheck({{folder_ / name, io::OutputKind::Statistics}}).find("32-bit float"),
            std::string::npos)
            << name;
}

TEST_F(OutputFiles, TwoSpellingsOfOnePathResolveToTheSameFile)
{
    fs::create_directories(folder_ / "sub");
    EXPECT_TRUE(io::resolveToSameFile(folder_ / "a.exr", folder_ / "sub" / ".." / "a.exr"));
    EXPECT_TRUE(io::resolveToSameFile(folder_ / "a.exr", folder_ / "." / "a.exr"));
    EXPECT_FALSE(io::resolveToSameFile(folder_ / "a.exr", folder_ / "b.exr"));
}

TEST_F(OutputFiles, AHardLinkResolvesToTheSameFile)
{
    std::ofstream(folder_ / "a.exr") << "x";
    fs::create_hard_link(folder_ / "a.exr", folder_ / "b.exr");
    EXPECT_TRUE(io::resolveToSameFile(folder_ / "a.exr", folder_ / "b.exr"));
}

TEST_F(OutputFiles, WhenTheSecondImageFailsNeitherIsWrittenAndTheOlderFileIsKept)
{
    std::ofstream(folder_ / "a.exr") << "older";
    const io::Image good = gradient(3);
    const io::Image twoChannels = gradient(2);  // PFM holds one or three channels
    EXPECT_THROW(io::writeAllOrNothing(
                     {{folder_ / "a.exr", good, {}, {}}, {folder_ / "b.pfm", twoChannels, {}, {}}}),
                 std::runtime_error);
    EXPECT_EQ(contents(folder_ / "a.exr"), "older");
    EXPECT_EQ(files(), std::vector<std::string>{"a.exr"}) << "no temporary file is left";
}

TEST_F(OutputFiles, BothImagesAreWrittenWhenBothSucceed)
{
    const io::Image image = gradient(3);
    io::writeAllOrNothing({{folder_ / "a.exr", image, {}, {}}, {folder_ / "b.pfm", image, {}, {}}});
    EXPECT_EQ(files(), (std::vector<std::string>{"a.exr", "b.pfm"}));
    EXPECT_EQ(io::readImage(folder_ / "a.exr").pixels, image.pixels);
    EXPECT_EQ(io::readImage(folder_ / "b.pfm").pixels, image.pixels);
}

TEST_F(OutputFiles, AFailedPfmWriteNamesTheUsersPathAndTheReason)
{
    const io::Image image = gradient(3);
    const fs::path path = folder_ / "missing" / "x.pfm";
    try {
        io::writeImage(path, image);
        FAIL() << "writing into a missing folder should fail";
    } catch (const std::runtime_error& error) {
        const std::string message = error.what();
        EXPECT_NE(message.find(path.string()), std::string::npos) << message;
        EXPECT_NE(message.find(std::strerror(ENOENT)), std::string::npos) << message;
        EXPECT_EQ(message.find(".partial"), std::string::npos) << message;
    }
}

TEST_F(OutputFiles, AFailedOpenImageIoWriteNamesTheUsersPathNotTheTemporaryOne)
{
    const io::Image image = gradient(3);
    const fs::path path = folder_ / "missing" / "x.png";
    try {
        io::writeImage(path, image);
        FAIL() << "writing into a missing folder should fail";
    } catch (const std::runtime_error& error) {
        const std::string message = error.what();
        EXPECT_NE(message.find(path.string()), std::string::npos) << message;
        EXPECT_EQ(message.find(".partial"), std::string::npos) << message;
    }
}

TEST_F(OutputFiles, AttributesAreWrittenIntoFormatsThatHoldThem)
{
    const io::Image image = gradient(3);
    for (const char* name : {"a.exr", "a.png"}) {
        io::writeImage(folder_ / name, image, {{"raytracer:note", "a test"}});
        EXPECT_EQ(io::readImageAttribute(folder_ / name, "raytracer:note"),
                  std::optional<std::string>("a test"))
            << name;
    }
}

TEST_F(OutputFiles, ChannelNamesAndAttributesComeBackFromAnExrAsWritten)
{
    const io::Image image = gradient(5);
    const std::vector<std::string> names = {"R", "G", "B", "samples", "layer.detail"};
    io::writeAllOrNothing({{folder_ / "a.exr", image, {{"raytracer:note", "a test"}}, names}});
    const io::ImageFileContents file = io::readImageFile(folder_ / "a.exr");
    ASSERT_EQ(file.image.channels, 5);
    for (const std::string& name : names) {
        const int index = file.channelIndex(name);
        ASSERT_GE(index, 0) << "no channel " << name;
        const int written =
            static_cast<int>(std::find(names.begin(), names.end(), name) - names.begin());
        for (int y = 0; y < image.height; ++y)
            for (int x = 0; x < image.width; ++x)
                EXPECT_EQ(file.image.at(x, y, index), image.at(x, y, written)) << name;
    }
    const auto note =
        std::find_if(file.attributes.begin(), file.attributes.end(),
                     [](const io::ImageAttribute& a) { return a.name == "raytracer:note"; });
    ASSERT_NE(note, file.attributes.end());
    EXPECT_EQ(note->value, "a test");
}

// --- temporary files left by a killed run -------------------------------------------------

// The number of a process that has ended (and been reaped): no process of it runs now.
long endedProcessId()
{
    const pid_t child = ::fork();
    if (child == 0)
        ::_exit(0);
    ::waitpid(child, nullptr, 0);
    return child;
}

std::string thisHost()
{
    char name[256] = {};
    ::gethostname(name, sizeof name - 1);
    return name;
}

TEST_F(OutputFiles, TemporariesOfTheDestinationWhoseProcessEndedAreRemoved)
{
    const long ended = endedProcessId();
    const std::string host = thisHost();
    const std::string endedHere = ".out.partial-" + host + "-" + std::to_string(ended) + "-0.exr";
    const std::string earlierName = ".out.partial-" + std::to_string(ended) + "-1.exr";
    const std::string running =
        ".out.partial-" + host + "-" + std::to_string(::getppid()) + "-0.exr";
    const std::string otherMachine = ".out.partial-elsewhere-" + std::to_string(ended) + "-0.exr";
    const std::string otherOutput =
        ".other.partial-" + host + "-" + std::to_string(ended) + "-0.exr";
    const std::string otherFormat = ".out.partial-" + host + "-" + std::to_string(ended) + "-0.png";
    for (const std::string& name :
         {endedHere, earlierName, running, otherMachine, otherOutput, otherFormat})
        std::ofstream(folder_ / name) << "21 MB of an image";

    const std::vector<io::StaleTemporary> removed =
        io::removeStaleTemporaries({folder_ / "out.exr"});

    std::vector<std::string> removedNames;
    for (const io::StaleTemporary& temporary : removed) {
        removedNames.push_back(temporary.path.filename().string());
        EXPECT_EQ(temporary.processId, ended);
    }
    std::sort(removedNames.begin(), removedNames.end());
    EXPECT_EQ(removedNames, (std::vector<std::string>{earlierName, endedHere}));
    std::vector<std::string> left = {running, otherMachine, otherOutput, otherFormat};
    std::sort(left.begin(), left.end());
    EXPECT_EQ(files(), left) << "a running process's, another machine's, another output's "
                                "temporary files are left";
}

TEST_F(OutputFiles, ALinkNamedLikeATemporaryIsNotFollowed)
{
    std::ofstream(folder_ / "precious") << "kept";
    const std::string name =
        ".out.partial-" + thisHost() + "-" + std::to_string(endedProcessId()) + "-0.exr";
    fs::create_symlink(folder_ / "precious", folder_ / name);
    EXPECT_TRUE(io::removeStaleTemporaries({folder_ / "out.exr"}).empty());
    EXPECT_EQ(contents(folder_ / "precious"), "kept");
}

TEST_F(OutputFiles, ATemporaryLeftByAKilledWriterIsRecognisedAndRemoved)
{
    // A child process makes the temporary file writeAllOrNothing would write, and is killed
    // before it renames it.
    const pid_t child = ::fork();
    if (child == 0) {
        std::ofstream(io::temporaryNameFor(folder_ / "a.png", 0)) << "half an image";
        ::pause();
        ::_exit(0);
    }
    while (files().empty())
        ::usleep(1000);
    EXPECT_TRUE(io::removeStaleTemporaries({folder_ / "a.png"}).empty())
        << "its process still runs";
    ::kill(child, SIGKILL);
    ::waitpid(child, nullptr, 0);
    const std::vector<io::StaleTemporary> removed = io::removeStaleTemporaries({folder_ / "a.png"});
    ASSERT_EQ(removed.size(), 1u);
    EXPECT_EQ(removed[0].processId, child);
    EXPECT_TRUE(files().empty());
}

}  // namespace
}  // namespace io_tests
