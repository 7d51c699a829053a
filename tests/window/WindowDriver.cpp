#include "window/WindowDriver.h"

#include "support/ChildProcess.h"

#include <X11/Xlib.h>
#include <X11/Xutil.h>

#include <memory>
#include <regex>
#include <stdexcept>
#include <thread>

namespace window_tests {

using namespace testing_support;

namespace {

ProcessResult runXdotool(const std::vector<std::string>& arguments)
{
    std::vector<std::string> command = {"/usr/bin/xdotool"};
    command.insert(command.end(), arguments.begin(), arguments.end());
    ProcessOptions options;
    options.timeoutSeconds = 20.0;
    return runProcess(command, options);
}

// The lowest set bit of a colour mask, and the mask's width: where a channel sits in a pixel.
int shiftOf(unsigned long mask)
{
    int shift = 0;
    while (mask != 0 && (mask & 1ul) == 0) {
        mask >>= 1;
        ++shift;
    }
    return shift;
}

}  // namespace

void xdotool(const std::vector<std::string>& arguments)
{
    const ProcessResult result = runXdotool(arguments);
    if (!result.exited || result.exitStatus != 0) {
        std::string command;
        for (const std::string& argument : arguments)
            command += " " + argument;
        throw std::runtime_error("xdotool" + command + " failed: " + result.describeEnd() + ": " +
                                 result.standardError);
    }
}

std::optional<unsigned long> findWindow(const std::string& titlePrefix, double seconds)
{
    const auto start = std::chrono::steady_clock::now();
    do {
        const ProcessResult result = runXdotool({"search", "--name", "^" + titlePrefix});
        const std::vector<std::string> lines = nonEmptyLines(result.standardOutput);
        if (result.exited && result.exitStatus == 0 && !lines.empty())
            return std::stoul(lines.front());
        std::this_thread::sleep_for(std::chrono::milliseconds(100));
    } while (std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() <
             seconds);
    return std::nullopt;
}

std::string windowTitle(unsigned long window)
{
    const ProcessResult result = runXdotool({"getwindowname", std::to_string(window)});
    std::string title = result.standardOutput;
    while (!title.empty() && (title.back() == '\n' || title.back() == '\r'))
        title.pop_back();
    return title;
}

std::string waitForTitle(unsigned long window,
                         const std::function<bool(const std::string&)>& accept, double seconds)
{
    const auto start = std::chrono::steady_clock::now();
    std::string title = windowTitle(window);
    while (!accept(title) &&
           std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() <
               seconds) {
        std::this_thread::sleep_for(std::chrono::milliseconds(50));
        title = windowTitle(window);
    }
    return title;
}

int samplesInTitle(const std::string& title)
{
    static const std::regex samples(R"( (\d+) spp,)");
    std::smatch match;
    if (!std::regex_search(title, match, samples))
        return -1;
    return std::stoi(match[1]);
}

void pressKey(unsigned long window, const std::string& keys)
{
    xdotool({"key", "--window", std::to_string(window), keys});
}

void pressEscapeToClose(unsigned long window)
{
    xdotool({"keydown", "--window", std::to_string(window), "Escape"});
}

void drag(unsigned long window, int button, int x, int y, int dx, int dy, int steps)
{
    const std::string id = std::to_string(window);
    xdotool({"mousemove", "--window", id, std::to_string(x), std::to_string(y)});
    xdotool({"mousedown", std::to_string(button)});
    for (int step = 1; step <= steps; ++step) {
        std::this_thread::sleep_for(std::chrono::milliseconds(30));
        xdotool({"mousemove", "--window", id, std::to_string(x + dx * step / steps),
                 std::to_string(y + dy * step / steps)});
    }
    xdotool({"mouseup", std::to_string(button)});
}

io::Image captureWindow(unsigned long window)
{
    const std::unique_ptr<Display, int (*)(Display*)> display(XOpenDisplay(nullptr),
                                                              &XCloseDisplay);
    if (!display)
        throw std::runtime_error("cannot open the X display");
    XWindowAttributes attributes{};
    if (XGetWindowAttributes(display.get(), window, &attributes) == 0)
        throw std::runtime_error("no such window");
    // XDestroyImage is a macro, not a function to point at.
    auto destroyImage = [](XImage* image) { XDestroyImage(image); };
    const std::unique_ptr<XImage, decltype(destroyImage)> picture(
        XGetImage(display.get(), window, 0, 0, static_cast<unsigned>(attributes.width),
                  static_cast<unsigned>(attributes.height), AllPlanes, ZPixmap),
        destroyImage);
    if (!picture)
        throw std::runtime_error("cannot read the window's pixels");
    const unsigned long masks[3] = {picture->red_mask, picture->green_mask, picture->blue_mask};
    io::Image image(attributes.width, attributes.height, 3);
    for (int y = 0; y < attributes.height; ++y)
        for (int x = 0; x < attributes.width; ++x) {
            const unsigned long pixel = XGetPixel(picture.get(), x, y);
            for (int c = 0; c < 3; ++c) {
                const unsigned long maximum = masks[c] >> shiftOf(masks[c]);
                image.at(x, y, c) = static_cast<float>(((pixel & masks[c]) >> shiftOf(masks[c]))) /
                                    static_cast<float>(maximum);
            }
        }
    return image;
}

ChannelMeans meanColour(const io::Image& image)
{
    ChannelMeans means;
    const double pixels = static_cast<double>(image.width) * image.height;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            means.red += image.at(x, y, 0) / pixels;
            means.green += image.at(x, y, 1) / pixels;
            means.blue += image.at(x, y, 2) / pixels;
        }
    return means;
}

}  // namespace window_tests
