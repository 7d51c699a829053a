// window_capture TITLE-PREFIX OUTPUT.png: writes the pixels of the first window whose title
// starts with TITLE-PREFIX as the X server holds them (for the README's screenshot of the
// window, tools/window-screenshot.sh).
#include "io/ImageFile.h"
#include "window/WindowDriver.h"

#include <exception>
#include <iostream>

int main(int argc, char** argv)
{
    if (argc != 3) {
        std::cerr << "usage: window_capture TITLE-PREFIX OUTPUT.png\n";
        return 2;
    }
    try {
        const std::optional<unsigned long> window = window_tests::findWindow(argv[1], 10.0);
        if (!window) {
            std::cerr << "window_capture: no window titled '" << argv[1] << "...'\n";
            return 1;
        }
        io::writeImage(argv[2], window_tests::captureWindow(*window));
    } catch (const std::exception& error) {
        std::cerr << "window_capture: " << error.what() << "\n";
        return 1;
    }
    return 0;
}
