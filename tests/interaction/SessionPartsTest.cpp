// The window session's parts that need no window: which files it watches and how it sees
// them change, how it paces frames and previews, what it names saved images, and the history
// behind the convergence plot.
#include "app/SceneLoading.h"
#include "app/Snapshot.h"
#include "interaction/ConvergenceHistory.h"
#include "interaction/FileWatcher.h"
#include "interaction/FramePacing.h"
#include "scene/SceneTestSupport.h"

#include <gtest/gtest.h>

#include <chrono>
#include <fstream>
#include <unistd.h>

namespace interaction_tests {
namespace {

namespace fs = std::filesystem;

class FileWatcherTest : public ::testing::Test {
protected:
    void SetUp() override
    {
        folder_ = fs::temp_directory_path() /
                  ("raytracer-watch-" + std::to_string(::getpid()) + "-" +
                   ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::create_directories(folder_);
    }
    void TearDown() override { fs::remove_all(folder_); }

    fs::path write(const std::string& name, const std::string& text)
    {
        std::ofstream(folder_ / name) << text;
        return folder_ / name;
    }

    fs::path folder_;
};

TEST_F(FileWatcherTest, ReportsEachChangeOnce)
{
    const fs::path scene = write("scene.in", "one");
    const fs::path other = write("other.glsl", "two");
    interaction::FileWatcher watcher;
    watcher.watch({scene, other});
    EXPECT_TRUE(watcher.changedFiles().empty()) << "nothing changed yet";
    write("scene.in", "changed and longer");
    EXPECT_EQ(watcher.changedFiles(), std::vector<fs::path>{scene});
    EXPECT_TRUE(watcher.changedFiles().empty()) << "a change is reported once";
}

TEST_F(FileWatcherTest, AFileThatDisappearsOrAppearsHasChanged)
{
    const fs::path scene = write("scene.in", "one");
    interaction::FileWatcher watcher;
    watcher.watch({scene, folder_ / "later.glsl"});
    fs::remove(scene);
    write("later.glsl", "new");
    EXPECT_EQ(watcher.changedFiles().size(), 2u);
}

TEST_F(FileWatcherTest, AFileStillWatchedKeepsItsLastSeenStateAcrossWatch)
{
    const fs::path scene = write("scene.in", "one");
    interaction::FileWatcher watcher;
    watcher.watch({scene});
    // Edited while the scene was being reloaded, before the new list is watched.
    write("scene.in", "edited meanwhile");
    watcher.watch({scene, write("texture.ppm", "x")});
    EXPECT_EQ(watcher.changedFiles(), std::vector<fs::path>{scene});
}

TEST_F(FileWatcherTest, TouchingAFileOrSavingItUnchangedIsNoChange)
{
    const fs::path scene = write("scene.in", "one");
    interaction::FileWatcher watcher;
    watcher.watch({scene});
    fs::last_write_time(scene, fs::last_write_time(scene) + std::chrono::seconds(10));
    EXPECT_TRUE(watcher.changedFiles().empty()) << "touched: a new time, the same bytes";
    // Saved unchanged as editors save: a new file with the same bytes renamed over the old.
    std::ofstream(folder_ / "scene.in.new") << "one";
    fs::rename(folder_ / "scene.in.new", scene);
    fs::last_write_time(scene, fs::last_write_time(scene) + std::chrono::seconds(20));
    EXPECT_TRUE(watcher.changedFiles().empty()) << "saved unchanged: the same bytes";
}

TEST_F(FileWatcherTest, NewBytesOfTheSameSizeAreAChange)
{
    const fs::path scene = write("scene.in", "one");
    interaction::FileWatcher watcher;
    watcher.watch({scene});
    write("scene.in", "two");
    fs::last_write_time(scene, fs::last_write_time(scene) + std::chrono::seconds(10));
    EXPECT_EQ(watcher.changedFiles(), std::vector<fs::path>{scene});
    EXPECT_TRUE(watcher.changedFiles().empty()) << "a change is reported once";
}

TEST(SceneFiles, AreTheSceneItsUserSdfFilesItsTexturesAndItsEnvironmentMap)
{
    const std::string text = "environment map sky-sun.hdr\n0 1 4\n0 0 0\n0 1 0\n45\n0\n"
                             "2\ntexmap brick.ppm 1\nsolid 1 1 1\n1\n0 0 0  0 0 0 0\n"
                             "2\n0 0 twisted_bar 0 0.4 0\n1 0 sphere 0 0 0 1\n";
    const std::vector<fs::path> files = app::filesOfScene("my.in", scene_tests::parse(text));
    ASSERT_EQ(files.size(), 4u);
    EXPECT_EQ(files[0], fs::path("my.in"));
    EXPECT_EQ(files[1].filename(), "twisted_bar.glsl");
    EXPECT_EQ(files[2].filename(), "brick.ppm");
    EXPECT_EQ(files[3].filename(), "sky-sun.hdr");
}

TEST(SnapshotFiles, AreNamedAfterTheSceneAndTheSamplesInTheCurrentOrOutputFolder)
{
    const app::SnapshotFiles here = app::snapshotFiles("scenes/scene3.in", 120, std::nullopt);
    EXPECT_EQ(here.picture, fs::path("scene3-120spp.png"));
    EXPECT_EQ(here.radiance, fs::path("scene3-120spp.exr"));
    const app::SnapshotFiles there =
        app::snapshotFiles("scene3.in", 7, fs::path("renders/final.exr"));
    EXPECT_EQ(there.picture, fs::path("renders/scene3-7spp.png"));
    EXPECT_EQ(there.radiance, fs::path("renders/scene3-7spp.exr"));
}

TEST(FramePacing, SamplesPerFrameAimAtTheTargetTimeWithinOneToSixteen)
{
    EXPECT_EQ(interaction::samplesPerFrameFor(0.15, 0.03), 5);
    EXPECT_EQ(interaction::samplesPerFrameFor(0.15, 1.0), 1);
    EXPECT_EQ(interaction::samplesPerFrameFor(0.15, 1e-5), 16);
    EXPECT_EQ(interaction::samplesPerFrameFor(0.15, 0.0), 16);
}

// The setting's value for the first frame, then the cost of the last frame decides, the first
// one's included: its code generation can only shorten the second frame.
TEST(FramePacing, SamplesPerFrameFollowTheCostOfTheLastFrameFromTheFirstOn)
{
    interaction::SamplesPerFrame pacing(1, false, 0.15);
    EXPECT_EQ(pacing.samples(), 1);
    pacing.afterFrame(1, 0.03);
    EXPECT_EQ(pacing.samples(), 5);
    pacing.afterFrame(2, 0.15);
    EXPECT_EQ(pacing.samples(), 1);
    pacing.afterFrame(3, 1e-5);
    EXPECT_EQ(pacing.samples(), 16);
}

TEST(FramePacing, SamplesPerFrameTheUserGaveAreKept)
{
    interaction::SamplesPerFrame pacing(7, true, 0.15);
    pacing.afterFrame(2, 0.03);
    pacing.afterFrame(3, 1e-5);
    EXPECT_EQ(pacing.samples(), 7);
}

TEST(FramePacing, SamplesPerFrameStayWithinTheLoopsMost)
{
    interaction::SamplesPerFrame pacing(1, false, 0.5, 1024);
    pacing.afterFrame(2, 1e-5);
    EXPECT_EQ(pacing.samples(), 1024);
}

// A render aimed at an error stops at the first frame that ends with the target reached: a
// frame takes at most a tenth of the time predicted to be left, and no less than 0.05 s.
TEST(FramePacing, FramesAimedAtAnErrorTakeATenthOfThePredictedTimeLeft)
{
    interaction::SamplesPerFrame pacing(1, false, 0.5, 1024);
    pacing.afterFrame(2, 0.001);
    EXPECT_EQ(pacing.samples(), 500) << "no prediction: the loop's 0.5 s";
    pacing.afterFrame(3, 0.001, 2.0);
    EXPECT_EQ(pacing.samples(), 200) << "0.2 s of the 2 s left";
    pacing.afterFrame(4, 0.001, 0.1);
    EXPECT_EQ(pacing.samples(), 50) << "never below 0.05 s";
    pacing.afterFrame(5, 0.001, 60.0);
    EXPECT_EQ(pacing.samples(), 500) << "never above the loop's own frame time";
}

// A render with a time limit abandons the frame the limit interrupts: a frame aims to end by
// the limit, at 0.9 of the time to it, and takes no less than 0.05 s.
TEST(FramePacing, FramesOfARenderWithATimeLimitAimToEndBeforeIt)
{
    interaction::SamplesPerFrame pacing(1, false, 2.0, 1024);
    pacing.afterFrame(2, 0.001, std::nullopt, 60.0);
    EXPECT_EQ(pacing.samples(), 1024) << "far from the limit: the loop's 2 s, within its most";
    pacing.afterFrame(3, 0.01, std::nullopt, 1.0);
    EXPECT_EQ(pacing.samples(), 90) << "0.9 of the 1 s left";
    pacing.afterFrame(4, 0.01, std::nullopt, 0.01);
    EXPECT_EQ(pacing.samples(), 5) << "never below 0.05 s";
    pacing.afterFrame(5, 0.001, 2.0, 1.0);
    EXPECT_EQ(pacing.samples(), 200) << "a predicted error's tenth, when that is shorter";
}

TEST(FramePacing, ThePreviewGridCoarsensWhenSlowAndRefinesWhenFast)
{
    EXPECT_EQ(interaction::nextPreviewDivisor(2, 0.2), 3);
    EXPECT_EQ(interaction::nextPreviewDivisor(3, 0.01), 2);
    EXPECT_EQ(interaction::nextPreviewDivisor(3, 0.05), 3) << "inside the band it stays";
    EXPECT_EQ(interaction::nextPreviewDivisor(1, 0.001), 1);
    EXPECT_EQ(interaction::nextPreviewDivisor(interaction::kMaxPreviewDivisor, 5.0),
              interaction::kMaxPreviewDivisor);
}

TEST(FramePacing, TheFirstPreviewGridFollowsTheCostOfAFullSample)
{
    EXPECT_EQ(interaction::firstPreviewDivisor(0.01), 1);
    EXPECT_EQ(interaction::firstPreviewDivisor(0.04), 1);
    EXPECT_EQ(interaction::firstPreviewDivisor(0.15), 2) << "0.15 / 4 = 0.0375";
    EXPECT_EQ(interaction::firstPreviewDivisor(0.5), 4) << "0.5 / 9 > 0.04 >= 0.5 / 16";
    EXPECT_EQ(interaction::firstPreviewDivisor(1000.0), interaction::kMaxPreviewDivisor);
}

TEST(ConvergenceHistory, KeepsPointsOneSpacingApart)
{
    interaction::ConvergenceHistory history;
    history.add(0.0, 1.0f);
    history.add(0.2, 0.9f);  // too soon
    history.add(0.5, 0.8f);
    history.add(0.99, 0.7f);
    EXPECT_EQ(history.errors(), (std::vector<float>{1.0f, 0.8f, 0.7f}));
}

TEST(ConvergenceHistory, WhenFullHalvesItsPointsAndDoublesItsSpacingToSpanEverything)
{
    interaction::ConvergenceHistory history;
    const std::size_t capacity = interaction::ConvergenceHistory::kCapacity;
    const double spacing = interaction::ConvergenceHistory::kFirstSpacingSeconds;
    for (std::size_t i = 0; i < capacity; ++i)
        history.add(i * spacing, static_cast<float>(i));
    ASSERT_EQ(history.errors().size(), capacity);
    // Full: the points at even positions stay, the last of them at (capacity - 2) * spacing,
    // and the new one is a doubled spacing after it.
    history.add(capacity * spacing, -1.0f);
    EXPECT_EQ(history.errors().size(), capacity / 2 + 1);
    EXPECT_DOUBLE_EQ(history.spacingSeconds(), 2.0 * spacing);
    EXPECT_EQ(history.errors()[1], 2.0f) << "every other point is kept";
    EXPECT_EQ(history.errors().back(), -1.0f);
    history.add((capacity + 1) * spacing, -2.0f);
    EXPECT_EQ(history.errors().back(), -1.0f) << "one old spacing on is too soon now";
    history.add((capacity + 2) * spacing, -3.0f);
    EXPECT_EQ(history.errors().back(), -3.0f);
}

// Without a trend yet, the error is taken to fall as 1 / sqrt(time): from 4 % at 10 s, 1 %
// takes 16 times the time, 150 s more.
TEST(ConvergenceHistory, PredictsTheInverseSquareRootLawWithoutATrend)
{
    interaction::ConvergenceHistory history;
    EXPECT_NEAR(*history.secondsLeftToReach(0.01, 10.0, 0.04), 150.0, 1e-9);
    EXPECT_EQ(*history.secondsLeftToReach(0.01, 10.0, 0.005), 0.0);
    EXPECT_FALSE(history.secondsLeftToReach(0.01, 0.0, 0.04));
}

// An error falling as 1 / time (adaptive sampling leaving the easy pixels) reaches a quarter
// of itself in four times the time.
TEST(ConvergenceHistory, PredictsFromTheTrendOfTheLatterHalf)
{
    interaction::ConvergenceHistory history;
    history.add(1.0, 0.9f);  // early and off the trend: not in the latter half
    for (double seconds = 5.0; seconds <= 10.0; seconds += 0.5)
        history.add(seconds, static_cast<float>(0.4 / seconds));
    EXPECT_NEAR(*history.secondsLeftToReach(0.01, 10.0, 0.04), 30.0, 0.1);
}

}  // namespace
}  // namespace interaction_tests
