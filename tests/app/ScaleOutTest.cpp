// Renders that outgrow one run (issue 16), through the program as a user runs it: shards
// merged agree with one render of all their samples; merge is associative; every file says
// what it holds and how it was made; merge and resume refuse, in one line and writing
// nothing, samples that do not estimate one image or that repeat a seed's samples; a resumed
// render goes on where an interrupted one stopped and loses nothing.
#include "app/ProgramInFolder.h"
#include "film/RenderFile.h"
#include "io/ImageFile.h"
#include "io/Sha256.h"
#include "support/ChildProcess.h"
#include "support/ImageComparison.h"
#include "support/TestPaths.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <regex>
#include <sstream>

namespace cli_tests {
namespace {

using namespace testing_support;
namespace fs = std::filesystem;

class ScaleOut : public ProgramInFolder {
protected:
    static std::string scene1() { return (sourceDirectory() / "scenes" / "scene1.in").string(); }

    // A headless render of scene 1 that must succeed.
    void render(std::vector<std::string> arguments, const std::string& scene = scene1()) const
    {
        arguments.insert(arguments.begin(), scene);
        arguments.push_back("--quiet");
        const ProcessResult result = run(arguments);
        ASSERT_TRUE(result.exited && result.exitStatus == 0) << describe(result);
    }

    void merge(std::vector<std::string> arguments) const
    {
        arguments.insert(arguments.begin(), "merge");
        const ProcessResult result = run(arguments);
        ASSERT_TRUE(result.exited && result.exitStatus == 0) << describe(result);
    }

    film::RenderFile readRender(const std::string& name) const
    {
        return film::readRenderFile(folder_ / name);
    }

    // A refusal: exit status 1, one line on standard error holding each of `words`, and not
    // one file more or changed in the folder.
    void expectRefused(const std::vector<std::string>& arguments,
                       const std::vector<std::string>& words) const
    {
        const std::vector<std::string> before = filesInFolder();
        std::vector<std::string> contentsBefore;
        for (const std::string& name : before)
            contentsBefore.push_back(contents(name));
        const ProcessResult result = run(arguments);
        ASSERT_TRUE(result.exited) << describe(result);
        EXPECT_EQ(result.exitStatus, 1) << describe(result);
        const auto lines = nonEmptyLines(result.standardError);
        ASSERT_EQ(lines.size(), 1u) << "one line on standard error; " << describe(result);
        for (const std::string& word : words)
            EXPECT_NE(lines[0].find(word), std::string::npos)
                << "the reason should name '" << word << "': " << lines[0];
        EXPECT_EQ(filesInFolder(), before) << "nothing may be written";
        for (std::size_t i = 0; i < before.size(); ++i)
            EXPECT_EQ(contents(before[i]), contentsBefore[i])
                << before[i] << " must be left as it was";
    }

    std::string contents(const fs::path& name) const
    {
        std::ifstream file(folder_ / name, std::ios::binary);
        std::ostringstream text;
        text << file.rdbuf();
        return text.str();
    }

