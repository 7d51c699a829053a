#include "platform/GlfwWindowContext.h"

#include "gl/EntryPoints.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <optional>
#include <stdexcept>
#include <string>

namespace platform {

namespace {

std::string lastGlfwError;

void recordGlfwError(int, const char* description)
{
    lastGlfwError = description != nullptr ? description : "unknown GLFW error";
}

void* glfwLoader(const char* name)
{
    return reinterpret_cast<void*>(glfwGetProcAddress(name));
}

// GLFW's key codes name physical keys by their place on a US keyboard.
std::optional<Key> keyOf(int glfwKey)
{
    switch (glfwKey) {
    case GLFW_KEY_W:
        return Key::W;
    case GLFW_KEY_A:
        return Key::A;
    case GLFW_KEY_S:
        return Key::S;
    case GLFW_KEY_D:
        return Key::D;
    case GLFW_KEY_Q:
        return Key::Q;
    case GLFW_KEY_E:
        return Key::E;
    case GLFW_KEY_R:
        return Key::R;
    case GLFW_KEY_TAB:
        return Key::Tab;
    case GLFW_KEY_C:
        return Key::C;
    case GLFW_KEY_N:
        return Key::N;
    default:
        return std::nullopt;
    }
}

std::optional<int> buttonIndex(int glfwButton)
{
    switch (glfwButton) {
    case GLFW_MOUSE_BUTTON_LEFT:
        return static_cast<int>(MouseButton::Left);
    case GLFW_MOUSE_BUTTON_RIGHT:
        return static_cast<int>(MouseButton::Right);
    case GLFW_MOUSE_BUTTON_MIDDLE:
        return static_cast<int>(MouseButton::Middle);
    default:
        return std::nullopt;
    }
}

GlfwWindowContext& contextOf(GLFWwindow* window)
{
    return *static_cast<GlfwWindowContext*>(glfwGetWindowUserPointer(window));
}

}  // namespace

GlfwWindowContext::GlfwWindowContext(int width, int height, const std::string& title)
{
    glfwSetErrorCallback(&recordGlfwError);
    if (!glfwInit())
        throw std::runtime_error("cannot open a window: " + lastGlfwError +
                                 " (use --headless to render without a display)");

    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
    glfwWindowHint(GLFW_RESIZABLE, GLFW_TRUE);
    window_ = glfwCreateWindow(width, height, title.c_str(), nullptr, nullptr);
    if (window_ == nullptr) {
        glfwTerminate();
        throw std::runtime_error("cannot open an OpenGL 3.3 core window: " + lastGlfwError);
    }
    glfwMakeContextCurrent(window_);
    glfwSetWindowUserPointer(window_, this);
    glfwSetKeyCallback(window_, &GlfwWindowContext::onKey);
    glfwSetMouseButtonCallback(window_, &GlfwWindowContext::onMouseButton);
    glfwSetCursorPosCallback(window_, &GlfwWindowContext::onCursorMove);
    glfwSetScrollCallback(window_, &GlfwWindowContext::onScroll);
    try {
        gl::loadEntryPoints(&glfwLoader, /*contextHasGlx=*/true);
        requireGl33();
    } catch (...) {
        glfwDestroyWindow(window_);
        glfwTerminate();
        throw;
    }
    // Frames are paced by the renderer, not by the display's refresh.
    glfwSwapInterval(0);
    identity_ = identifyCurrentContext("GLFW window");
}

GlfwWindowContext::~GlfwWindowContext()
{
    glfwDestroyWindow(window_);
    glfwTerminate();
}

DrawableSize GlfwWindowContext::windowFramebufferSize() const
{
    DrawableSize size;
    glfwGetFramebufferSize(window_, &size.width, &size.height);
    return size;
}

void GlfwWindowContext::present()
{
    glfwSwapBuffers(window_);
}

bool GlfwWindowContext::closeRequested()
{
    glfwPollEvents();
    return glfwWindowShouldClose(window_) != 0;
}

void GlfwWindowContext::setTitle(const std::string& title)
{
    glfwSetWindowTitle(window_, title.c_str());
}

DrawableSize GlfwWindowContext::windowSize() const
{
    DrawableSize size;
    glfwGetWindowSize(window_, &size.width, &size.height);
    return size;
}

void GlfwWindowContext::waitForInput(double seconds)
{
    glfwWaitEventsTimeout(seconds);
}

WindowInput GlfwWindowContext::takeInput()
{
    WindowInput input = std::move(input_);
    input_ = WindowInput();
    pendingInput_ = false;
    for (int button = 0; button < kMouseButtonCount; ++button)
        input_.down[button] = input.down[button];
    const int glfwKeys[kKeyCount] = {GLFW_KEY_W, GLFW_KEY_A, GLFW_KEY_S,   GLFW_KEY_D, GLFW_KEY_Q,
                                     GLFW_KEY_E, GLFW_KEY_R, GLFW_KEY_TAB, GLFW_KEY_C, GLFW_KEY_N};
    for (int key = 0; key < kKeyCount; ++key)
        input.keyHeld[key] = glfwGetKey(window_, glfwKeys[key]) == GLFW_PRESS;
    input.shiftHeld = glfwGetKey(window_, GLFW_KEY_LEFT_SHIFT) == GLFW_PRESS ||
                      glfwGetKey(window_, GLFW_KEY_RIGHT_SHIFT) == GLFW_PRESS;
    input.controlHeld = glfwGetKey(window_, GLFW_KEY_LEFT_CONTROL) == GLFW_PRESS ||
                        glfwGetKey(window_, GLFW_KEY_RIGHT_CONTROL) == GLFW_PRESS;
    return input;
}

void GlfwWindowContext::onKey(GLFWwindow* window, int key, int, int action, int mods)
{
    if (action != GLFW_PRESS)
        return;
    if (key == GLFW_KEY_ESCAPE) {
        glfwSetWindowShouldClose(window, GLFW_TRUE);
        return;
    }
    if (const std::optional<Key> known = keyOf(key)) {
        GlfwWindowContext& context = contextOf(window);
        context.input_.keyPresses.push_back({*known, (mods & GLFW_MOD_CONTROL) != 0});
        context.pendingInput_ = true;
    }
}

void GlfwWindowContext::onMouseButton(GLFWwindow* window, int button, int action, int)
{
    const std::optional<int> index = buttonIndex(button);
    if (!index)
        return;
    GlfwWindowContext& context = contextOf(window);
    context.input_.down[*index] = action == GLFW_PRESS;
    if (action == GLFW_PRESS)
        context.input_.pressed[*index] = true;
    context.pendingInput_ = true;
}

void GlfwWindowContext::onCursorMove(GLFWwindow* window, double x, double y)
{
    GlfwWindowContext& context = contextOf(window);
    const glm::dvec2 position(x, y);
    if (context.cursorKnown_) {
        const glm::vec2 travel(position - context.cursor_);
        for (int button = 0; button < kMouseButtonCount; ++button)
            if (context.input_.down[button]) {
                context.input_.drag[button] += travel;
                context.pendingInput_ = true;
            }
    }
    context.cursor_ = position;
    context.cursorKnown_ = true;
}

void GlfwWindowContext::onScroll(GLFWwindow* window, double, double y)
{
    GlfwWindowContext& context = contextOf(window);
    context.input_.wheelSteps += static_cast<float>(y);
    context.pendingInput_ = true;
}

}  // namespace platform
