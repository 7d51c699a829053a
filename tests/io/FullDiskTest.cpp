// A full disk loses nothing (io/OutputFiles.h): writing any format onto a disk with one page
// free fails with the system's reason and the user's path, leaves the older file as it was
// and no temporary file. The disk is a 64 KB tmpfs mounted for the test (root or CAP_SYS_ADMIN;
// skipped, with the reason, where mounting is not allowed).
#include "io/ImageFile.h"
#include "io/OutputFiles.h"
#include "support/SmallDisk.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <memory>
#include <random>
#include <sstream>

namespace io_tests {
namespace {

namespace fs = std::filesystem;

class FullDisk : public ::testing::TestWithParam<std::string> {
protected:
    void SetUp() override
    {
        root_ = fs::temp_directory_path() /
                ("raytracer-full-disk-" + std::to_string(std::random_device{}()));
        folder_ = root_ / "disk";
        disk_ = std::make_unique<testing_support::SmallDisk>(folder_, "64k");
        if (!disk_->mounted())
            GTEST_SKIP() << disk_->whyNotMounted();
    }
    void TearDown() override
    {
        disk_.reset();
        fs::remove_all(root_);
    }

    std::string contents(const fs::path& path) const
    {
        std::ifstream file(path, std::ios::binary);
        std::ostringstream text;
        text << file.rdbuf();
        return text.str();
    }

    std::vector<std::string> files() const
    {
        std::vector<std::string> names;
        for (const auto& entry : fs::directory_iterator(folder_))
            names.push_back(entry.path().filename().string());
        std::sort(names.begin(), names.end());
        return names;
    }

    // 160x30 of noise: no format compresses it into the page left, and TIFF writes it as one
    // strip, when the file is closed (where a failed write went unreported).
    static io::Image noise()
    {
        io::Image image(160, 30, 3);
        std::mt19937 random(35);
        std::uniform_real_distribution<float> uniform(0.0f, 1.0f);
        for (float& value : image.pixels)
            value = uniform(random);
        return image;
    }

    fs::path root_;
    fs::path folder_;
    std::unique_ptr<testing_support::SmallDisk> disk_;
};

TEST_P(FullDisk, AWriteThatDoesNotFitFailsWithTheReasonAndKeepsTheOlderFile)
{
    const fs::path path = folder_ / ("out" + GetParam());
    std::ofstream(path) << "an earlier render";
    // One page left: a file larger than 4 KB is cut short after its first page (as TIFF's
    // 4,096-byte files were).
    ASSERT_TRUE(disk_->fillLeaving(4096));
    try {
        io::writeImage(path, noise(), {{"raytracer:note", "a test"}});
        ADD_FAILURE() << "writing " << path << " onto a full disk should fail; the file is now "
                      << fs::file_size(path) << " bytes";
    } catch (const std::runtime_error& error) {
        const std::string message = error.what();
        EXPECT_NE(message.find(path.string()), std::string::npos) << message;
        EXPECT_NE(message.find(std::strerror(ENOSPC)), std::string::npos) << message;
        EXPECT_EQ(message.find(".partial"), std::string::npos) << message;
    }
    EXPECT_EQ(contents(path), "an earlier render") << "the older file must be kept";
    EXPECT_EQ(files(), (std::vector<std::string>{"filler", "out" + GetParam()}))
        << "no temporary file is left";
}

TEST_P(FullDisk, AWriteThatFitsIsComplete)
{
    // The check is of the write, not of the space: with room enough, every format is
    // written and reads back.
    const fs::path path = folder_ / ("small" + GetParam());
    io::Image image(8, 6, 3);
    for (std::size_t i = 0; i < image.pixels.size(); ++i)
        image.pixels[i] = static_cast<float>(i % 7) / 7.0f;
    io::writeImage(path, image);
    const io::ImageHeader header = io::readImageHeader(path);
    EXPECT_EQ(header.width, 8);
    EXPECT_EQ(header.height, 6);
}

INSTANTIATE_TEST_SUITE_P(EveryFormat, FullDisk,
                         ::testing::Values(".ppm", ".png", ".jpg", ".tif", ".exr", ".pfm", ".hdr"),
                         [](const ::testing::TestParamInfo<std::string>& info) {
                             return info.param.substr(1);
                         });

}  // namespace
}  // namespace io_tests
