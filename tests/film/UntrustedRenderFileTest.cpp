// A render's file is untrusted (film/RenderFile.h, film/RenderFileChecks.h): each way a
// file can be wrong that issue 35 found merged, resumed or described without a word
// (support/CraftedRenderFiles.cpp) is refused, naming the first pixel and channel at fault.
#include "film/RenderFile.h"
#include "film/RenderFileChecks.h"
#include "io/OutputFiles.h"
#include "support/CraftedRenderFiles.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <random>

namespace scale_out_tests {
namespace {

namespace fs = std::filesystem;
using testing_support::CraftedRenderFile;

class UntrustedRenderFile : public ::testing::TestWithParam<std::string> {
protected:
    void SetUp() override
    {
        folder_ = fs::temp_directory_path() /
                  ("raytracer-untrusted-render-file-" + std::to_string(std::random_device{}()));
        fs::create_directories(folder_);
        writeBase(folder_ / "base.exr");
    }
    void TearDown() override { fs::remove_all(folder_); }

    // An 8x6 render of 4 samples per pixel, seed 1, as the program writes it: means and
    // second moments of samples that could have been drawn.
    static void writeBase(const fs::path& path)
    {
        film::Accumulation accumulation(8, 6);
        std::mt19937 random(35);
        std::uniform_real_distribution<float> uniform(0.05f, 1.0f);
        for (int y = 0; y < 6; ++y)
            for (int x = 0; x < 8; ++x) {
                for (int c = 0; c < 3; ++c) {
                    const float mean = uniform(random);
                    accumulation.estimate.at(x, y, c) = mean;
                    accumulation.moments.at(x, y, c) = uniform(random) * 12.0f * mean * mean;
                }
                accumulation.estimate.at(x, y, 3) = 4.0f;
            }
        film::RenderMetadata metadata;
        metadata.width = 8;
        metadata.height = 6;
        metadata.sceneFile = "s.in";
        metadata.sceneSha256 = std::string(64, 'c');
        metadata.samplesPerPixel = 4;
        metadata.sampleRanges = {{1, 0, 4}};
        metadata.program = "raytracer 1.0.0";
        io::writeAllOrNothing({film::accumulationOutput(path, accumulation, metadata)});
    }

    // The refusal's message, or "(accepted)".
    std::string refusalOf(const fs::path& path) const
    {
        try {
            film::readRenderFile(path);
        } catch (const std::runtime_error& error) {
            return error.what();
        }
        return "(accepted)";
    }

    fs::path folder_;
};

TEST_F(UntrustedRenderFile, TheBaseOfTheCraftedFilesIsAccepted)
{
    EXPECT_EQ(refusalOf(folder_ / "base.exr"), "(accepted)");
    // Written again as the crafted files are, with nothing changed.
    testing_support::writeCraftedRenderFile({"unchanged", "", {}, "", {}}, folder_ / "base.exr",
                                            folder_ / "unchanged.exr");
    EXPECT_EQ(refusalOf(folder_ / "unchanged.exr"), "(accepted)");
}

TEST_P(UntrustedRenderFile, IsRefusedSayingWhatIsWrongAndWhere)
{
    const CraftedRenderFile& crafted = testing_support::craftedRenderFile(GetParam());
    const fs::path path = folder_ / (crafted.name + ".exr");
    testing_support::writeCraftedRenderFile(crafted, folder_ / "base.exr", path);
    const std::string refusal = refusalOf(path);
    EXPECT_NE(refusal.find(path.string()), std::string::npos)
        << "the refusal must name the file: " << refusal;
    EXPECT_NE(refusal.find(crafted.refusal), std::string::npos)
        << "expected a refusal saying \"" << crafted.refusal << "\", got: " << refusal;
}

std::vector<std::string> craftedNames()
{
    std::vector<std::string> names;
    for (const CraftedRenderFile& file : testing_support::craftedRenderFiles())
        names.push_back(file.name);
    return names;
}

INSTANTIATE_TEST_SUITE_P(Crafted, UntrustedRenderFile, ::testing::ValuesIn(craftedNames()),
                         [](const ::testing::TestParamInfo<std::string>& info) {
                             std::string name;
                             for (char c : info.param)
                                 name += std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
                             return name;
                         });

TEST_F(UntrustedRenderFile, AFileNamedOtherThanExrIsNotReadAsARender)
{
    fs::copy_file(folder_ / "base.exr", folder_ / "base.png");
    const std::string refusal = refusalOf(folder_ / "base.png");
    EXPECT_NE(refusal.find("it is not an .exr file"), std::string::npos) << refusal;
}

TEST_F(UntrustedRenderFile, ASecondMomentAtItsBoundAsOneBrightSampleLeavesItIsAccepted)
{
    // One sample of 4 holds all the radiance: M2 = n (n - 1) mean^2 exactly, the most a
    // render can hold, which the bound must not refuse.
    io::ImageFileContents file = io::readImageFile(folder_ / "base.exr");
    const float mean = testing_support::craftedValue(file, "R");
    testing_support::craftedValue(file, "sumSquaredDeviations.R") = 4.0f * 3.0f * mean * mean;
    std::vector<io::ImageAttribute> attributes;
    for (const io::ImageAttribute& attribute : file.attributes)
        if (attribute.name.rfind("raytracer:", 0) == 0 &&
            attribute.name != film::kPixelDigestAttribute)
            attributes.push_back(attribute);
    io::writeAllOrNothing({{folder_ / "bound.exr", file.image, attributes, file.channelNames}});
    EXPECT_EQ(refusalOf(folder_ / "bound.exr"), "(accepted)");
}

}  // namespace
}  // namespace scale_out_tests
