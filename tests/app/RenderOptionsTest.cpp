// The options a renderer's users reach for, run as a user runs them: --camera, --exposure and
// --tone-curve, --crop and the merge of crops, the warning for a scene that can emit no light (--strict), the exit status of
// a render that ends before its target error, --quiet and --summary-json.
#include "app/ProgramInFolder.h"
#include "film/RenderFile.h"
#include "film/ToneCurve.h"
#include "io/ImageFile.h"
#include "support/ChildProcess.h"
#include "support/TestPaths.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>

namespace cli_tests {
namespace {

using namespace testing_support;

// The program's documented status for a render that ended without reaching --target-error
// (app/RenderCommand.h, kExitTargetNotReached).
constexpr int kTargetNotReached = 3;

// A ball on a floor with no light, no emitter and a black environment.
constexpr const char* kDarkScene = R"(environment none
0 1.5 5
0 0.5 0
0 1 0
45
0
1 solid 0.8 0.8 0.8
1 0 0 0 0 0 0 0
2
0 0 polyhedron 1
    0 1 0 0
0 0 sphere 0 1 0 1
)";

class RenderOptions : public ProgramInFolder {
protected:
    std::string scene1() const { return (sourceDirectory() / "scenes" / "scene1.in").string(); }

    // A small render of scene 1 that must succeed.
    ProcessResult render(std::vector<std::string> arguments) const
    {
        arguments.insert(arguments.begin(), {scene1(), "24", "16", "--spp", "1"});
        const ProcessResult result = run(arguments);
        EXPECT_TRUE(result.exited && result.exitStatus == 0) << describe(result);
        return result;
    }

