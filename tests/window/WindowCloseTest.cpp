// A window run with --spp N that the user closes (Escape) before N samples is an interrupted
// render: it writes what it has, marks the file so, says so, and exits 130.
#include "io/ImageFile.h"
#include "support/ChildProcess.h"
#include "support/TestPaths.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cstdlib>
#include <thread>
#include <unistd.h>

namespace window_tests {
namespace {

using namespace testing_support;
namespace fs = std::filesystem;

// Presses Escape in the program's window (xdotool, as a keyboard would) as soon as its title
// shows a first sample done: "raytracer - scene3.in - 1 spp, ...".
void pressEscapeInTheWindowWhenItOpens(const fs::path& folder)
{
    ProcessOptions options;
    options.workingDirectory = folder;
    options.timeoutSeconds = 20.0;
    const auto start = std::chrono::steady_clock::now();
    while (std::chrono::steady_clock::now() - start < std::chrono::seconds(60)) {
        const ProcessResult found =
            runProcess({"/bin/sh", "-c",
                        "xdotool search --name '^raytracer - .* [1-9][0-9]* spp' | head -n 1"},
                       options);
        const std::string window =
            found.standardOutput.substr(0, found.standardOutput.find_first_of("\r\n"));
        if (!window.empty()) {
            runProcess({"/bin/sh", "-c",
                        "xdotool windowfocus --sync " + window + " mousemove --window " + window +
                            " 8 8 key Escape"},
                       options);
            return;
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(200));
    }
}

TEST(WindowClosedEarly, IsAnInterruptedRenderWithItsFileMarked)
{
    ASSERT_NE(std::getenv("DISPLAY"), nullptr)
        << "run this test through run-under-xvfb.sh, which provides a display";
    if (std::system("command -v xdotool >/dev/null 2>&1") != 0)
        GTEST_SKIP() << "xdotool is not installed (Debian package xdotool): no key can be sent";
    const fs::path folder =
        fs::temp_directory_path() / ("raytracer-window-close-" + std::to_string(::getpid()));
    fs::create_directories(folder);
    const std::string scene = (sourceDirectory() / "scenes" / "scene3.in").string();
    ProcessOptions options;
    options.workingDirectory = folder;
    options.timeoutSeconds = 90.0;

    std::thread escape(pressEscapeInTheWindowWhenItOpens, folder);
    const ProcessResult result =
        runProcess({RAYTRACER_EXECUTABLE, scene, "64", "48", "--spp", "16777216",
                    "--samples-per-frame", "1", "--output", "closed.exr"},
                   options);
    escape.join();
    const std::string shown = result.describeEnd() + "\n--- stdout:\n" + result.standardOutput +
                              "--- stderr:\n" + result.standardError;
    ASSERT_TRUE(result.exited) << shown;
    EXPECT_EQ(result.exitStatus, 130) << shown;
    EXPECT_NE(result.standardOutput.find("(interrupted)"), std::string::npos) << shown;
    ASSERT_TRUE(fs::exists(folder / "closed.exr")) << shown;
    const auto mark = io::readImageAttribute(folder / "closed.exr", "raytracer:interrupted");
    fs::remove_all(folder);
    ASSERT_TRUE(mark.has_value()) << "the file should say it was interrupted";
    EXPECT_NE(mark->find("of 16777216 samples per pixel"), std::string::npos) << *mark;
}

}  // namespace
}  // namespace window_tests
