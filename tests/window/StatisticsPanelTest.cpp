// The statistics panel (interaction/StatisticsPanel.h) in a real 320x240 GLFW window under a
// virtual X server (run-under-xvfb.sh): every part of it can be reached. The panel stays
// inside the window, and the mouse wheel over it, sent through xdotool as a user's would be,
// scrolls it down until its last item shows and back up until its first does. The panel's
// items and scroll are read from what its last draw laid out (StatisticsPanel::layout).
#include "interaction/StatisticsPanel.h"
#include "interaction/ConvergenceHistory.h"
#include "platform/GlfwWindowContext.h"

#include "window/WindowDriver.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <string>

namespace window_tests {
namespace {

constexpr int kWidth = 320;
constexpr int kHeight = 240;
const char* const kTitle = "statistics panel at 320x240";

void printLayout(const char* when, const interaction::PanelLayout& layout)
{
    std::printf(
        "%s: panel (%.0f, %.0f)-(%.0f, %.0f) in %.0fx%.0f, items show in y %.0f to %.0f; "
        "first item's top %.0f, last item's bottom %.0f; scroll %.0f of %.0f; items end at x %.0f, "
        "show to %.0f, scroll %.0f of %.0f\n",
        when, layout.left, layout.top, layout.right, layout.bottom, layout.displayWidth,
        layout.displayHeight, layout.visibleTop, layout.visibleBottom, layout.firstItemTop,
        layout.lastItemBottom, layout.scrollY, layout.scrollMaxY, layout.contentRight,
        layout.visibleRight, layout.scrollX, layout.scrollMaxX);
}

TEST(StatisticsPanelWindow, EveryPartIsReachableAt320x240)
{
    ASSERT_NE(std::getenv("DISPLAY"), nullptr)
        << "run this test through run-under-xvfb.sh, which provides a display";
    platform::GlfwWindowContext window(kWidth, kHeight, kTitle);
    interaction::StatisticsPanel panel(window.glfwWindow());
    panel.toggle();

    // Every part the panel can show: the plot, a target, a long error status and the
    // features of a rich scene.
    interaction::ConvergenceHistory history;
    for (int i = 1; i <= 20; ++i)
        history.add(i, 0.5f / i);
    interaction::PanelReadings readings;
    readings.width = kWidth;
    readings.height = kHeight;
    readings.samplesPerPixel = 64;
    readings.samplesPerSecond = 12.5;
    readings.elapsedSeconds = 5.1;
    readings.relativeError = 0.031;
    readings.targetError = 0.01;
    readings.secondsToTarget = 42.0;
    readings.history = &history;
    readings.features = "shapes: sphere, box, cylinder, torus, polyhedron\n"
                        "materials: lambertian, mirror, dielectric, rough conductor\n"
                        "textures: checker, image (triplanar)\nlights: point, sphere\n"
                        "environment: sky\nCSG: union, smooth union";
    readings.status = "scene.in:12: expected a number for the sphere's radius, found 'x'; "
                      "the picture is the last scene that was read";
    readings.statusIsError = true;
    interaction::PanelSettings settings;
    const auto frame = [&] {
        window.closeRequested();  // reads the window's events
        settings = panel.draw(readings, settings);
        window.present();
    };
    for (int i = 0; i < 5; ++i)
        frame();
    const interaction::PanelLayout start = panel.layout();
    printLayout("shown", start);
    ASSERT_TRUE(start.shown);
    EXPECT_EQ(start.displayWidth, kWidth);
    EXPECT_EQ(start.displayHeight, kHeight);
    EXPECT_GE(start.left, 0.0f);
    EXPECT_GE(start.top, 0.0f);
    EXPECT_LE(start.right, kWidth) << "the panel and its scroll bar must be inside the window";
    EXPECT_LE(start.bottom, kHeight) << "the panel and its scroll bar must be inside the window";
    EXPECT_GE(start.firstItemTop, start.visibleTop) << "the first item shows at first";
    ASSERT_GT(start.lastItemBottom, start.visibleBottom)
        << "the panel fits the window: this test would not test its scrolling";

    // The wheel over the panel, as a user turns it: down until the panel stops scrolling.
    const std::optional<unsigned long> id = findWindow(kTitle, 10.0);
    ASSERT_TRUE(id.has_value()) << "the window is not found by its title";
    const std::string windowId = std::to_string(*id);
    xdotool({"windowfocus", "--sync", windowId});
    xdotool({"mousemove", "--window", windowId, "60", std::to_string(kHeight / 2)});
    frame();
    const auto turnWheel = [&](const char* button, int clicks) {
        for (int i = 0; i < clicks; ++i) {
            xdotool({"click", "--window", windowId, button});
            frame();
        }
        for (int i = 0; i < 3; ++i)
            frame();
    };
    turnWheel("5", 30);
    const interaction::PanelLayout down = panel.layout();
    printLayout("wheel down", down);
    EXPECT_GT(down.scrollY, 0.0f) << "the wheel over the panel must scroll it";
    EXPECT_EQ(down.scrollY, down.scrollMaxY);
    EXPECT_LE(down.lastItemBottom, down.visibleBottom + 0.5f)
        << "scrolled to the end, the panel's last item must show";
    EXPECT_LE(down.bottom, kHeight);

    // Lines wider than the panel: the horizontal wheel (buttons 6 and 7) brings their ends in.
    if (down.contentRight > down.visibleRight + 0.5f) {
        turnWheel("7", 30);
        const interaction::PanelLayout right = panel.layout();
        printLayout("wheel right", right);
        EXPECT_LE(right.contentRight, right.visibleRight + 0.5f)
            << "scrolled right, the ends of the widest lines must show";
        turnWheel("6", 30);
    }

    turnWheel("4", 30);
    const interaction::PanelLayout up = panel.layout();
    printLayout("wheel up", up);
    EXPECT_EQ(up.scrollY, 0.0f);
    EXPECT_EQ(up.scrollX, 0.0f);
    EXPECT_GE(up.firstItemTop, up.visibleTop) << "scrolled back, the first item shows again";
}

}  // namespace
}  // namespace window_tests
