#include "platform/ContextFactory.h"

#include "gl/EntryPoints.h"
#include "platform/EglContext.h"
#include "platform/EglDevices.h"
#include "platform/GlfwWindowContext.h"
#include "platform/OsMesaContext.h"

#include <cstdlib>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

namespace platform {

namespace {

// Each way tried, and why it failed, for the error that lists them all.
class Attempts {
public:
    // Runs `make`; keeps its failure (labelled) and returns null when it throws.
    std::unique_ptr<GlContext> attempt(const std::string& label,
                                       const std::function<std::unique_ptr<GlContext>()>& make)
    {
        try {
            return make();
        } catch (const std::exception& error) {
            failures_.push_back(label + ": " + error.what());
            return nullptr;
        }
    }
    void fail(const std::string& label, const std::string& reason)
    {
        failures_.push_back(label + ": " + reason);
    }
    [[noreturn]] void throwNone(const std::string& what) const
    {
        std::string message = "no OpenGL context could be made for " + what + "; tried:";
        for (const std::string& failure : failures_)
            message += "\n  " + failure;
        throw std::runtime_error(message);
    }

private:
    std::vector<std::string> failures_;
};

// "1 device: EGL software device" for messages.
std::string listDevices(const std::vector<EglDevice>& devices)
{
    std::string text =
        std::to_string(devices.size()) + (devices.size() == 1 ? " device" : " devices");
    for (std::size_t i = 0; i < devices.size(); ++i)
        text += (i == 0 ? ": " : ", ") + devices[i].kind();
    return text;
}

// EGL on a GPU (the one asked for, else each in turn), then, unless `gpusOnly`, on Mesa's
// software device and on Mesa's surfaceless platform. Null when none works; the reasons are
// in `attempts`.
std::unique_ptr<GlContext> tryEgl(const ContextRequest& request, bool gpusOnly, Attempts& attempts)
{
    std::vector<EglDevice> devices;
    try {
        devices = enumerateEglDevices();
    } catch (const std::exception& error) {
        attempts.fail("EGL devices", error.what());
    }
    int gpus = 0;
    for (const EglDevice& device : devices) {
        if (device.software)
            continue;
        ++gpus;
        if (request.gpuIndex && device.gpuIndex != *request.gpuIndex)
            continue;
        if (auto context =
                attempts.attempt(device.kind(), [&] { return EglContext::onDevice(device); }))
            return context;
    }
    if (request.gpuIndex) {
        if (*request.gpuIndex >= gpus)
            attempts.fail("--gl-device " + std::to_string(*request.gpuIndex),
                          "EGL lists " + std::to_string(gpus) + (gpus == 1 ? " GPU" : " GPUs") +
                              " (" + listDevices(devices) + ")");
        return nullptr;
    }
    if (gpus == 0 && !devices.empty())
        attempts.fail("EGL on a GPU", "EGL lists no GPU (" + listDevices(devices) + ")");
    if (gpusOnly)
        return nullptr;
    for (const EglDevice& device : devices)
        if (device.software)
            if (auto context =
                    attempts.attempt(device.kind(), [&] { return EglContext::onDevice(device); }))
                return context;
    return attempts.attempt("EGL surfaceless", [] { return EglContext::surfaceless(); });
}

std::unique_ptr<GlContext> tryOsMesa(Attempts& attempts)
{
    return attempts.attempt("OSMesa", [] { return std::make_unique<OsMesaContext>(); });
}

}  // namespace

const char* contextKindName(ContextKind kind)
{
    switch (kind) {
    case ContextKind::Automatic:
        return "auto";
    case ContextKind::Egl:
        return "egl";
    case ContextKind::Gpu:
        return "gpu";
    case ContextKind::OsMesa:
        return "osmesa";
    case ContextKind::Window:
        return "window";
    }
    return "?";
}

std::optional<ContextKind> contextKindNamed(const std::string& name)
{
    for (ContextKind kind : {ContextKind::Automatic, ContextKind::Egl, ContextKind::Gpu,
                             ContextKind::OsMesa, ContextKind::Window})
        if (name == contextKindName(kind))
            return kind;
    return std::nullopt;
}

bool displayAvailable()
{
    const char* x11 = std::getenv("DISPLAY");
    const char* wayland = std::getenv("WAYLAND_DISPLAY");
    return (x11 != nullptr && *x11 != '\0') || (wayland != nullptr && *wayland != '\0');
}

bool makesHeadlessContext(const ContextRequest& request)
{
    switch (request.kind) {
    case ContextKind::Automatic:
        return request.headless || request.gpuIndex || !displayAvailable();
    case ContextKind::Window:
        return false;
    case ContextKind::Egl:
    case ContextKind::Gpu:
    case ContextKind::OsMesa:
        return true;
    }
    return true;
}

std::unique_ptr<GlContext> createContext(const ContextRequest& request)
{
    Attempts attempts;
    std::unique_ptr<GlContext> context;
    // A GPU asked for by number is that GPU through EGL, nothing else.
    const ContextKind kind = request.gpuIndex ? ContextKind::Gpu : request.kind;
    switch (kind) {
    case ContextKind::Window:
        return std::make_unique<GlfwWindowContext>(request.windowWidth, request.windowHeight,
                                                   request.windowTitle);
    case ContextKind::OsMesa:
        if ((context = tryOsMesa(attempts)))
            return context;
        attempts.throwNone("--gl osmesa");
    case ContextKind::Egl:
        if ((context = tryEgl(request, false, attempts)))
            return context;
        attempts.throwNone("--gl egl");
    case ContextKind::Gpu:
        if ((context = tryEgl(request, true, attempts)))
            return context;
        attempts.throwNone(request.gpuIndex ? "--gl-device " + std::to_string(*request.gpuIndex)
                                            : std::string("--gl gpu"));
    case ContextKind::Automatic:
        if (!makesHeadlessContext(request))
            return std::make_unique<GlfwWindowContext>(request.windowWidth, request.windowHeight,
                                                       request.windowTitle);
        if ((context = tryEgl(request, false, attempts)) || (context = tryOsMesa(attempts)))
            return context;
        attempts.throwNone("a headless render");
    }
    attempts.throwNone("an unknown kind");
}

ContextIdentity identifyCurrentContext(const std::string& kind)
{
    auto text = [](GLenum name) {
        const GLubyte* value = glGetString(name);
        return value != nullptr ? std::string(reinterpret_cast<const char*>(value))
                                : std::string("?");
    };
    return {kind, text(GL_RENDERER), text(GL_VERSION)};
}

std::string ContextIdentity::describe() const
{
    return kind + ": " + renderer + ", OpenGL " + version;
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
