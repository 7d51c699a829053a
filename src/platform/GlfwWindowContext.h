#pragma once
#include "platform/GlContext.h"
#include "platform/WindowInput.h"

struct GLFWwindow;

namespace platform {

// A resizable window with an OpenGL 3.3 core context, through GLFW. Escape or the close
// button ends it; vsync is off so that the renderer's speed is its own. It gathers the
// mouse and key input the window gets (takeInput).
class GlfwWindowContext final : public GlContext {
public:
    GlfwWindowContext(int width, int height, const std::string& title);
    ~GlfwWindowContext() override;
    GlfwWindowContext(const GlfwWindowContext&) = delete;
    GlfwWindowContext& operator=(const GlfwWindowContext&) = delete;

    bool hasWindow() const override { return true; }
    const ContextIdentity& identity() const override { return identity_; }
    DrawableSize windowFramebufferSize() const override;
    void present() override;
    bool closeRequested() override;
    void setTitle(const std::string& title) override;

    // The window's size in screen coordinates (mouse positions are in these).
    DrawableSize windowSize() const;
    // What the user did since the last call (events are read by closeRequested and
    // waitForInput).
    WindowInput takeInput();
    // Input arrived since the last takeInput: a button, a drag, the wheel or a key.
    bool hasPendingInput() const { return pendingInput_; }
    // Sleeps until an event arrives or `seconds` pass, then reads the events.
    void waitForInput(double seconds);

    // For libraries that draw into the window themselves (the statistics panel).
    GLFWwindow* glfwWindow() const { return window_; }

private:
    static void onKey(GLFWwindow* window, int key, int scancode, int action, int mods);
    static void onMouseButton(GLFWwindow* window, int button, int action, int mods);
    static void onCursorMove(GLFWwindow* window, double x, double y);
    static void onScroll(GLFWwindow* window, double x, double y);

    GLFWwindow* window_ = nullptr;
    ContextIdentity identity_;
    WindowInput input_;
    glm::dvec2 cursor_{0.0};
    bool cursorKnown_ = false;
    bool pendingInput_ = false;
};

}  // namespace platform
