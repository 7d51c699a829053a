#pragma once
#include <glm/glm.hpp>

#include <array>
#include <vector>

namespace platform {

enum class MouseButton { Left, Right, Middle };
constexpr int kMouseButtonCount = 3;

// The keys the window answers to (Escape closes it by itself).
enum class Key { W, A, S, D, Q, E, R, Tab, C };
constexpr int kKeyCount = 9;

struct KeyPress {
    Key key;
    bool control = false;  // Ctrl was held
};

// What the user did in a window between two GlfwWindowContext::takeInput calls, in window
// coordinates (pixels, y down), and which keys are held at the second.
struct WindowInput {
    // How far the cursor moved while each button was down.
    std::array<glm::vec2, kMouseButtonCount> drag{};
    // Each button that went down since the last call.
    std::array<bool, kMouseButtonCount> pressed{};
    // Whether each button is down now.
    std::array<bool, kMouseButtonCount> down{};
    float wheelSteps = 0.0f;  // up (away from the user) positive
    std::vector<KeyPress> keyPresses;
    std::array<bool, kKeyCount> keyHeld{};
    bool shiftHeld = false;
    bool controlHeld = false;

    glm::vec2 dragOf(MouseButton button) const { return drag[static_cast<int>(button)]; }
    bool isDown(MouseButton button) const { return down[static_cast<int>(button)]; }
    bool held(Key key) const { return keyHeld[static_cast<int>(key)]; }
};

}  // namespace platform
