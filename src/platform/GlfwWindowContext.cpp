#include "platform/GlfwWindowContext.h"

#include "gl/EntryPoints.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

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

void closeOnEscape(GLFWwindow* window, int key, int, int action, int)
{
    if (key == GLFW_KEY_ESCAPE && action == GLFW_PRESS)
        glfwSetWindowShouldClose(window, GLFW_TRUE);
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
    glfwWindowHint(GLFW_RESIZABLE, GLFW_FALSE);
    window_ = glfwCreateWindow(width, height, title.c_str(), nullptr, nullptr);
    if (window_ == nullptr) {
        glfwTerminate();
        throw std::runtime_error("cannot open an OpenGL 3.3 core window: " + lastGlfwError);
    }
    glfwMakeContextCurrent(window_);
    glfwSetKeyCallback(window_, &closeOnEscape);
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
    description_ = describeCurrentContext("GLFW window");
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

}  // namespace platform
