#include "platform/EglDevices.h"

#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <cstdio>
#include <cstring>
#include <stdexcept>

namespace platform {

namespace {

const char* eglErrorName(EGLint error)
{
    switch (error) {
    case EGL_SUCCESS:
        return "EGL_SUCCESS";
    case EGL_NOT_INITIALIZED:
        return "EGL_NOT_INITIALIZED";
    case EGL_BAD_ACCESS:
        return "EGL_BAD_ACCESS";
    case EGL_BAD_ALLOC:
        return "EGL_BAD_ALLOC";
    case EGL_BAD_ATTRIBUTE:
        return "EGL_BAD_ATTRIBUTE";
    case EGL_BAD_CONFIG:
        return "EGL_BAD_CONFIG";
    case EGL_BAD_CONTEXT:
        return "EGL_BAD_CONTEXT";
    case EGL_BAD_CURRENT_SURFACE:
        return "EGL_BAD_CURRENT_SURFACE";
    case EGL_BAD_DISPLAY:
        return "EGL_BAD_DISPLAY";
    case EGL_BAD_MATCH:
        return "EGL_BAD_MATCH";
    case EGL_BAD_NATIVE_PIXMAP:
        return "EGL_BAD_NATIVE_PIXMAP";
    case EGL_BAD_NATIVE_WINDOW:
        return "EGL_BAD_NATIVE_WINDOW";
    case EGL_BAD_PARAMETER:
        return "EGL_BAD_PARAMETER";
    case EGL_BAD_SURFACE:
        return "EGL_BAD_SURFACE";
    case EGL_CONTEXT_LOST:
        return "EGL_CONTEXT_LOST";
    case EGL_BAD_DEVICE_EXT:
        return "EGL_BAD_DEVICE_EXT";
    default:
        return "an unknown EGL error";
    }
}

}  // namespace

std::string lastEglError()
{
    const EGLint error = eglGetError();
    char code[16];
    std::snprintf(code, sizeof code, "0x%04x", static_cast<unsigned>(error));
    return std::string(eglErrorName(error)) + " (" + code + ")";
}

std::string EglDevice::kind() const
{
    if (software)
        return "EGL software device";
    return "EGL device " + std::to_string(gpuIndex) + " (GPU" + (file.empty() ? "" : ", " + file) +
           ")";
}

std::vector<EglDevice> enumerateEglDevices()
{
    // Client extensions: queried without a display (EGL 1.5, EGL_EXT_client_extensions).
    const char* client = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
    if (client == nullptr)
        throw std::runtime_error("libEGL offers no client extensions (" + lastEglError() +
                                 "): is an EGL vendor library installed (Debian: libegl-mesa0, "
                                 "or the GPU's driver)?");
    for (const char* needed :
         {"EGL_EXT_device_enumeration", "EGL_EXT_device_query", "EGL_EXT_platform_device"})
        if (!eglExtensionListHas(client, needed))
            throw std::runtime_error(std::string("libEGL lacks ") + needed);

    const auto queryDevices =
        reinterpret_cast<PFNEGLQUERYDEVICESEXTPROC>(eglGetProcAddress("eglQueryDevicesEXT"));
    const auto queryDeviceString = reinterpret_cast<PFNEGLQUERYDEVICESTRINGEXTPROC>(
        eglGetProcAddress("eglQueryDeviceStringEXT"));
    if (queryDevices == nullptr || queryDeviceString == nullptr)
        throw std::runtime_error("libEGL lists EGL_EXT_device_enumeration but does not give "
                                 "eglQueryDevicesEXT");

    EGLint count = 0;
    if (!queryDevices(0, nullptr, &count))
        throw std::runtime_error("eglQueryDevicesEXT failed: " + lastEglError());
    std::vector<EGLDeviceEXT> handles(static_cast<std::size_t>(count));
    if (count > 0 && !queryDevices(count, handles.data(), &count))
        throw std::runtime_error("eglQueryDevicesEXT failed: " + lastEglError());
    handles.resize(static_cast<std::size_t>(count));

    std::vector<EglDevice> devices;
    int gpus = 0;
    for (EGLDeviceEXT handle : handles) {
        EglDevice device;
        device.handle = handle;
        const char* extensions = queryDeviceString(handle, EGL_EXTENSIONS);
        device.software = eglExtensionListHas(extensions, "EGL_MESA_device_software");
        device.gpuIndex = device.software ? -1 : gpus++;
        // A render node needs no privileges a display server holds; the primary node is
        // named where there is no render node.
        const char* node = nullptr;
        if (eglExtensionListHas(extensions, "EGL_EXT_device_drm_render_node"))
            node = queryDeviceString(handle, EGL_DRM_RENDER_NODE_FILE_EXT);
        if (node == nullptr && eglExtensionListHas(extensions, "EGL_EXT_device_drm"))
            node = queryDeviceString(handle, EGL_DRM_DEVICE_FILE_EXT);
        if (node != nullptr)
            device.file = node;
        eglGetError();  // a string a device lacks is no error of the caller's
        devices.push_back(device);
    }
    return devices;
}

bool eglExtensionListHas(const char* extensions, const char* name)
{
    if (extensions == nullptr)
        return false;
    const std::size_t length = std::strlen(name);
    for (const char* at = std::strstr(extensions, name); at != nullptr;
         at = std::strstr(at + 1, name))
        if ((at == extensions || at[-1] == ' ') && (at[length] == ' ' || at[length] == '\0'))
            return true;
    return false;
}

}  // namespace platform
