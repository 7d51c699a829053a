// Files from elsewhere are untrusted (docs/USAGE.md, "Files from elsewhere"): merge, --resume and
// info refuse, in one line and writing nothing, each kind of file issue 35 found them to
// accept (made from a render of the program by support/CraftedRenderFiles.cpp), and files that
// are not regular files at all, without waiting on them.
#include "app/ProgramInFolder.h"
#include "support/ChildProcess.h"
#include "support/CraftedRenderFiles.h"
#include "support/TestPaths.h"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <sys/stat.h>

namespace cli_tests {
namespace {

using namespace testing_support;
namespace fs = std::filesystem;

class UntrustedInput : public ProgramInFolder {
protected:
    static std::string scene1() { return (sourceDirectory() / "scenes" / "scene1.in").string(); }

    // An 8x6 render of scene 1, 4 samples per pixel, of `seed`.
    void renderShard(const std::string& seed, const std::string& name) const
    {
        const ProcessResult result =
            run({scene1(), "8", "6", "--spp", "4", "--seed", seed, "--quiet", "--output", name});
        ASSERT_TRUE(result.exited && result.exitStatus == 0) << describe(result);
    }

    // Seeds 1 (a.exr) and 2 (b.exr): merged, they hold 8 samples per pixel.
    void renderTwoShards() const
    {
        renderShard("1", "a.exr");
        renderShard("2", "b.exr");
    }

    void craft(const std::string& name, const fs::path& base, const fs::path& crafted) const
    {
        writeCraftedRenderFile(craftedRenderFile(name), folder_ / base, folder_ / crafted);
    }

    std::string contents(const fs::path& name) const
    {
        std::ifstream file(folder_ / name, std::ios::binary);
        std::ostringstream text;
        text << file.rdbuf();
        return text.str();
    }

