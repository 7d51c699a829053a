// The output files' promise (io/OutputFiles.h): checked before any work, written all or none,
// never two into one file, never a temporary name in a message.
#include "io/ImageFile.h"
#include "io/OutputFiles.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <random>
#include <sstream>
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
        EXPECT_EQ(messageOfCheck({{folder_ / name, io::OutputKind::Image}}), "(accepted)")
            << name;
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
        EXPECT_NE(messageOfCheck({{folder_ / name, io::OutputKind::Statistics}})
                      .find("32-bit float"),
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
    EXPECT_THROW(io::writeAllOrNothing({{folder_ / "a.exr", good, {}, {}},
                                        {folder_ / "b.pfm", twoChannels, {}, {}}}),
                 std::runtime_error);
    EXPECT_EQ(contents(folder_ / "a.exr"), "older");
    EXPECT_EQ(files(), std::vector<std::string>{"a.exr"}) << "no temporary file is left";
}

TEST_F(OutputFiles, BothImagesAreWrittenWhenBothSucceed)
{
    const io::Image image = gradient(3);
    io::writeAllOrNothing(
        {{folder_ / "a.exr", image, {}, {}}, {folder_ / "b.pfm", image, {}, {}}});
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
        const int written = static_cast<int>(
            std::find(names.begin(), names.end(), name) - names.begin());
        for (int y = 0; y < image.height; ++y)
            for (int x = 0; x < image.width; ++x)
                EXPECT_EQ(file.image.at(x, y, index), image.at(x, y, written)) << name;
    }
    const auto note = std::find_if(file.attributes.begin(), file.attributes.end(),
                                   [](const io::ImageAttribute& a) { return a.name == "raytracer:note"; });
    ASSERT_NE(note, file.attributes.end());
    EXPECT_EQ(note->value, "a test");
}

}  // namespace
}  // namespace io_tests
