#pragma once
#include <string>
#include <vector>

namespace platform {

// An OpenGL device EGL offers without a display (EGL_EXT_device_enumeration): each GPU of
// a vendor's driver (NVIDIA's lists every GPU; Mesa one per render node it can drive), and
// Mesa's software rasteriser (llvmpipe) as a device of its own.
struct EglDevice {
    void* handle = nullptr;  // the EGLDeviceEXT
    // Mesa's software device (EGL_MESA_device_software): the CPU, not a GPU.
    bool software = false;
    // Among the GPUs only, in EGL's order: what --gl-device counts. -1 for the software one.
    int gpuIndex = -1;
    // The DRM node it drives ("/dev/dri/renderD128"); empty where EGL names none.
    std::string file;

    // "EGL device 0 (GPU, /dev/dri/renderD128)" or "EGL software device".
    std::string kind() const;
};

// Every device EGL lists, in its order. Throws std::runtime_error naming what is missing
// when EGL cannot list devices (no EGL_EXT_device_enumeration, no vendor library).
std::vector<EglDevice> enumerateEglDevices();

// "EGL_BAD_MATCH (0x3009)": the EGL error last raised on this thread.
std::string lastEglError();

// True when the space-separated EGL extension list `extensions` (which may be null) names
// `name` whole, not as the prefix of a longer name.
bool eglExtensionListHas(const char* extensions, const char* name);

}  // namespace platform
