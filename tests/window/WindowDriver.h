#pragma once
// Driving the program's window as a user would, under a virtual X server: synthetic input
// through xdotool, and what the window shows read back from the X server (its title, its
// pixels), never from anything the test itself wrote.
#include "io/Image.h"

#include <chrono>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace window_tests {

// The first window whose title starts with `titlePrefix`, waited for up to `seconds`.
std::optional<unsigned long> findWindow(const std::string& titlePrefix, double seconds);

std::string windowTitle(unsigned long window);

// Waits up to `seconds` for the title to satisfy `accept`; returns the last title read
// either way (the caller checks it with `accept` again for its message).
std::string waitForTitle(unsigned long window,
                         const std::function<bool(const std::string&)>& accept, double seconds);

// The samples per pixel the title gives ("... - 42 spp, ..."), or -1.
int samplesInTitle(const std::string& title);

// Runs xdotool with these arguments; throws when it fails.
void xdotool(const std::vector<std::string>& arguments);

// Presses and releases keys in the window ("Tab", "ctrl+s").
void pressKey(unsigned long window, const std::string& keys);

// Presses Escape, which closes the window, and sends no release: the program closes on the
// press, so a release could meet a window already destroyed, which xdotool reports as a
// failure (BadWindow) though the window closed as asked.
void pressEscapeToClose(unsigned long window);

// Moves the pointer to (x, y) in the window, holds `button` (1 left, 2 middle, 3 right), moves
// it by (dx, dy) in `steps` steps and releases it.
void drag(unsigned long window, int button, int x, int y, int dx, int dy, int steps = 6);

// The window's pixels as the X server holds them (RGB in [0, 1], top row first).
io::Image captureWindow(unsigned long window);

// Mean of each channel over the picture.
struct ChannelMeans {
    double red = 0.0;
    double green = 0.0;
    double blue = 0.0;
};
ChannelMeans meanColour(const io::Image& image);

}  // namespace window_tests
