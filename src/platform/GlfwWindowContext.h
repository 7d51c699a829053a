#pragma once
#include "platform/GlContext.h"

struct GLFWwindow;

namespace platform {

// A window with an OpenGL 3.3 core context, through GLFW. Escape or the close button ends
// it; vsync is off so that the renderer's speed is its own.
class GlfwWindowContext final : public GlContext {
public:
    GlfwWindowContext(int width, int height, const std::string& title);
    ~GlfwWindowContext() override;
    GlfwWindowContext(const GlfwWindowContext&) = delete;
    GlfwWindowContext& operator=(const GlfwWindowContext&) = delete;

    bool hasWindow() const override { return true; }
    std::string description() const override { return description_; }
    DrawableSize windowFramebufferSize() const override;
    void present() override;
    bool closeRequested() override;
    void setTitle(const std::string& title) override;

private:
    GLFWwindow* window_ = nullptr;
    std::string description_;
};

}  // namespace platform
