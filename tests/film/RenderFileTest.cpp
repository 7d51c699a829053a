// The render's own files (film/RenderFile.h): an EXR keeps the accumulation and the
// metadata exactly; the statistics file names its channels for what they are.
#include "film/RenderFile.h"
#include "io/ImageFile.h"
#include "io/OutputFiles.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <random>

namespace scale_out_tests {
namespace {

namespace fs = std::filesystem;

class RenderFiles : public ::testing::Test {
protected:
    void SetUp() override
    {
        folder_ = fs::temp_directory_path() /
                  ("raytracer-render-files-" + std::to_string(std::random_device{}()));
        fs::create_directories(folder_);
    }
    void TearDown() override { fs::remove_all(folder_); }

    static film::Accumulation someAccumulation()
    {
        film::Accumulation accumulation(5, 3);
        std::mt19937 random(5);
        std::uniform_real_distribution<float> uniform(0.0f, 3.0f);
        for (int y = 0; y < 3; ++y)
            for (int x = 0; x < 5; ++x) {
                const float kept = static_cast<float>(16 + x);
                for (int c = 0; c < 3; ++c) {
                    // A second moment that samples of this mean could have: below n (n - 1)
                    // mean^2 (film/RenderFileChecks.h).
                    const float mean = uniform(random);
                    accumulation.estimate.at(x, y, c) = mean;
                    accumulation.moments.at(x, y, c) =
                        uniform(random) / 3.0f * kept * (kept - 1.0f) * mean * mean;
                }
                accumulation.estimate.at(x, y, 3) = kept;
                accumulation.moments.at(x, y, 3) = static_cast<float>(y);
            }
        return accumulation;
    }
    static film::RenderMetadata someMetadata()
    {
        film::RenderMetadata metadata;
        metadata.width = 5;
        metadata.height = 3;
        metadata.sceneFile = "s.in";
        metadata.sceneSha256 = std::string(64, 'c');
        metadata.samplesPerPixel = 24;
        metadata.sampleRanges = {{3, 0, 24}};
        metadata.renderSeconds = 2.5;
        metadata.program = "raytracer 1.0.0";
        metadata.settings.maxBounces = 5;
        return metadata;
    }

