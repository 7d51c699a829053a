#pragma once
#include "platform/GlContext.h"

#include <memory>
#include <optional>
#include <string>

namespace platform {

// Which OpenGL to render with (--gl).
enum class ContextKind {
    // A window where there is a display and the render is not headless; else the first of
    // EGL on a GPU, EGL on Mesa's software device, EGL surfaceless and OSMesa that works.
    Automatic,
    Egl,     // headless through EGL only: a GPU, else the software device, else surfaceless
    Gpu,     // headless through EGL on a GPU only (the first that works), never on the CPU
    OsMesa,  // headless through Mesa's off-screen interface (llvmpipe)
    Window,  // a GLFW window (needs a display)
};

// "auto", "egl", "gpu", "osmesa", "window" (for messages and --gl).
const char* contextKindName(ContextKind kind);
std::optional<ContextKind> contextKindNamed(const std::string& name);

struct ContextRequest {
    ContextKind kind = ContextKind::Automatic;
    // Automatic only: no window even where there is a display.
    bool headless = false;
    // --gl-device N: the Nth GPU EGL lists (GPUs only, counted from 0), and no other: a
    // render meant for one GPU never falls back to another device or to the CPU. Whatever
    // the kind, it makes the request Gpu's for that one GPU.
    std::optional<int> gpuIndex;
    int windowWidth = 640;
    int windowHeight = 480;
    std::string windowTitle = "raytracer";
};

// True when an X11 or Wayland display is named in the environment.
bool displayAvailable();

// True when `request` makes a context without a window.
bool makesHeadlessContext(const ContextRequest& request);

// The context `request` asks for. Throws std::runtime_error when none can be made, naming
// every kind tried and why each failed.
std::unique_ptr<GlContext> createContext(const ContextRequest& request);

}  // namespace platform
