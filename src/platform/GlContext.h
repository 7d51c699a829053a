#pragma once
#include <memory>
#include <string>

namespace platform {

struct DrawableSize {
    int width = 0;
    int height = 0;
};

// An OpenGL 3.3+ core context, current on the calling thread from construction until
// destruction, with every entry point loaded (see gl/EntryPoints.h). A context may show a
// window; a headless one has none and its presentation calls do nothing.
class GlContext {
public:
    virtual ~GlContext() = default;

    virtual bool hasWindow() const = 0;
    // One line naming the implementation: "OSMesa: llvmpipe (LLVM 15.0.6, 256 bits), 4.5".
    virtual std::string description() const = 0;

    // Window only: size of the default framebuffer in pixels.
    virtual DrawableSize windowFramebufferSize() const { return {}; }
    // Window only: shows the back buffer and processes input.
    virtual void present() {}
    // Window only: true once the user has closed the window or pressed Escape.
    virtual bool closeRequested() { return false; }
    virtual void setTitle(const std::string&) {}
};

// "OpenGL 4.5 (Core Profile) Mesa 22.3.6 on llvmpipe (...)": for the context now current.
std::string describeCurrentContext(const std::string& api);
// Throws unless the current context offers OpenGL 3.3 or later.
void requireGl33();

}  // namespace platform
