// The window path: under a virtual X server (run-under-xvfb.sh), the program opens a GLFW
// window, renders a fixed number of samples with a fixed seed and writes the picture it read
// back from the window's framebuffer. The same render headless (OSMesa) must give the same
// picture: one renderer, two contexts.
#include "io/ImageFile.h"
#include "support/ChildProcess.h"
#include "support/TestPaths.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <unistd.h>

namespace window_tests {
namespace {

using namespace testing_support;
namespace fs = std::filesystem;

TEST(WindowPicture, MatchesTheHeadlessPictureOfTheSameSeed)
{
    ASSERT_NE(std::getenv("DISPLAY"), nullptr)
        << "run this test through run-under-xvfb.sh, which provides a display";
    const fs::path folder =
        fs::temp_directory_path() / ("raytracer-window-" + std::to_string(::getpid()));
    fs::create_directories(folder);
    const std::string scene = (sourceDirectory() / "scenes" / "scene3.in").string();
    ProcessOptions options;
    options.workingDirectory = folder;

    const ProcessResult window = runProcess({RAYTRACER_EXECUTABLE, scene, "64", "48", "--spp", "8",
                                             "--seed", "3", "--output", "window.png"},
                                            options);
    ASSERT_TRUE(window.exited && window.exitStatus == 0)
        << "the window render failed: " << window.describeEnd() << "\n"
        << window.standardError;
    const ProcessResult headless =
        runProcess({RAYTRACER_EXECUTABLE, scene, "64", "48", "--spp", "8", "--seed", "3",
                    "--output", "headless.png", "--headless"},
                   options);
    ASSERT_TRUE(headless.exited && headless.exitStatus == 0)
        << "the headless render failed: " << headless.describeEnd() << "\n"
        << headless.standardError;

    const io::Image fromWindow = io::readImage(folder / "window.png");
    const io::Image fromOsMesa = io::readImage(folder / "headless.png");
    fs::remove_all(folder);
    ASSERT_EQ(fromWindow.width, 64);
    ASSERT_EQ(fromWindow.height, 48);
    ASSERT_EQ(fromOsMesa.width, fromWindow.width);
    ASSERT_EQ(fromOsMesa.height, fromWindow.height);
    ASSERT_EQ(fromOsMesa.channels, fromWindow.channels);
    double largest = 0.0;
    std::size_t where = 0;
    for (std::size_t i = 0; i < fromWindow.pixels.size(); ++i) {
        const double difference = std::abs(fromWindow.pixels[i] - fromOsMesa.pixels[i]);
        if (difference > largest) {
            largest = difference;
            where = i;
        }
    }
    const int pixel = static_cast<int>(where / fromWindow.channels);
    EXPECT_LE(largest * 255.0, 1.0 + 1e-3)
        << "the window's picture and the headless picture should be identical (at most 1/255 "
        << "apart per channel); they differ by " << largest * 255.0 << "/255 at pixel ("
        << pixel % fromWindow.width << ", " << pixel / fromWindow.width << ")";
}

// A window given --target-error ends once the estimate gets there, sampling every pixel
// alike, and its summary says so, before the time limit.
TEST(WindowTargetError, EndsAtTheTargetAndSaysSo)
{
    ASSERT_NE(std::getenv("DISPLAY"), nullptr)
        << "run this test through run-under-xvfb.sh, which provides a display";
    const fs::path folder =
        fs::temp_directory_path() / ("raytracer-window-target-" + std::to_string(::getpid()));
    fs::create_directories(folder);
    const std::string scene = (sourceDirectory() / "scenes" / "scene5.in").string();
    ProcessOptions options;
    options.workingDirectory = folder;
    const ProcessResult window = runProcess({RAYTRACER_EXECUTABLE, scene, "64", "48", "60",
                                             "--target-error", "0.1", "--output", "window.png"},
                                            options);
    fs::remove_all(folder);
    ASSERT_TRUE(window.exited && window.exitStatus == 0) << window.describeEnd() << "\n"
                                                         << window.standardError;
    EXPECT_NE(window.standardOutput.find("(target 10 %, uniform sampling: reached)"),
              std::string::npos)
        << window.standardOutput;
}

}  // namespace
}  // namespace window_tests