    // Refused: exit status 1 within `seconds`, one line on standard error holding each of
    // `words`, and nothing written or changed in the folder.
    void expectRefused(const std::vector<std::string>& arguments,
                       const std::vector<std::string>& words, double seconds = 30.0) const
    {
        const std::vector<std::string> before = filesInFolder();
        std::vector<std::string> contentsBefore;
        for (const std::string& name : before)
            contentsBefore.push_back(fs::is_regular_file(folder_ / name) ? contents(name) : "");
        ProcessOptions options;
        options.timeoutSeconds = seconds;
        const ProcessResult result = run(arguments, options);
        ASSERT_TRUE(result.exited) << describe(result);
        EXPECT_EQ(result.exitStatus, 1) << describe(result);
        const auto lines = nonEmptyLines(result.standardError);
        ASSERT_EQ(lines.size(), 1u) << "one line on standard error; " << describe(result);
        for (const std::string& word : words)
            EXPECT_NE(lines[0].find(word), std::string::npos)
                << "the reason should say '" << word << "': " << lines[0];
        EXPECT_EQ(filesInFolder(), before) << "nothing may be written";
        for (std::size_t i = 0; i < before.size(); ++i) {
            if (fs::is_regular_file(folder_ / before[i])) {
                EXPECT_EQ(contents(before[i]), contentsBefore[i])
                    << before[i] << " must be left as it was";
            }
        }
    }
};

// --- values no render holds -------------------------------------------------------------

TEST_F(UntrustedInput, MergeRefusesANegativeCountNamingThePixelAndChannel)
{
    // Merged, a count of -3 in one pixel gave "pixels hold 2 to 4".
    renderTwoShards();
    craft("negative-count", "b.exr", "c.exr");
    expectRefused({"merge", "m.exr", "a.exr", "c.exr"},
                  {"cannot merge", "c.exr", craftedRenderFile("negative-count").refusal});
}

TEST_F(UntrustedInput, MergeRefusesAFileWhoseStoredBytesChanged)
{
    // One bit of the PIZ-compressed pixels changed: merged without a word.
    renderTwoShards();
    craft("piz-byte-flipped", "b.exr", "piz-byte-flipped.exr");
    expectRefused({"merge", "m.exr", "a.exr", "piz-byte-flipped.exr"},
                  {"cannot merge", "piz-byte-flipped.exr"});
}

TEST_F(UntrustedInput, MergeRefusesSamplesPerPixelNoPixelHolds)
{
    // 2147483647 samples per pixel in each of two shards merged to "-2 spp".
    renderTwoShards();
    craft("samples-per-pixel-2147483647", "a.exr", "c.exr");
    craft("samples-per-pixel-2147483647", "b.exr", "d.exr");
    expectRefused({"merge", "m.exr", "c.exr", "d.exr"},
                  {"c.exr", craftedRenderFile("samples-per-pixel-2147483647").refusal});
}

TEST_F(UntrustedInput, MergeRefusesSamplesPerPixelThatSumBeyondWhatAPixelHolds)
{
    // Each file within the largest count, 2^24 samples per pixel; together twice that. The
    // sum is 64-bit, and refused.
    renderTwoShards();
    for (const auto& [base, seed, full] :
         {std::tuple{"a.exr", "1", "c.exr"}, std::tuple{"b.exr", "2", "d.exr"}}) {
        const std::string ranges = std::string(seed) + ":0+16777216";
        writeCraftedRenderFile({"full",
                                "",
                                [&](io::ImageFileContents& file) {
                                    setAttribute(file, "raytracer:samplesPerPixel", "16777216");
                                    setAttribute(file, "raytracer:sampleRanges", ranges);
                                },
                                "",
                                {}},
                               folder_ / base, folder_ / full);
    }
    expectRefused({"merge", "m.exr", "c.exr", "d.exr"},
                  {"cannot merge", "33554432 samples per pixel", "16777216"});
}

TEST_F(UntrustedInput, ResumeRefusesACountOfATrillionAtOnce)
{
    // Through lround into an int, a count of 1e12 wrapped, and the render went on for ever.
    renderShard("1", "a.exr");
    craft("count-of-a-trillion", "a.exr", "c.exr");
    expectRefused({scene1(), "--resume", "c.exr", "--spp", "8", "--output", "r.exr"},
                  {"cannot resume", craftedRenderFile("count-of-a-trillion").refusal}, 30.0);
}

TEST_F(UntrustedInput, InfoRefusesAMeanThatIsNotANumber)
{
    renderShard("1", "a.exr");
    craft("nan-mean", "a.exr", "c.exr");
    expectRefused({"info", "c.exr"}, {craftedRenderFile("nan-mean").refusal});
}

TEST_F(UntrustedInput, InfoRefusesAHeaderAskingForGigabytesOfASmallFile)
{
    // A 20 KB file whose header says 10000x10000: 3.2 GB allocated before a pixel was read.
    renderShard("1", "a.exr");
    craft("data-window-10000x10000-in-20-kb", "a.exr", "big.exr");
    expectRefused({"info", "big.exr"},
                  {"big.exr", craftedRenderFile("data-window-10000x10000-in-20-kb").refusal});
}

// --- files that are not regular files ---------------------------------------------------

TEST_F(UntrustedInput, InfoRefusesALinkToADeviceAtOnce)
{
    // OpenImageIO's readers, tried one after another, spun on /dev/zero for ever.
    fs::create_symlink("/dev/zero", folder_ / "z.exr");
    expectRefused({"info", "z.exr"}, {"z.exr", "a character device, not a regular file"}, 20.0);
}

TEST_F(UntrustedInput, MergeRefusesAFifoWithoutWaitingOnIt)
{
    renderShard("1", "a.exr");
    ASSERT_EQ(::mkfifo((folder_ / "f.exr").c_str(), 0600), 0);
    expectRefused({"merge", "m.exr", "a.exr", "f.exr"}, {"f.exr", "a FIFO, not a regular file"},
                  20.0);
}

TEST_F(UntrustedInput, ResumeRefusesAFolder)
{
    fs::create_directories(folder_ / "d.exr");
    expectRefused({scene1(), "--resume", "d.exr", "--spp", "8"},
                  {"d.exr", "a folder, not a regular file"}, 20.0);
}

}  // namespace
}  // namespace cli_tests
