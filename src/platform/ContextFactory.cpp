#include "platform/ContextFactory.h"

#include "gl/EntryPoints.h"
#include "platform/GlfwWindowContext.h"
#include "platform/OsMesaContext.h"

#include <cstdlib>
#include <stdexcept>
#include <string>

namespace platform {

bool displayAvailable()
{
    const char* x11 = std::getenv("DISPLAY");
    const char* wayland = std::getenv("WAYLAND_DISPLAY");
    return (x11 != nullptr && *x11 != '\0') || (wayland != nullptr && *wayland != '\0');
}

std::unique_ptr<GlContext> createContext(const ContextRequest& request)
{
    if (request.headless)
        return std::make_unique<OsMesaContext>();
    return std::make_unique<GlfwWindowContext>(request.windowWidth, request.windowHeight,
                                               request.windowTitle);
}

std::string describeCurrentContext(const std::string& api)
{
    auto text = [](GLenum name) {
        const GLubyte* value = glGetString(name);
        return value != nullptr ? std::string(reinterpret_cast<const char*>(value))
                                : std::string("?");
    };
    return api + ": " + text(GL_RENDERER) + ", OpenGL " + text(GL_VERSION);
}

void requireGl33()
{
    GLint major = 0;
    GLint minor = 0;
    glGetIntegerv(GL_MAJOR_VERSION, &major);
    glGetIntegerv(GL_MINOR_VERSION, &minor);
    if (major < 3 || (major == 3 && minor < 3)) {
        const GLubyte* version = glGetString(GL_VERSION);
        throw std::runtime_error(
            "OpenGL 3.3 core is required; this context offers " +
            std::string(version != nullptr ? reinterpret_cast<const char*>(version) : "none"));
    }
}

}  // namespace platform
