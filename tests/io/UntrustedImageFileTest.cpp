// Image files read are untrusted (io/ImageFile.h): only a regular file is opened, and only by
// the reader of the format its extension names.
#include "io/ImageFile.h"

#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <random>
#include <sys/stat.h>

namespace io_tests {
namespace {

namespace fs = std::filesystem;

class UntrustedImageFile : public ::testing::Test {
protected:
    void SetUp() override
    {
        folder_ = fs::temp_directory_path() /
                  ("raytracer-untrusted-image-" + std::to_string(std::random_device{}()));
        fs::create_directories(folder_);
    }
    void TearDown() override { fs::remove_all(folder_); }

    // The message of the refusal and how long it took; "(read)" when the file was read.
    std::pair<std::string, double> refusalOf(const fs::path& path) const
    {
        const auto start = std::chrono::steady_clock::now();
        std::string message = "(read)";
        try {
            io::readImageFile(path);
        } catch (const std::runtime_error& error) {
            message = error.what();
        }
        return {message,
                std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count()};
    }

    fs::path folder_;
};

// Each of these made `raytracer info` spin or block for ever (OpenImageIO tried every reader
// on /dev/zero; a FIFO waited for a writer).
TEST_F(UntrustedImageFile, ALinkToADeviceIsRefusedBeforeAnyReaderSeesIt)
{
    fs::create_symlink("/dev/zero", folder_ / "z.exr");
    const auto [message, seconds] = refusalOf(folder_ / "z.exr");
    EXPECT_NE(message.find("z.exr: it is a character device, not a regular file"),
              std::string::npos)
        << message;
    EXPECT_LT(seconds, 1.0);
}

TEST_F(UntrustedImageFile, AFifoIsRefusedWithoutWaitingForAWriter)
{
    ASSERT_EQ(::mkfifo((folder_ / "f.exr").c_str(), 0600), 0);
    const auto [message, seconds] = refusalOf(folder_ / "f.exr");
    EXPECT_NE(message.find("f.exr: it is a FIFO, not a regular file"), std::string::npos)
        << message;
    EXPECT_LT(seconds, 1.0);
}

TEST_F(UntrustedImageFile, AFolderIsRefused)
{
    fs::create_directories(folder_ / "d.exr");
    const auto [message, seconds] = refusalOf(folder_ / "d.exr");
    EXPECT_NE(message.find("d.exr: it is a folder, not a regular file"), std::string::npos)
        << message;
}

TEST_F(UntrustedImageFile, AFileIsReadOnlyAsTheFormatItsExtensionNames)
{
    // A good PNG named .exr: OpenImageIO, asked to open it, guesses it is a PNG.
    io::Image image(4, 3, 3);
    io::writeImage(folder_ / "picture.png", image);
    fs::copy_file(folder_ / "picture.png", folder_ / "picture.exr");
    const auto [message, seconds] = refusalOf(folder_ / "picture.exr");
    EXPECT_NE(message.find("picture.exr: not a readable exr file"), std::string::npos) << message;
}

// Read in bands of rows (so that memory follows the pixels the file holds): every row comes
// back in its place, for scan-line files of heights that are no multiple of a band, and for
// tiled ones.
TEST_F(UntrustedImageFile, ImagesReadInBandsComeBackWhole)
{
    for (const auto& [name, tile] : {std::pair{"lines.exr", 0}, std::pair{"tiles.exr", 16}}) {
        OIIO::ImageSpec spec(21, 37, 2, OIIO::TypeDesc::FLOAT);
        if (tile > 0) {
            spec.tile_width = tile;
            spec.tile_height = tile;
        }
        std::vector<float> pixels(static_cast<std::size_t>(21) * 37 * 2);
        for (std::size_t i = 0; i < pixels.size(); ++i)
            pixels[i] = static_cast<float>(i);
        auto output = OIIO::ImageOutput::create("openexr");
        ASSERT_TRUE(output && output->open((folder_ / name).string(), spec)) << name;
        ASSERT_TRUE(output->write_image(OIIO::TypeDesc::FLOAT, pixels.data()));
        ASSERT_TRUE(output->close());
        const io::ImageFileContents read = io::readImageFile(folder_ / name);
        EXPECT_EQ(read.image.width, 21);
        EXPECT_EQ(read.image.height, 37);
        EXPECT_EQ(read.image.pixels, pixels) << name;
    }
}

}  // namespace
}  // namespace io_tests
