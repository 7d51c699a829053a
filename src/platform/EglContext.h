#pragma once
#include "platform/EglDevices.h"
#include "platform/GlContext.h"

#include <memory>

namespace platform {

// A headless OpenGL core context through EGL, on a device EGL lists (a GPU, or Mesa's
// software device) or on Mesa's surfaceless platform. It needs no display and no window
// system: the renderer draws into its own framebuffer objects, so the context has no surface
// at all where the driver allows (EGL_KHR_surfaceless_context), else a tiny pbuffer.
class EglContext final : public GlContext {
public:
    // Each throws std::runtime_error saying which EGL step failed and why.
    static std::unique_ptr<EglContext> onDevice(const EglDevice& device);
    static std::unique_ptr<EglContext> surfaceless();

    ~EglContext() override;
    EglContext(const EglContext&) = delete;
    EglContext& operator=(const EglContext&) = delete;

    bool hasWindow() const override { return false; }
    const ContextIdentity& identity() const override { return identity_; }

private:
    // `display` from eglGetPlatformDisplayEXT, not yet initialised.
    EglContext(void* display, const std::string& kind);
    void release();

    void* display_ = nullptr;
    void* context_ = nullptr;
    void* surface_ = nullptr;
    ContextIdentity identity_;
};

}  // namespace platform
