#pragma once
#include <memory>
#include <string>

namespace platform {

struct DrawableSize {
    int width = 0;
    int height = 0;
};

// Which OpenGL renders: the kind of context and what the driver says of itself. Every
// summary line, --features, each output's metadata and `raytracer info` name it, so that a
// render on a software rasteriser where a GPU was meant is seen at once, not from its speed.
struct ContextIdentity {
    // "EGL device 0 (GPU, /dev/dri/renderD128)", "EGL software device", "EGL surfaceless",
    // "OSMesa", "GLFW window".
    std::string kind;
    std::string renderer;  // GL_RENDERER: "llvmpipe (LLVM 15.0.6, 256 bits)"
    std::string version;   // GL_VERSION: "4.5 (Core Profile) Mesa 22.3.6"

    // "OSMesa: llvmpipe (LLVM 15.0.6, 256 bits), OpenGL 4.5 (Core Profile) Mesa 22.3.6"
    std::string describe() const;
};

// An OpenGL 3.3+ core context, current on the calling thread from construction until
// destruction, with every entry point loaded (see gl/EntryPoints.h). A context may show a
// window; a headless one has none and its presentation calls do nothing.
class GlContext {
public:
    virtual ~GlContext() = default;

    virtual bool hasWindow() const = 0;
    virtual const ContextIdentity& identity() const = 0;
    // One line naming the implementation (identity().describe()).
    std::string description() const { return identity().describe(); }

    // Window only: size of the default framebuffer in pixels.
    virtual DrawableSize windowFramebufferSize() const { return {}; }
    // Window only: shows the back buffer and processes input.
    virtual void present() {}
    // Window only: true once the user has closed the window or pressed Escape.
    virtual bool closeRequested() { return false; }
    virtual void setTitle(const std::string&) {}
};

// The identity of the context now current, of the given kind.
ContextIdentity identifyCurrentContext(const std::string& kind);
// Throws unless the current context offers OpenGL 3.3 or later.
void requireGl33();

}  // namespace platform
