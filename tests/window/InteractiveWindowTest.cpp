// The window as a user meets it, under a virtual X server (run-under-xvfb.sh): synthetic
// mouse and key input through xdotool, and what the window shows read back from the X
// server, its title and its pixels. Each test runs the program in its own folder on a scene
// it writes there, and edits that scene as a user would (a new file renamed over the old,
// as editors save).
#include "io/ImageFile.h"
#include "scene/FileLookup.h"
#include "scene/SceneBounds.h"
#include "scene/SceneParser.h"

#include "support/ChildProcess.h"
#include "window/WindowDriver.h"
#include <glm/glm.hpp>

#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <future>
#include <iostream>
#include <iterator>
#include <optional>
#include <sstream>
#include <thread>
#include <unistd.h>

namespace window_tests {
namespace {

using namespace testing_support;
namespace fs = std::filesystem;

// A red sphere on a grey floor under a point light and the sky. `colour` is the sphere's
// pigment (line 8); `extraObjects` follow the two objects (the count on line 12 follows).
std::string sceneText(const std::string& colour, const std::string& extraObjects = "",
                      int extraCount = 0, const std::string& sphereWord = "sphere")
{
    return "0 1.2 4\n"          // 1 eye
           "0 0.5 0\n"          // 2 target
           "0 1 0\n"            // 3 up
           "45\n"               // 4 fovy
           "1\n"                // 5 point lights
           "2 5 3  40 40 40\n"  // 6
           "2\n"                // 7 pigments
           "solid " +
           colour +
           "\n"                   // 8
           "solid 0.5 0.5 0.5\n"  // 9
           "1\n"                  // 10 finishes
           "0 0 0  0 0 0 0\n"     // 11
           + std::to_string(2 + extraCount) +
           "\n"  // 12 objects
           "0 0 " +
           sphereWord +
           " 0 0.5 0  0.5\n"     // 13
           "1 0 polyhedron 1\n"  // 14
           "    0 1 0 0\n"       // 15
           + extraObjects;
}

const char* const kRed = "0.8 0.1 0.1";

std::string readText(const fs::path& path)
{
    std::ifstream file(path);
    return std::string(std::istreambuf_iterator<char>(file), {});
}
const char* const kBlue = "0.1 0.1 0.8";

class InteractiveWindow : public ::testing::Test {
protected:
    void SetUp() override
    {
        ASSERT_NE(std::getenv("DISPLAY"), nullptr)
            << "run this test through run-under-xvfb.sh, which provides a display";
        folder_ = fs::temp_directory_path() /
                  ("raytracer-interactive-" + std::to_string(::getpid()) + "-" +
                   ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::remove_all(folder_);
        fs::create_directories(folder_);
    }

    void TearDown() override
    {
        if (program_.valid()) {
            try {
                pressEscapeToClose(window_);
            } catch (const std::exception&) {
            }
            program_.wait();
        }
        fs::remove_all(folder_);
    }

    // Saves the scene file as an editor does: a new file renamed over the old one.
    void writeScene(const std::string& text)
    {
        const fs::path temporary = folder_ / "scene.in.new";
        std::ofstream(temporary) << text;
        fs::rename(temporary, folder_ / "scene.in");
    }

    // Starts the program on folder/scene.in in a window of the size given (160x120 unless
    // told) and waits for the window. The statistics panel starts hidden; `showPanel` shows
    // it with Tab.
    void start(const std::vector<std::string>& options = {}, bool showPanel = false,
               const std::string& width = "160", const std::string& height = "120")
    {
        std::vector<std::string> arguments = {RAYTRACER_EXECUTABLE, "scene.in", width, height};
        arguments.insert(arguments.end(), options.begin(), options.end());
        ProcessOptions processOptions;
        processOptions.workingDirectory = folder_;
        processOptions.timeoutSeconds = 60.0;
        program_ = std::async(std::launch::async, [arguments, processOptions] {
            return runProcess(arguments, processOptions);
        });
        const std::optional<unsigned long> window = findWindow("raytracer", 20.0);
        if (!window && running())
            FAIL() << "no window appeared within 20 s, and the program is still running";
        if (!window) {
            const ProcessResult ended = program_.get();
            FAIL() << "no window appeared: the program " << ended.describeEnd() << "\n"
                   << ended.standardOutput << ended.standardError;
        }
        window_ = *window;
        if (showPanel)
            pressKey(window_, "Tab");
    }

    // Waits until the title shows at least `samples` samples per pixel, and returns it.
    std::string waitForSamples(int samples, double seconds = 20.0)
    {
        return waitForTitle(
            window_,
            [samples](const std::string& title) { return samplesInTitle(title) >= samples; },
            seconds);
    }

    std::string waitForTitleWith(const std::string& part, double seconds = 20.0)
    {
        return waitForTitle(
            window_,
            [&part](const std::string& title) { return title.find(part) != std::string::npos; },
            seconds);
    }

    // Waits for the title to show that the view changed since it showed `before`: `moving`
    // (a preview while the view changes) or fewer samples than then (the accumulation
    // restarted). Returns that title, or the last title read after `seconds`. A title read
    // the moment after the input may still be one from before it, so the test waits for the
    // change instead of reading the title once.
    std::string waitForRestartAfter(const std::string& before, double seconds = 10.0)
    {
        const int samplesBefore = samplesInTitle(before);
        return waitForTitle(
            window_,
            [samplesBefore](const std::string& title) {
                return title.find("moving") != std::string::npos ||
                       (samplesInTitle(title) >= 0 && samplesInTitle(title) < samplesBefore);
            },
            seconds);
    }

    static bool showsRestart(const std::string& before, const std::string& after)
    {
        return after.find("moving") != std::string::npos ||
               (samplesInTitle(after) >= 0 && samplesInTitle(after) < samplesInTitle(before));
    }

    // Watches the title for `seconds`: returns the first title whose sample count fell
    // below the one before it (the accumulation restarted) or that says the scene was
    // reloaded, or else the last title read.
    std::string firstRestartWithin(double seconds)
    {
        int previous = samplesInTitle(windowTitle(window_));
        return waitForTitle(
            window_,
            [&previous](const std::string& title) {
                const int samples = samplesInTitle(title);
                const bool restarted =
                    samples < previous || title.find("reloaded") != std::string::npos;
                previous = samples;
                return restarted;
            },
            seconds);
    }

    // Closes the window with Escape and returns how the program ended.
    // A window gone before the Escape is a failure that says how the program ended.
    ProcessResult close()
    {
        try {
            pressEscapeToClose(window_);
        } catch (const std::exception& error) {
            if (program_.wait_for(std::chrono::seconds(5)) != std::future_status::ready)
                throw;
            ProcessResult result = program_.get();
            ADD_FAILURE() << "the window was gone before Escape (" << error.what()
                          << "): the program " << result.describeEnd() << "\n"
                          << result.standardOutput << result.standardError;
            return result;
        }
        return program_.get();
    }

    static fs::path scene1Path() { return fs::path(RAYTRACER_SOURCE_DIR) / "scenes" / "scene1.in"; }

    static scene::Scene readScene1() { return scene::parseSceneFile(scene1Path()); }

    // Presses C and reads back the camera it writes to scene.camera (scene1's objects after
    // it); none, with a failure, where the window does not say it wrote it.
    std::optional<scene::Camera> writtenCamera()
    {
        pressKey(window_, "c");
        const std::string written = waitForTitleWith("camera line");
        if (written.find("scene.camera") == std::string::npos) {
            ADD_FAILURE() << "C must write the camera to scene.camera: " << written;
            return std::nullopt;
        }
        const std::string scene1Text = readText(scene1Path());
        // scene1's text after its camera (its field of view, 35, ends it).
        return scene::parseSceneText(readText(folder_ / "scene.camera") + "\n" +
                                         scene1Text.substr(scene1Text.find("35\n") + 3),
                                     "written.in", scene::FileLookup::forScene(scene1Path()))
            .camera;
    }

    bool running() const
    {
        return program_.wait_for(std::chrono::seconds(0)) != std::future_status::ready;
    }

    fs::path folder_;
    std::future<ProcessResult> program_;
    unsigned long window_ = 0;
};

TEST_F(InteractiveWindow, DraggingTheMouseRestartsTheAccumulation)
{
    writeScene(sceneText(kRed));
    start();
    const std::string before = waitForSamples(60);
    ASSERT_GE(samplesInTitle(before), 60) << "the render did not get going: " << before;
    drag(window_, 1, 80, 60, 40, 10);
    const std::string after = waitForRestartAfter(before);
    EXPECT_TRUE(showsRestart(before, after))
        << "a left drag orbits the camera, so the window must show a moving view and the "
           "accumulation start again; before the drag: \""
        << before << "\", 10 s after: \"" << after << "\"";
}

// Nothing pressed first: the window as a user meets it, at the size the README measures.
TEST_F(InteractiveWindow, ADragInAFreshWindowMovesTheCamera)
{
    writeScene(sceneText(kRed));
    start({}, false, "320", "240");
    const std::string before = waitForSamples(6);
    ASSERT_GE(samplesInTitle(before), 6) << "the render did not get going: " << before;
    drag(window_, 1, 150, 110, 60, 20);
    const std::string after = waitForRestartAfter(before);
    EXPECT_TRUE(showsRestart(before, after))
        << "a left drag in the middle of a fresh 320x240 window must orbit the camera (a "
           "moving view, then the accumulation restarted), not be taken by the statistics "
           "panel; before the drag: \""
        << before << "\", 10 s after: \"" << after << "\"";
}

TEST_F(InteractiveWindow, InputThatLeavesTheViewAloneKeepsTheAccumulation)
{
    writeScene(sceneText(kRed));
    start();
    const std::string before = waitForSamples(20);
    ASSERT_GE(samplesInTitle(before), 20) << before;
    // A mouse move without a button, the panel key and the preview denoiser's key (display
    // only) change nothing of the view.
    xdotool({"mousemove", "--window", std::to_string(window_), "20", "20"});
    xdotool({"mousemove", "--window", std::to_string(window_), "120", "90"});
    pressKey(window_, "Tab");
    pressKey(window_, "Tab");
    pressKey(window_, "n");
    std::this_thread::sleep_for(std::chrono::milliseconds(600));
    const std::string after = windowTitle(window_);
    EXPECT_GT(samplesInTitle(after), samplesInTitle(before))
        << "nothing changed the view, so the samples must go on adding up; before: \"" << before
        << "\", after: \"" << after << "\"";
}

TEST_F(InteractiveWindow, CtrlSWritesPngAndExrNamedAfterTheSceneAndGoesOn)
{
    writeScene(sceneText(kRed));
    start();
    ASSERT_GE(samplesInTitle(waitForSamples(4)), 4);
    pressKey(window_, "ctrl+s");
    const std::string saved = waitForTitleWith("saved");
    ASSERT_NE(saved.find("saved"), std::string::npos) << "the title never said it saved: " << saved;
    const int samples = samplesInTitle(saved);
    std::vector<fs::path> pictures;
    std::vector<fs::path> radiance;
    for (const fs::directory_entry& entry : fs::directory_iterator(folder_)) {
        const std::string name = entry.path().filename().string();
        if (name.rfind("scene-", 0) == 0 && entry.path().extension() == ".png")
            pictures.push_back(entry.path());
        if (name.rfind("scene-", 0) == 0 && entry.path().extension() == ".exr")
            radiance.push_back(entry.path());
    }
    ASSERT_EQ(pictures.size(), 1u) << "one PNG named scene-Nspp.png in the current folder";
    ASSERT_EQ(radiance.size(), 1u) << "one EXR named scene-Nspp.exr in the current folder";
    EXPECT_EQ(pictures[0].stem(), radiance[0].stem());
    EXPECT_NE(saved.find(pictures[0].filename().string()), std::string::npos)
        << "the title names the file written: " << saved;
    const io::Image picture = io::readImage(pictures[0]);
    const io::Image hdr = io::readImage(radiance[0]);
    EXPECT_EQ(picture.width, 160);
    EXPECT_EQ(picture.height, 120);
    EXPECT_EQ(hdr.width, 160);
    EXPECT_EQ(hdr.height, 120);
    EXPECT_GT(meanColour(hdr).red, 0.0) << "the EXR holds the radiance";

    const std::string later = waitForSamples(samples + 4);
    EXPECT_GE(samplesInTitle(later), samples + 4) << "saving must not stop the render: " << later;
    const ProcessResult result = close();
    EXPECT_TRUE(result.exited && result.exitStatus == 0) << result.describeEnd();
    EXPECT_NE(result.standardOutput.find(pictures[0].filename().string()), std::string::npos)
        << "the terminal names the files written: " << result.standardOutput;
}

TEST_F(InteractiveWindow, EditingAColourChangesThePictureWithoutARecompile)
{
    writeScene(sceneText(kRed));
    start();
    ASSERT_GE(samplesInTitle(waitForSamples(16)), 16);
    const ChannelMeans red = meanColour(captureWindow(window_));
    writeScene(sceneText(kBlue));
    const std::string reloaded = waitForTitleWith("reloaded");
    EXPECT_NE(reloaded.find("values only"), std::string::npos)
        << "a colour is a uniform: the reload must not rebuild the shader: " << reloaded;
    EXPECT_EQ(reloaded.find("rebuilt"), std::string::npos) << reloaded;
    // Samples of the new scene (the title's count restarted with the reload).
    std::this_thread::sleep_for(std::chrono::milliseconds(300));
    ASSERT_GE(samplesInTitle(waitForSamples(16)), 16);
    const ChannelMeans blue = meanColour(captureWindow(window_));
    EXPECT_LT(blue.red, red.red - 0.02) << "the sphere turned from red to blue";
    EXPECT_GT(blue.blue, red.blue + 0.02) << "the sphere turned from red to blue";
}

TEST_F(InteractiveWindow, TouchingOrSavingTheSceneUnchangedKeepsTheAccumulation)
{
    writeScene(sceneText(kRed));
    start();
    ASSERT_GE(samplesInTitle(waitForSamples(8)), 8);
    // Each change is left a second, four times the watcher's polling period.
    fs::last_write_time(folder_ / "scene.in",
                        fs::last_write_time(folder_ / "scene.in") + std::chrono::seconds(5));
    std::string title = firstRestartWithin(1.0);
    EXPECT_EQ(title.find("reloaded"), std::string::npos) << "touched: " << title;
    EXPECT_GE(samplesInTitle(title), 8) << "touched: the accumulation restarted: " << title;
    writeScene(sceneText(kRed));
    title = firstRestartWithin(1.0);
    EXPECT_EQ(title.find("reloaded"), std::string::npos) << "saved unchanged: " << title;
    EXPECT_GE(samplesInTitle(title), 8) << "saved unchanged: the accumulation restarted: " << title;
    // Another file, the same scene: read, found to change nothing, and said so.
    writeScene("# a comment\n" + sceneText(kRed));
    const std::string commented = waitForTitleWith("changes nothing", 5.0);
    EXPECT_NE(commented.find("changes nothing"), std::string::npos) << commented;
    EXPECT_GE(samplesInTitle(commented), 8) << "a comment added: " << commented;
}

TEST_F(InteractiveWindow, ASyntaxErrorKeepsTheWindowAndShowsWhere)
{
    writeScene(sceneText(kRed));
    start();
    ASSERT_GE(samplesInTitle(waitForSamples(8)), 8);
    writeScene(sceneText(kRed, "", 0, "spherr"));
    const std::string broken = waitForTitleWith("error");
    EXPECT_NE(broken.find("scene.in:13"), std::string::npos)
        << "the title names the file and line of the error: " << broken;
    EXPECT_NE(broken.find("spherr"), std::string::npos) << broken;
    // The last good scene goes on converging.
    const std::string later = waitForSamples(samplesInTitle(broken) + 8);
    EXPECT_GT(samplesInTitle(later), samplesInTitle(broken)) << later;
    EXPECT_TRUE(running()) << "a broken edit must never end the program";
    // Mended, it loads again.
    writeScene(sceneText(kBlue));
    const std::string mended = waitForTitleWith("reloaded");
    EXPECT_NE(mended.find("reloaded"), std::string::npos) << mended;
    const ProcessResult result = close();
    EXPECT_TRUE(result.exited && result.exitStatus == 0) << result.describeEnd();
    EXPECT_NE(result.standardError.find("scene.in:13"), std::string::npos)
        << "the terminal shows the error too: " << result.standardError;
}

TEST_F(InteractiveWindow, AStructuralEditRebuildsTheShader)
{
    writeScene(sceneText(kRed));
    start();
    ASSERT_GE(samplesInTitle(waitForSamples(16)), 16);
    const ChannelMeans before = meanColour(captureWindow(window_));
    // A red box beside the sphere: a new kind of shape is new code.
    writeScene(sceneText(kRed, "0 0 box 1.1 0.3 0.4  0.3 0.3 0.3\n", 1));
    const std::string reloaded = waitForTitleWith("reloaded");
    EXPECT_NE(reloaded.find("structure changed, shader rebuilt"), std::string::npos) << reloaded;
    std::this_thread::sleep_for(std::chrono::milliseconds(300));
    ASSERT_GE(samplesInTitle(waitForSamples(16)), 16);
    const ChannelMeans after = meanColour(captureWindow(window_));
    const double change = std::abs(after.red - before.red) + std::abs(after.green - before.green) +
                          std::abs(after.blue - before.blue);
    EXPECT_GT(change, 0.01) << "the box must appear in the picture";
}

TEST_F(InteractiveWindow, ResizingRendersAtTheNewSize)
{
    writeScene(sceneText(kRed));
    start();
    ASSERT_GE(samplesInTitle(waitForSamples(2)), 2);
    xdotool({"windowsize", std::to_string(window_), "200", "100"});
    const std::string resized = waitForTitleWith("200x100");
    EXPECT_NE(resized.find("200x100"), std::string::npos)
        << "the image is rendered at the window's new size, so its aspect stays right: " << resized;
}

// How deep `point` lies in the scene's polyhedra (its walls, floor and ceiling): the most of
// any plane's distance into a solid, 0 when outside every one.
float depthInWalls(const scene::Scene& scene, const glm::vec3& point)
{
    float deepest = 0.0f;
    for (const scene::SceneObject& object : scene.objects)
        if (const auto* polyhedron = std::get_if<scene::Polyhedron>(&object.shape.geometry))
            for (const glm::vec4& plane : polyhedron->planes)
                deepest = std::max(deepest, -(glm::dot(glm::vec3(plane), point) + plane.w) /
                                                glm::length(glm::vec3(plane)));
    return deepest;
}

// scene1's look-at point lies behind its back wall: an orbit about it took the eye into a
// wall. A quarter turn must keep the eye in the room (the camera the C key writes, read
// back), and the picture about as bright.
TEST_F(InteractiveWindow, AQuarterTurnOrbitInScene1KeepsThePicture)
{
    writeScene(readText(scene1Path()));
    start();
    ASSERT_GE(samplesInTitle(waitForSamples(4, 40.0)), 4) << windowTitle(window_);
    const ChannelMeans before = meanColour(captureWindow(window_));
    const std::string titleBefore = windowTitle(window_);
    // A drag half the window's height (120 pixels) to the right: a quarter of a turn.
    drag(window_, 1, 50, 60, 60, 0, 6);
    const std::string moved = waitForRestartAfter(titleBefore);
    ASSERT_TRUE(showsRestart(titleBefore, moved)) << "the drag did not move the camera: " << moved;
    std::this_thread::sleep_for(std::chrono::milliseconds(500));
    ASSERT_GE(samplesInTitle(waitForSamples(4, 40.0)), 4) << windowTitle(window_);
    const ChannelMeans after = meanColour(captureWindow(window_));
    const double brightnessBefore = before.red + before.green + before.blue;
    const double brightnessAfter = after.red + after.green + after.blue;
    std::cout << "mean brightness before the orbit " << brightnessBefore << ", after "
              << brightnessAfter << std::endl;
    EXPECT_GT(brightnessAfter, 0.5 * brightnessBefore)
        << "the picture's mean fell from " << brightnessBefore << " to " << brightnessAfter;
    EXPECT_LT(brightnessAfter, 2.0 * brightnessBefore)
        << "the picture's mean rose from " << brightnessBefore << " to " << brightnessAfter;

    const std::optional<scene::Camera> camera = writtenCamera();
    ASSERT_TRUE(camera.has_value());
    const std::string cameraText = readText(folder_ / "scene.camera");
    // Its eye must be in the room.
    const scene::Scene original = readScene1();
    EXPECT_EQ(depthInWalls(original, camera->eye), 0.0f)
        << "the eye went into a wall: " << cameraText;
    const scene::SceneBounds bounds = scene::computeSceneBounds(original);
    EXPECT_LE(glm::length(camera->eye - bounds.center), bounds.radius)
        << "the eye left the scene: " << cameraText;

    // The summary gives the accumulation on screen (restarted by the drag) and, apart, the
    // time the window was open.
    const ProcessResult result = close();
    const std::string& out = result.standardOutput;
    const std::size_t in = out.find(" spp in ");
    const std::size_t open = out.find("window open ");
    ASSERT_TRUE(in != std::string::npos && open != std::string::npos) << out;
    const double accumulationSeconds = std::stod(out.substr(in + 8));
    const double windowSeconds = std::stod(out.substr(open + 12));
    EXPECT_LT(accumulationSeconds, windowSeconds - 0.1)
        << "the accumulation restarted after the drag, 0.15 s after it at the earliest: " << out;
}

// Ten wheel steps towards the view's centre in scene1: the eye comes near the front sphere
// under it (the pivot) and never passes it; the look-at point, behind the back wall, is not
// what it dollies towards.
TEST_F(InteractiveWindow, TenWheelStepsInScene1NeverPassThePivot)
{
    writeScene(readText(scene1Path()));
    start();
    ASSERT_GE(samplesInTitle(waitForSamples(2, 40.0)), 2) << windowTitle(window_);
    for (int step = 0; step < 10; ++step) {
        xdotool({"mousemove", "--window", std::to_string(window_), "80", "60"});
        xdotool({"click", "--window", std::to_string(window_), "4"});
        std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(500));
    const std::optional<scene::Camera> camera = writtenCamera();
    ASSERT_TRUE(camera.has_value());
    // Where the file's view centre meets the front sphere (centre (1 0 1), radius 1).
    const scene::Camera home = readScene1().camera;
    const glm::vec3 forward = glm::normalize(home.target - home.eye);
    const glm::vec3 offset = home.eye - glm::vec3(1.0f, 0.0f, 1.0f);
    const float b = glm::dot(offset, forward);
    const glm::vec3 pivot =
        home.eye + (-b - std::sqrt(b * b - glm::dot(offset, offset) + 1.0f)) * forward;
    const float startDistance = glm::length(pivot - home.eye);
    const float left = glm::dot(pivot - camera->eye, forward);
    EXPECT_GT(left, 0.0f) << "the eye passed the front sphere's surface by " << -left;
    EXPECT_LT(left, 0.5f * startDistance) << "ten steps should have come much nearer";
    EXPECT_GT(glm::length(camera->eye - glm::vec3(1.0f, 0.0f, 1.0f)), 1.0f)
        << "the eye is in the front sphere";
}

// C writes the camera as a scene file's camera line, to the terminal and to scene.camera.
TEST_F(InteractiveWindow, CWritesTheCameraAsASceneFileLine)
{
    writeScene(sceneText(kRed));
    start();
    ASSERT_GE(samplesInTitle(waitForSamples(2)), 2);
    drag(window_, 1, 80, 60, 30, 0);
    pressKey(window_, "c");
    const std::string written = waitForTitleWith("camera line");
    ASSERT_NE(written.find("scene.camera"), std::string::npos) << written;
    std::ifstream file(folder_ / "scene.camera");
    std::string comment;
    std::string line;
    std::getline(file, comment);
    std::getline(file, line);
    EXPECT_EQ(comment.rfind("# ", 0), 0u) << comment;
    std::istringstream numbers(line);
    int count = 0;
    for (double value = 0.0; numbers >> value;)
        ++count;
    EXPECT_EQ(count, 10) << "eye, look-at point, up and field of view: " << line;
    EXPECT_NE(line.find("  45"), std::string::npos) << "the field of view is kept: " << line;
    const ProcessResult result = close();
    EXPECT_NE(result.standardOutput.find(line + "\n"), std::string::npos)
        << "the terminal shows the line on its own: " << result.standardOutput;
}

TEST_F(InteractiveWindow, ClosingBeforeTheSamplesAskedForIsAnInterruptedRender)
{
    writeScene(sceneText(kRed));
    start({"--spp", "100000", "--output", "out.png"});
    ASSERT_GE(samplesInTitle(waitForSamples(2)), 2);
    const ProcessResult result = close();
    EXPECT_TRUE(result.exited && result.exitStatus == 130)
        << "like Ctrl-C: " << result.describeEnd() << "\n"
        << result.standardOutput;
    EXPECT_NE(result.standardOutput.find("(interrupted)"), std::string::npos)
        << result.standardOutput;
    EXPECT_TRUE(fs::exists(folder_ / "out.png")) << "what was rendered is still written";
}

}  // namespace
}  // namespace window_tests