    std::string read(const std::string& name) const
    {
        std::ifstream file(folder_ / name, std::ios::binary);
        return std::string(std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>());
    }
};

TEST_F(RenderOptions, CameraReplacesTheScenesCameraAndIsRecorded)
{
    render({"--output", "file.exr"});
    render({"--camera", "eye 1 -6 4 look-at 1 10 -2 up 0 0 1 fov 50", "--output", "moved.exr"});
    const film::RenderFile file = film::readRenderFile(folder_ / "file.exr");
    const film::RenderFile moved = film::readRenderFile(folder_ / "moved.exr");
    EXPECT_EQ(film::formatCamera(moved.metadata.camera),
              "eye 1 -6 4 target 1 10 -2 up 0 0 1 fovy 50");
    EXPECT_NE(file.accumulation.estimate.pixels, moved.accumulation.estimate.pixels)
        << "another camera shows another picture";
}

TEST_F(RenderOptions, RendersFromAnotherCameraAreNotMerged)
{
    render({"--seed", "1", "--output", "a.exr"});
    render({"--seed", "2", "--camera", "1 -6 4  1 10 -2  0 0 1  50", "--output", "b.exr"});
    const ProcessResult merge = run({"merge", "ab.exr", "a.exr", "b.exr"});
    EXPECT_EQ(merge.exitStatus, 1) << describe(merge);
    EXPECT_NE(merge.standardError.find("the camera"), std::string::npos) << describe(merge);
}

TEST_F(RenderOptions, ACameraThatCannotBeReadNamesTheOptionAndTheToken)
{
    const ProcessResult result =
        run({scene1(), "24", "16", "--spp", "1", "--camera", "0 0 5  0 0 0  0 1 x  45"});
    EXPECT_EQ(result.exitStatus, 2) << describe(result);
    EXPECT_NE(result.standardError.find("--camera: read 'x', expected a number (camera up "
                                        "vector"),
              std::string::npos)
        << describe(result);
}

// Each curve's picture is what film/ToneCurve.h computes from the radiance the EXR holds, to
// the 8-bit rounding (and float against double); the EXR is the same whatever the curve.
TEST_F(RenderOptions, EveryToneCurveMakesThePictureFromTheSameRadiance)
{
    render({"--output", "default.exr"});
    const io::Image defaultRadiance = io::readImage(folder_ / "default.exr");
    for (const auto& choice : settings::Choices<settings::ToneCurveKind>::values) {
        const std::string curve = choice.name;
        render({"--tone-curve", curve, "--exposure", "1.5", "--output", curve + ".exr"});
        render({"--tone-curve", curve, "--exposure", "1.5", "--output", curve + ".png"});
        const io::Image radiance = io::readImage(folder_ / (curve + ".exr"));
        EXPECT_EQ(radiance.pixels, defaultRadiance.pixels) << curve << ": the EXR holds radiance";
        EXPECT_EQ(io::readImageAttribute(folder_ / (curve + ".exr"), "raytracer:toneCurve"), curve);
        const io::Image picture = io::readImage(folder_ / (curve + ".png"));
        double largest = 0.0;
        for (int y = 0; y < picture.height; ++y)
            for (int x = 0; x < picture.width; ++x) {
                const film::Rgb expected = film::displayColour(
                    {radiance.at(x, y, 0), radiance.at(x, y, 1), radiance.at(x, y, 2)}, 1.5,
                    choice.value);
                for (int c = 0; c < 3; ++c)
                    largest = std::max(largest, std::abs(picture.at(x, y, c) - expected[c]));
            }
        EXPECT_LE(largest * 255.0, 1.01) << curve << ": the picture differs from the curve";
    }
}

TEST_F(RenderOptions, ASceneThatCannotEmitLightIsAWarningBeforeTheRender)
{
    const std::string scene = write("dark.in", kDarkScene).string();
    const ProcessResult result = run({scene, "16", "12", "--spp", "1", "--output", "dark.png"});
    EXPECT_EQ(result.exitStatus, 0) << describe(result);
    EXPECT_NE(result.standardError.find("warning: " + scene + " can emit no light"),
              std::string::npos)
        << describe(result);
}

TEST_F(RenderOptions, WithStrictASceneThatCannotEmitLightIsRefused)
{
    const std::string scene = write("dark.in", kDarkScene).string();
    const ProcessResult result =
        run({scene, "16", "12", "--spp", "1", "--strict", "--output", "dark.png"});
    EXPECT_EQ(result.exitStatus, 1) << describe(result);
    EXPECT_NE(result.standardError.find("can emit no light"), std::string::npos)
        << describe(result);
    EXPECT_EQ(filesInFolder(), std::vector<std::string>{"dark.in"});
}

TEST_F(RenderOptions, ATargetErrorNotReachedAtTheTimeLimitHasItsOwnExitStatus)
{
    const ProcessResult result =
        run({scene1(), "24", "16", "1", "--target-error", "0.0001", "--output", "short.exr"});
    EXPECT_EQ(result.exitStatus, kTargetNotReached) << describe(result);
    EXPECT_NE(result.standardOutput.find("stopped at the time limit before it"), std::string::npos)
        << describe(result);
    EXPECT_NE(result.standardOutput.find("exit status 3"), std::string::npos) << describe(result);
    EXPECT_NO_THROW(film::readRenderFile(folder_ / "short.exr")) << "the image is written";
}

TEST_F(RenderOptions, QuietPrintsNothingOnSuccess)
{
    const ProcessResult result = render({"--quiet", "--output", "q.png"});
    EXPECT_EQ(result.standardOutput, "");
    EXPECT_EQ(result.standardError, "");
}

TEST_F(RenderOptions, SummaryJsonHoldsTheSummarysFields)
{
    render({"--quiet", "--summary-json", "summary.json", "--output", "s.png"});
    const std::string json = read("summary.json");
    for (const char* field : {"\"width\": 24", "\"height\": 16", "\"samplesPerPixel\": 1",
                              "\"seconds\": ", "\"megapathsPerSecond\": ", "\"targetError\": null",
                              "\"errorReached\": null", "\"stopReason\": \"samples\"",
                              "\"exitStatus\": 0", "\"outputs\": [\"s.png\"]"})
        EXPECT_NE(json.find(field), std::string::npos) << field << " not in:\n" << json;
    EXPECT_EQ(json.front(), '{');
    EXPECT_EQ(json.substr(json.size() - 2), "}\n");
}

TEST_F(RenderOptions, SummaryJsonOfATargetErrorSaysWhetherItWasReached)
{
    const ProcessResult result =
        run({scene1(), "24", "16", "1", "--target-error", "0.0001", "--quiet", "--summary-json",
             "summary.json", "--output", "t.exr"});
    EXPECT_EQ(result.exitStatus, kTargetNotReached) << describe(result);
    const std::string json = read("summary.json");
    for (const char* field : {"\"targetError\": 0.0001", "\"targetReached\": false",
                              "\"stopReason\": \"time limit\"", "\"exitStatus\": 3"})
        EXPECT_NE(json.find(field), std::string::npos) << field << " not in:\n" << json;
    EXPECT_EQ(json.find("\"errorReached\": null"), std::string::npos) << json;
}

// --crop: the full frame with only the crop traced, each pixel's samples those of the full
// render (they follow from the seed, the pixel and the sample index), so crops that share no
// pixel merge into the full render bit for bit.
TEST_F(RenderOptions, CropsOfARenderMergeIntoItsFullFrameExactly)
{
    for (const std::vector<std::string>& arguments :
         {std::vector<std::string>{"--output", "full.exr"},
          std::vector<std::string>{"--crop", "0 0 24 6", "--output", "top.exr"},
          std::vector<std::string>{"--crop", "0,6,24,16", "--output", "bottom.exr"}}) {
        std::vector<std::string> command = {scene1(), "24", "16", "--spp", "3"};
        command.insert(command.end(), arguments.begin(), arguments.end());
        const ProcessResult result = run(command);
        ASSERT_EQ(result.exitStatus, 0) << describe(result);
    }
    const ProcessResult merge = run({"merge", "merged.exr", "top.exr", "bottom.exr"});
    ASSERT_EQ(merge.exitStatus, 0) << describe(merge);
    const film::RenderFile full = film::readRenderFile(folder_ / "full.exr");
    const film::RenderFile merged = film::readRenderFile(folder_ / "merged.exr");
    EXPECT_EQ(merged.accumulation.estimate.pixels, full.accumulation.estimate.pixels);
    EXPECT_EQ(merged.accumulation.moments.pixels, full.accumulation.moments.pixels);
    EXPECT_FALSE(merged.metadata.crop.has_value()) << "the crops cover the frame";
    EXPECT_EQ(merged.metadata.samplesPerPixel, 3);
}

TEST_F(RenderOptions, ACropTracesOnlyItsPixelsAndIsRecorded)
{
    render({"--crop", "4 2 12 10", "--output", "crop.exr"});
    const film::RenderFile crop = film::readRenderFile(folder_ / "crop.exr");
    ASSERT_TRUE(crop.metadata.crop.has_value());
    EXPECT_EQ(film::formatCrop(*crop.metadata.crop), "4 2 12 10");
    EXPECT_EQ(crop.accumulation.width(), 24) << "the file holds the full frame";
    for (int y = 0; y < 16; ++y)
        for (int x = 0; x < 24; ++x) {
            const bool inside = x >= 4 && x < 12 && y >= 2 && y < 10;
            EXPECT_EQ(crop.accumulation.samplesTaken(x, y), inside ? 1.0f : 0.0f)
                << "pixel " << x << ", " << y;
        }
}

TEST_F(RenderOptions, CropsThatShareAPixelAndASeedAreNotMerged)
{
    render({"--crop", "0 0 14 16", "--output", "left.exr"});
    render({"--crop", "10 0 24 16", "--output", "right.exr"});
    const ProcessResult merge = run({"merge", "both.exr", "left.exr", "right.exr"});
    EXPECT_EQ(merge.exitStatus, 1) << describe(merge);
    EXPECT_NE(merge.standardError.find("crops (--crop) that share no pixel"), std::string::npos)
        << describe(merge);
}

TEST_F(RenderOptions, ACropBeyondTheFrameIsRefused)
{
    const ProcessResult result = run({scene1(), "24", "16", "--spp", "1", "--crop", "0 0 30 8"});
    EXPECT_EQ(result.exitStatus, 2) << describe(result);
    EXPECT_NE(result.standardError.find("--crop 0 0 30 8 reaches beyond the 24x16 frame"),
              std::string::npos)
        << describe(result);
}

}  // namespace
}  // namespace cli_tests
