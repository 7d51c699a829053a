#pragma once
#include "platform/GlContext.h"

#include <memory>
#include <string>

namespace platform {

struct ContextRequest {
    bool headless = false;
    int windowWidth = 640;
    int windowHeight = 480;
    std::string windowTitle = "raytracer";
};

// True when an X11 or Wayland display is named in the environment.
bool displayAvailable();

// An OSMesa context when `request.headless`, else a GLFW window of the requested size.
std::unique_ptr<GlContext> createContext(const ContextRequest& request);

}  // namespace platform