    std::optional<std::string> attribute(const std::string& file, const std::string& name) const
    {
        return io::readImageAttribute(folder_ / file, name);
    }
};

RenderedImage asRenderedImage(const film::Accumulation& accumulation)
{
    RenderedImage image;
    image.radiance = film::meanRadiance(accumulation);
    image.statistics = film::sampleStatistics(accumulation);
    return image;
}

float largestRelativeDifference(const io::Image& a, const io::Image& b)
{
    float largest = 0.0f;
    for (std::size_t i = 0; i < a.pixels.size(); ++i) {
        const float scale = std::max({std::abs(a.pixels[i]), std::abs(b.pixels[i]), 1e-20f});
        largest = std::max(largest, std::abs(a.pixels[i] - b.pixels[i]) / scale);
    }
    return largest;
}

// The largest difference of two accumulations' second moments, each relative to the scale
// float precision applies to: the sum of squares of the samples, M2 + n mean^2 (rounding a
// mean perturbs M2 by about 2 n |mean - sample| ulp(mean), however small M2 itself is).
float largestMomentDifference(const film::Accumulation& a, const film::Accumulation& b)
{
    float largest = 0.0f;
    for (int y = 0; y < a.height(); ++y)
        for (int x = 0; x < a.width(); ++x)
            for (int c = 0; c < 3; ++c) {
                const float mean = a.estimate.at(x, y, c);
                const float scale = a.moments.at(x, y, c) + a.samplesKept(x, y) * mean * mean;
                const float difference = std::abs(a.moments.at(x, y, c) - b.moments.at(x, y, c));
                largest = std::max(largest, difference / std::max(scale, 1e-30f));
            }
    return largest;
}

void expectEveryPixelHolds(const film::Accumulation& accumulation, int samples)
{
    const film::SampleCountSpan span = film::samplesTakenSpan(accumulation);
    EXPECT_EQ(span.fewest, samples);
    EXPECT_EQ(span.most, samples);
}

// --- merge ------------------------------------------------------------------------------------

TEST_F(ScaleOut, ShardsMergedAgreeWithOneRenderOfAllTheirSamples)
{
    // Three shards of 32 samples (seeds 11, 12, 13) against one render of 96 (seed 99, so
    // the two estimates are independent, as the comparison assumes).
    for (const char* seed : {"11", "12", "13"})
        render({"64", "48", "--spp", "32", "--seed", seed, "--output",
                std::string("shard-") + seed + ".exr"});
    merge({"merged.exr", "shard-11.exr", "shard-12.exr", "shard-13.exr"});
    render({"64", "48", "--spp", "96", "--seed", "99", "--output", "whole.exr"});

    const film::RenderFile merged = readRender("merged.exr");
    const film::RenderFile whole = readRender("whole.exr");
    expectEveryPixelHolds(merged.accumulation, 96);
    EXPECT_EQ(merged.metadata.samplesPerPixel, 96);
    const std::vector<film::SampleRange> ranges = {{11, 0, 32}, {12, 0, 32}, {13, 0, 32}};
    EXPECT_EQ(merged.metadata.sampleRanges, ranges);

    const Comparison comparison =
        compareImages(asRenderedImage(merged.accumulation), asRenderedImage(whole.accumulation));
    EXPECT_TRUE(comparison.passed()) << comparison.describe();
}

TEST_F(ScaleOut, MergeIsAssociative)
{
    for (const char* seed : {"1", "2", "3"})
        render({"32", "24", "--spp", "4", "--seed", seed, "--output",
                std::string("s") + seed + ".exr"});
    merge({"ab.exr", "s1.exr", "s2.exr"});
    merge({"ab_c.exr", "ab.exr", "s3.exr"});
    merge({"bc.exr", "s2.exr", "s3.exr"});
    merge({"a_bc.exr", "s1.exr", "bc.exr"});
    merge({"abc.exr", "s1.exr", "s2.exr", "s3.exr"});

    const film::RenderFile left = readRender("ab_c.exr");
    const film::RenderFile right = readRender("a_bc.exr");
    const film::RenderFile once = readRender("abc.exr");
    // Each merge rounds its result to float once: the orders may differ in the last bits.
    EXPECT_LE(largestRelativeDifference(left.accumulation.estimate, right.accumulation.estimate),
              1e-6f);
    EXPECT_LE(largestMomentDifference(left.accumulation, right.accumulation), 1e-6f);
    EXPECT_LE(largestRelativeDifference(left.accumulation.estimate, once.accumulation.estimate),
              1e-6f);
    EXPECT_LE(largestMomentDifference(left.accumulation, once.accumulation), 1e-6f);
    expectEveryPixelHolds(left.accumulation, 12);
    EXPECT_EQ(left.metadata.sampleRanges, right.metadata.sampleRanges);
    EXPECT_EQ(left.metadata.samplesPerPixel, 12);
    EXPECT_EQ(right.metadata.samplesPerPixel, 12);
}

TEST_F(ScaleOut, InfoOnAMergedFileShowsTheSummedSamplesAndTheSeeds)
{
    render({"16", "12", "--spp", "3", "--seed", "4", "--output", "a.exr"});
    render({"16", "12", "--spp", "5", "--seed", "9", "--output", "b.exr"});
    merge({"m.exr", "a.exr", "b.exr", "--png", "m.png", "--stats-output", "ms.exr"});
    const ProcessResult result = run({"info", "m.exr"});
    ASSERT_TRUE(result.exited && result.exitStatus == 0) << describe(result);
    const std::string& text = result.standardOutput;
    EXPECT_TRUE(std::regex_search(text, std::regex("\nsamples +8 per pixel; every pixel holds 8")))
        << text;
    EXPECT_TRUE(std::regex_search(text, std::regex("\nseeds +4, 9\n"))) << text;
    EXPECT_TRUE(std::regex_search(text, std::regex("\nmerged from +a.exr, b.exr\n"))) << text;
    // The picture and the statistics say the same of themselves.
    for (const char* file : {"m.png", "ms.exr"}) {
        EXPECT_EQ(attribute(file, "raytracer:samplesPerPixel"), std::optional<std::string>("8"))
            << file;
        EXPECT_EQ(attribute(file, "raytracer:seed"), std::optional<std::string>("4 9")) << file;
    }
    EXPECT_EQ(io::readImage(folder_ / "m.png").width, 16);
}

// --- what every file says of itself ----------------------------------------------------------

TEST_F(ScaleOut, EveryOutputCarriesTheSettingsSeedSamplesSceneAndProgram)
{
    render({"24",
            "18",
            "--spp",
            "3",
            "--seed",
            "42",
            "--max-bounces",
            "7",
            "--rr-depth",
            "3",
            "--hit-tolerance",
            "0.3",
            "--fresnel",
            "exact",
            "--no-mis",
            "--sampler",
            "independent",
            "--max-steps",
            "300",
            "--over-relaxation",
            "1.1",
            "--step-scale",
            "0.9",
            "--output",
            "a.exr",
            "--stats-output",
            "s.exr"});
    render({"24",
            "18",
            "--spp",
            "3",
            "--seed",
            "42",
            "--max-bounces",
            "7",
            "--rr-depth",
            "3",
            "--hit-tolerance",
            "0.3",
            "--fresnel",
            "exact",
            "--no-mis",
            "--sampler",
            "independent",
            "--max-steps",
            "300",
            "--over-relaxation",
            "1.1",
            "--step-scale",
            "0.9",
            "--output",
            "a.png"});
    const ProcessResult version = run({"--version"});
    for (const char* file : {"a.exr", "s.exr", "a.png"}) {
        const io::ImageFileContents contents = io::readImageFile(folder_ / file);
        const auto metadata = film::metadataFromAttributes(contents.attributes, file);
        ASSERT_TRUE(metadata.has_value()) << file << " should describe itself";
        EXPECT_EQ(metadata->samplesPerPixel, 3) << file;
        EXPECT_EQ(metadata->sampleRanges, (std::vector<film::SampleRange>{{42, 0, 3}})) << file;
        EXPECT_EQ(metadata->settings.maxBounces, 7) << file;
        EXPECT_EQ(metadata->settings.russianRouletteDepth, 3) << file;
        EXPECT_EQ(metadata->settings.hitTolerance, 0.3f) << file;
        EXPECT_EQ(metadata->settings.maxMarchSteps, 300) << file;
        EXPECT_EQ(metadata->settings.overRelaxation, 1.1f) << file;
        EXPECT_EQ(metadata->settings.stepScale, 0.9f) << file;
        EXPECT_EQ(metadata->settings.dielectricFresnel, settings::FresnelModel::Exact) << file;
        EXPECT_FALSE(metadata->settings.multipleImportanceSampling) << file;
        EXPECT_EQ(metadata->settings.sampler, settings::SamplerKind::Independent) << file;
        EXPECT_EQ(metadata->sceneFile, scene1()) << file;
        EXPECT_EQ(metadata->sceneSha256.size(), 64u) << file;
        EXPECT_GT(metadata->renderSeconds, 0.0) << file;
        EXPECT_TRUE(metadata->interrupted.empty()) << file;
        EXPECT_EQ(metadata->program.rfind("raytracer ", 0), 0u) << file;
        // Built from this git checkout: the commit is the one --version names.
        ASSERT_EQ(metadata->gitCommit.size(), 40u) << file;
        EXPECT_NE(version.standardOutput.find(metadata->gitCommit), std::string::npos)
            << version.standardOutput;
    }
}

TEST_F(ScaleOut, TheSceneHashCoversItsTextureButNotWhereTheFilesAre)
{
    // A scene with a texture, in two folders; then the texture edited in one of them.
    const std::string scene = "0 1.2 4\n0 0.5 0\n0 1 0\n45\n1\n2 5 3  40 40 40\n"
                              "1\ntexmap wood.ppm 1\n1\n0 0 0  0 0 0 0\n"
                              "1\n0 0 sphere 0 0.5 0  0.5\n";
    std::ifstream texture(sourceDirectory() / "textures" / "wood.ppm", std::ios::binary);
    std::ostringstream wood;
    wood << texture.rdbuf();
    for (const char* folder : {"one", "two"}) {
        write(fs::path(folder) / "s.in", scene);
        write(fs::path(folder) / "wood.ppm", wood.str());
    }
    auto hashOf = [&](const std::string& folder) {
        render({"8", "6", "--spp", "1", "--output", folder + ".exr"},
               (folder_ / folder / "s.in").string());
        return attribute(folder + ".exr", "raytracer:sceneSha256").value_or("");
    };
    const std::string one = hashOf("one");
    EXPECT_EQ(hashOf("two"), one) << "the same files in another folder are the same scene";
    std::string edited = wood.str();
    edited[edited.size() - 1] = static_cast<char>(edited.back() ^ 1);
    write(fs::path("two") / "wood.ppm", edited);
    EXPECT_NE(hashOf("two"), one) << "a texture edited by one bit is another scene";
}

TEST_F(ScaleOut, TheSceneHashIsTheSha256OfTheScenesFilesAsDocumented)
{
    // A scene of one file: its SHA-256 is of its length (8 bytes, little-endian) and bytes.
    const std::string scene = "0 1.2 4\n0 0.5 0\n0 1 0\n45\n0\n1\nsolid 1 1 1\n"
                              "1\n0 0 0  0 0 0 0\n1\n0 0 sphere 0 0.5 0  0.5\n";
    write("s.in", scene);
    render({"8", "6", "--spp", "1", "--output", "s.exr"}, (folder_ / "s.in").string());
    io::Sha256 expected;
    unsigned char length[8] = {static_cast<unsigned char>(scene.size()), 0, 0, 0, 0, 0, 0, 0};
    expected.add(length, sizeof length);
    expected.add(scene);
    EXPECT_EQ(attribute("s.exr", "raytracer:sceneSha256"),
              std::optional<std::string>(expected.hexDigest()));
}

// --- merge refuses ----------------------------------------------------------------------------

TEST_F(ScaleOut, MergeRefusesRendersOfDifferentScenes)
{
    std::ifstream original(scene1());
    std::ostringstream text;
    text << original.rdbuf();
    write("scene1.in", text.str() + "\n# an edit\n");
    render({"16", "12", "--spp", "2", "--seed", "1", "--output", "a.exr"});
    render({"16", "12", "--spp", "2", "--seed", "2", "--output", "b.exr"},
           (folder_ / "scene1.in").string());
    expectRefused({"merge", "out.exr", "a.exr", "b.exr", "--png", "out.png"},
                  {"a.exr", "b.exr", "scene"});
}

TEST_F(ScaleOut, MergeRefusesRendersOfDifferentSizes)
{
    render({"16", "12", "--spp", "2", "--seed", "1", "--output", "a.exr"});
    render({"12", "16", "--spp", "2", "--seed", "2", "--output", "b.exr"});
    expectRefused({"merge", "out.exr", "a.exr", "b.exr"}, {"size", "16x12", "12x16"});
}

TEST_F(ScaleOut, MergeRefusesRendersOfDifferentSettings)
{
    render({"16", "12", "--spp", "2", "--seed", "1", "--output", "a.exr"});
    render({"16", "12", "--spp", "2", "--seed", "2", "--rr-depth", "2", "--output", "b.exr"});
    expectRefused({"merge", "out.exr", "a.exr", "b.exr"}, {"--rr-depth", "4", "2"});
}

TEST_F(ScaleOut, MergeRefusesRendersThatShareASeed)
{
    render({"16", "12", "--spp", "2", "--seed", "5", "--output", "a.exr"});
    render({"16", "12", "--spp", "3", "--seed", "5", "--output", "b.exr"});
    expectRefused({"merge", "out.exr", "a.exr", "b.exr"}, {"seed 5", "--seed"});
}

TEST_F(ScaleOut, MergeRefusesARenderWithItsOwnResumedContinuation)
{
    render({"16", "12", "--spp", "2", "--seed", "5", "--output", "a.exr"});
    render({"--resume", "a.exr", "--spp", "4", "--output", "more.exr"});
    expectRefused({"merge", "out.exr", "a.exr", "more.exr"}, {"seed 5"});
}

TEST_F(ScaleOut, MergeRefusesAFileWithoutAnAccumulation)
{
    render({"16", "12", "--spp", "2", "--seed", "1", "--output", "a.exr"});
    render({"16", "12", "--spp", "2", "--seed", "2", "--output", "b.png"});
    expectRefused({"merge", "out.exr", "a.exr", "b.png"}, {"b.png", "accumulation"});
}

TEST_F(ScaleOut, MergeOfInputsThatDoNotExistSaysWhichAndWritesNothing)
{
    render({"16", "12", "--spp", "2", "--seed", "1", "--output", "a.exr"});
    expectRefused({"merge", "out.exr", "a.exr", "missing.exr"}, {"missing.exr"});
}

// --- resume ------------------------------------------------------------------------------------

TEST_F(ScaleOut, ResumeAfterAnInterruptEqualsAnUninterruptedRender)
{
    // Interrupted once its first frame is done, with one sample a frame.
    ProcessOptions interrupt;
    interrupt.terminalColumns = 200;
    interrupt.signalWhenErrorShows = " spp";
    const ProcessResult stopped = run({scene1(), "64", "48", "--spp", "64", "--seed", "8",
                                       "--samples-per-frame", "1", "--output", "r.exr"},
                                      interrupt);
    ASSERT_TRUE(stopped.exited && stopped.exitStatus == 130) << describe(stopped);
    const film::RenderFile before = readRender("r.exr");
    const int held = film::samplesTakenSpan(before.accumulation).most;
    ASSERT_GT(held, 0);
    ASSERT_LT(held, 64) << "the render should have been interrupted before its end";
    EXPECT_FALSE(before.metadata.interrupted.empty()) << "the file is marked interrupted";

    render({"64", "48", "--resume", "r.exr", "--spp", "64"});
    render({"64", "48", "--spp", "64", "--seed", "8", "--output", "whole.exr"});
    render({"64", "48", "--spp", "64", "--seed", "80", "--output", "other.exr"});
    const film::RenderFile resumed = readRender("r.exr");
    const film::RenderFile whole = readRender("whole.exr");
    expectEveryPixelHolds(resumed.accumulation, 64);
    EXPECT_EQ(resumed.metadata.samplesPerPixel, 64);
    EXPECT_EQ(resumed.metadata.sampleRanges, (std::vector<film::SampleRange>{{8, 0, 64}}))
        << "the resumed samples continue seed 8's indices";
    EXPECT_TRUE(resumed.metadata.interrupted.empty()) << "the resumed render reached its end";
    EXPECT_GT(resumed.metadata.renderSeconds, before.metadata.renderSeconds)
        << "the render time adds up";

    const Comparison comparison =
        compareImages(asRenderedImage(resumed.accumulation),
                      asRenderedImage(readRender("other.exr").accumulation));
    EXPECT_TRUE(comparison.passed()) << comparison.describe();
    // Stronger than noise: the same seed's next indices give the very render that never
    // stopped.
    EXPECT_EQ(resumed.accumulation.estimate.pixels, whole.accumulation.estimate.pixels);
    EXPECT_EQ(resumed.accumulation.moments.pixels, whole.accumulation.moments.pixels);
}

TEST_F(ScaleOut, InterruptingAResumedRenderLosesNothing)
{
    render({"64", "48", "--spp", "6", "--seed", "3", "--output", "r.exr"});
    const std::string six = contents("r.exr");

    // Interrupted at once, before its first new sample: the file stays as it was.
    ProcessOptions atOnce;
    atOnce.signalAfterSeconds = 0.0;
    atOnce.startWithSignalBlocked = true;
    const ProcessResult early = run({scene1(), "--resume", "r.exr", "--spp", "1000"}, atOnce);
    ASSERT_TRUE(early.exited && early.exitStatus == 130) << describe(early);
    EXPECT_EQ(contents("r.exr"), six) << "an interrupt before a new sample leaves the file";
    EXPECT_EQ(filesInFolder(), std::vector<std::string>{"r.exr"});

    // Interrupted after a frame: more samples than before, the first six among them.
    ProcessOptions afterAFrame;
    afterAFrame.terminalColumns = 200;
    afterAFrame.signalWhenErrorShows = " spp";
    const ProcessResult later =
        run({scene1(), "--resume", "r.exr", "--spp", "100000", "--samples-per-frame", "1"},
            afterAFrame);
    ASSERT_TRUE(later.exited && later.exitStatus == 130) << describe(later);
    const film::RenderFile resumed = readRender("r.exr");
    const film::SampleCountSpan span = film::samplesTakenSpan(resumed.accumulation);
    EXPECT_GT(span.fewest, 6) << "every pixel holds more than the six it had";
    EXPECT_EQ(resumed.metadata.sampleRanges.size(), 1u);
    EXPECT_EQ(resumed.metadata.sampleRanges.front().first, 0);
    EXPECT_NE(resumed.metadata.interrupted.find("of 100000"), std::string::npos)
        << resumed.metadata.interrupted;
    EXPECT_EQ(filesInFolder(), std::vector<std::string>{"r.exr"}) << "no temporary file left";
}

TEST_F(ScaleOut, ResumeRefusesAnotherSizeOrScene)
{
    render({"16", "12", "--spp", "2", "--output", "r.exr"});
    expectRefused({scene1(), "12", "16", "--resume", "r.exr", "--spp", "4"},
                  {"r.exr", "size", "16x12", "12x16"});
    expectRefused(
        {(sourceDirectory() / "scenes" / "scene2.in").string(), "--resume", "r.exr", "--spp", "4"},
        {"r.exr", "scene"});
}

TEST_F(ScaleOut, ResumeRefusesAnSppItHoldsAlready)
{
    render({"16", "12", "--spp", "4", "--output", "r.exr"});
    expectRefused({scene1(), "--resume", "r.exr", "--spp", "4"}, {"r.exr", "holds 4"});
}

TEST_F(ScaleOut, ResumeWithoutAnEndIsACommandLineError)
{
    const ProcessResult result = run({scene1(), "--resume", "r.exr"});
    ASSERT_TRUE(result.exited) << describe(result);
    EXPECT_EQ(result.exitStatus, 2) << describe(result);
    EXPECT_EQ(nonEmptyLines(result.standardError).size(), 1u) << describe(result);
}

// Checked before any rendering: each is a one-line refusal naming the setting, and nothing
// written. (One test for all: a base render costs more than every refusal together.)
TEST_F(ScaleOut, ResumeRefusesEveryImageChangingSettingThatDiffers)
{
    render({"16", "12", "--spp", "2", "--output", "r.exr"});
    const std::vector<std::vector<std::string>> changes = {{"--hit-tolerance", "0.5"},
                                                           {"--max-steps", "100"},
                                                           {"--over-relaxation", "1.5"},
                                                           {"--step-scale", "0.5"},
                                                           {"--max-bounces", "3"},
                                                           {"--rr-depth", "1"},
                                                           {"--no-mis"},
                                                           {"--fresnel", "exact"},
                                                           {"--sampler", "independent"},
                                                           {"--exact-geometry"},
                                                           {"--no-specialize"}};
    for (const std::vector<std::string>& change : changes) {
        SCOPED_TRACE(change.front());
        std::vector<std::string> arguments = {scene1(), "--resume", "r.exr", "--spp", "4"};
        arguments.insert(arguments.end(), change.begin(), change.end());
        expectRefused(arguments, {"r.exr", change.front()});
    }
}

}  // namespace
}  // namespace cli_tests