    fs::path folder_;
};

TEST_F(RenderFiles, AnExrKeepsTheAccumulationBitForBitAndTheMetadata)
{
    const film::Accumulation written = someAccumulation();
    io::writeAllOrNothing({film::accumulationOutput(folder_ / "r.exr", written, someMetadata())});
    const film::RenderFile read = film::readRenderFile(folder_ / "r.exr");
    EXPECT_EQ(read.accumulation.estimate.pixels, written.estimate.pixels);
    EXPECT_EQ(read.accumulation.moments.pixels, written.moments.pixels);
    EXPECT_EQ(read.metadata.width, 5);
    EXPECT_EQ(read.metadata.height, 3);
    EXPECT_EQ(read.metadata.settings.maxBounces, 5);
    EXPECT_EQ(read.metadata.sampleRanges, someMetadata().sampleRanges);
    EXPECT_EQ(read.metadata.sceneSha256, someMetadata().sceneSha256);
}

TEST_F(RenderFiles, TheExrNamesItsChannelsForWhatTheyHold)
{
    io::writeAllOrNothing(
        {film::accumulationOutput(folder_ / "r.exr", someAccumulation(), someMetadata())});
    const io::ImageFileContents file = io::readImageFile(folder_ / "r.exr");
    for (const char* name : {"R", "G", "B", "samples", "samplesDiscarded", "sumSquaredDeviations.R",
                             "sumSquaredDeviations.G", "sumSquaredDeviations.B"})
        EXPECT_GE(file.channelIndex(name), 0) << "no channel " << name;
    EXPECT_EQ(file.image.channels, 8);
}

// Feature buffers (--feature-buffers) as named layers, read back bit for bit; a value no
// render holds (an albedo above 1) is refused with its pixel and channel.
TEST_F(RenderFiles, FeatureBuffersAreNamedLayersReadBackBitForBit)
{
    film::Accumulation written = someAccumulation();
    written.addEmptyFeatures();
    std::mt19937 random(7);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    for (float& value : written.albedoDepth.pixels)
        value = unit(random);
    for (float& value : written.normalCoverage.pixels)
        value = 2.0f * unit(random) - 1.0f;
    for (int y = 0; y < 3; ++y)
        for (int x = 0; x < 5; ++x) {
            written.albedoDepth.at(x, y, 3) = 10.0f * unit(random);  // a distance
            written.normalCoverage.at(x, y, 3) = unit(random);       // a fraction
        }
    io::writeAllOrNothing({film::accumulationOutput(folder_ / "f.exr", written, someMetadata())});
    const io::ImageFileContents file = io::readImageFile(folder_ / "f.exr");
    for (const char* name : {"albedo.R", "albedo.G", "albedo.B", "N.X", "N.Y", "N.Z", "Z"})
        EXPECT_GE(file.channelIndex(name), 0) << "no channel " << name;
    EXPECT_EQ(file.image.at(4, 2, file.channelIndex("Z")), written.albedoDepth.at(4, 2, 3));
    EXPECT_EQ(file.image.at(1, 1, file.channelIndex("N.Y")), written.normalCoverage.at(1, 1, 1));
    const film::RenderFile read = film::readRenderFile(folder_ / "f.exr");
    ASSERT_TRUE(read.accumulation.hasFeatures());
    EXPECT_EQ(read.accumulation.albedoDepth.pixels, written.albedoDepth.pixels);
    EXPECT_EQ(read.accumulation.normalCoverage.pixels, written.normalCoverage.pixels);
    EXPECT_EQ(read.accumulation.estimate.pixels, written.estimate.pixels);

    written.albedoDepth.at(3, 1, 1) = 1.5f;
    io::writeAllOrNothing({film::accumulationOutput(folder_ / "g.exr", written, someMetadata())});
    try {
        film::readRenderFile(folder_ / "g.exr");
        FAIL() << "an albedo of 1.5 is no render's";
    } catch (const std::runtime_error& error) {
        EXPECT_NE(std::string(error.what()).find("pixel (3, 1), channel albedo.G"),
                  std::string::npos)
            << error.what();
    }
}

TEST_F(RenderFiles, TheStatisticsFileNamesItsChannelsNotRGB)
{
    io::writeAllOrNothing(
        {film::statisticsOutput(folder_ / "s.exr", someAccumulation(), someMetadata())});
    const io::ImageFileContents file = io::readImageFile(folder_ / "s.exr");
    EXPECT_EQ(file.channelNames,
              (std::vector<std::string>{"samples", "samplesDiscarded", "varianceOfMean"}));
    EXPECT_EQ(file.image.at(2, 1, file.channelIndex("samples")), 18.0f);
    EXPECT_EQ(file.image.at(2, 1, file.channelIndex("samplesDiscarded")), 1.0f);
}

TEST_F(RenderFiles, APictureWithMetadataIsNoAccumulation)
{
    io::Image picture(5, 3, 3);
    io::writeImage(folder_ / "p.png", picture, film::metadataAttributes(someMetadata()));
    try {
        film::readRenderFile(folder_ / "p.png");
        FAIL() << "a PNG holds no accumulation";
    } catch (const std::runtime_error& error) {
        EXPECT_NE(std::string(error.what()).find("holds no accumulation"), std::string::npos)
            << error.what();
    }
    // Its metadata reads back all the same.
    const io::ImageFileContents file = io::readImageFile(folder_ / "p.png");
    const auto metadata = film::metadataFromAttributes(file.attributes, "p.png");
    ASSERT_TRUE(metadata.has_value());
    EXPECT_EQ(metadata->sampleRanges, someMetadata().sampleRanges);
    EXPECT_EQ(metadata->settings.maxBounces, 5);
}

}  // namespace
}  // namespace scale_out_tests
