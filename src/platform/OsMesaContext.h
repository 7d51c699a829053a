#pragma once
#include "platform/GlContext.h"

#include <vector>

typedef struct osmesa_context* OSMesaContext;

namespace platform {

// A headless OpenGL core context from Mesa's off-screen interface. It needs no X server; the
// renderer draws into its own framebuffer objects, so the context's own buffer stays tiny.
class OsMesaContext final : public GlContext {
public:
    OsMesaContext();
    ~OsMesaContext() override;
    OsMesaContext(const OsMesaContext&) = delete;
    OsMesaContext& operator=(const OsMesaContext&) = delete;

    bool hasWindow() const override { return false; }
    const ContextIdentity& identity() const override { return identity_; }

private:
    OSMesaContext context_ = nullptr;
    std::vector<unsigned char> defaultFramebuffer_;
    ContextIdentity identity_;
};

}  // namespace platform
