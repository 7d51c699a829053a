#include "film/Denoiser.h"

#include <dlfcn.h>

#include <cstdlib>
#include <filesystem>
#include <mutex>
#include <vector>

namespace film {

namespace fs = std::filesystem;

namespace {

// OIDN 2's C API (include/OpenImageDenoise/oidn.h), the part used here.
using Handle = void*;
constexpr int kDeviceTypeCpu = 1;  // OIDN_DEVICE_TYPE_CPU
constexpr int kFormatFloat3 = 3;   // OIDN_FORMAT_FLOAT3
constexpr int kErrorNone = 0;      // OIDN_ERROR_NONE

struct OidnApi {
    Handle (*newDevice)(int type);
    void (*commitDevice)(Handle device);
    int (*getDeviceError)(Handle device, const char** message);
    void (*releaseDevice)(Handle device);
    Handle (*newFilter)(Handle device, const char* type);
    void (*setSharedFilterImage)(Handle filter, const char* name, void* pointer, int format,
                                 std::size_t width, std::size_t height, std::size_t byteOffset,
                                 std::size_t pixelByteStride, std::size_t rowByteStride);
    void (*setFilterBool)(Handle filter, const char* name, bool value);
    void (*commitFilter)(Handle filter);
    void (*executeFilter)(Handle filter);
    void (*releaseFilter)(Handle filter);
    std::string path;
};

std::vector<fs::path> candidateLibraries()
{
    std::vector<fs::path> candidates;
    if (const char* given = std::getenv("RAYTRACER_OIDN_LIBRARY"); given && *given)
        candidates.emplace_back(given);
    fs::path venv;
    if (const char* given = std::getenv("RAYTRACER_OIDN_VENV"); given && *given)
        venv = given;
    else if (const char* home = std::getenv("HOME"); home && *home)
        venv = fs::path(home) / ".local/share/raytracer/oidn-venv";
    std::error_code error;
    if (!venv.empty() && fs::is_directory(venv / "lib", error))
        for (const fs::directory_entry& python : fs::directory_iterator(venv / "lib", error)) {
            const fs::path library = python.path() / "site-packages/pyoidn/oidn/lib/"
                                                     "libOpenImageDenoise.so.2";
            if (python.path().filename().string().rfind("python", 0) == 0 &&
                fs::exists(library, error))
                candidates.push_back(library);
        }
    candidates.emplace_back("libOpenImageDenoise.so.2");
    return candidates;
}

std::string installHint()
{
    return "Open Image Denoise (libOpenImageDenoise.so.2) was not found: install it with "
           "tools/install-dependencies.sh (it puts the pyoidn wheel in "
           "~/.local/share/raytracer/oidn-venv), or `python3 -m venv "
           "~/.local/share/raytracer/oidn-venv && ~/.local/share/raytracer/oidn-venv/bin/pip "
           "install pyoidn`, or set RAYTRACER_OIDN_LIBRARY to the library's path "
           "(docs/DENOISING.md)";
}

template <typename Function>
void bindEntryPoint(void* library, const char* name, Function& function, const std::string& path)
{
    function = reinterpret_cast<Function>(dlsym(library, name));
    if (function == nullptr)
        throw DenoiserUnavailable(path + " has no " + name + ": not Open Image Denoise 2");
}

// Loaded once per process, kept loaded.
const OidnApi& api()
{
    static std::once_flag once;
    static OidnApi loaded{};
    static std::string failure;
    std::call_once(once, [] {
        std::string tried;
        for (const fs::path& candidate : candidateLibraries()) {
            void* library = dlopen(candidate.c_str(), RTLD_NOW | RTLD_LOCAL);
            if (library == nullptr) {
                const char* why = dlerror();
                tried += "\n  " + candidate.string() + ": " + (why ? why : "not loadable");
                continue;
            }
            try {
                const std::string path = candidate.string();
                bindEntryPoint(library, "oidnNewDevice", loaded.newDevice, path);
                bindEntryPoint(library, "oidnCommitDevice", loaded.commitDevice, path);
                bindEntryPoint(library, "oidnGetDeviceError", loaded.getDeviceError, path);
                bindEntryPoint(library, "oidnReleaseDevice", loaded.releaseDevice, path);
                bindEntryPoint(library, "oidnNewFilter", loaded.newFilter, path);
                bindEntryPoint(library, "oidnSetSharedFilterImage", loaded.setSharedFilterImage,
                               path);
                bindEntryPoint(library, "oidnSetFilterBool", loaded.setFilterBool, path);
                bindEntryPoint(library, "oidnCommitFilter", loaded.commitFilter, path);
                bindEntryPoint(library, "oidnExecuteFilter", loaded.executeFilter, path);
                bindEntryPoint(library, "oidnReleaseFilter", loaded.releaseFilter, path);
                loaded.path = path;
                return;
            } catch (const DenoiserUnavailable& error) {
                tried += std::string("\n  ") + error.what();
                dlclose(library);
            }
        }
        failure = installHint() + ". Looked for:" + tried;
    });
    if (loaded.path.empty())
        throw DenoiserUnavailable(failure);
    return loaded;
}

void throwOnError(const OidnApi& oidn, Handle device, const char* doing)
{
    const char* message = nullptr;
    if (oidn.getDeviceError(device, &message) != kErrorNone)
        throw std::runtime_error(std::string("Open Image Denoise failed ") + doing + ": " +
                                 (message ? message : "no message"));
}

// A contiguous RGB copy (the images may have more channels).
std::vector<float> rgbOf(const io::Image& image)
{
    std::vector<float> rgb(static_cast<std::size_t>(image.width) * image.height * 3);
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x)
            for (int c = 0; c < 3; ++c)
                rgb[(static_cast<std::size_t>(y) * image.width + x) * 3 + c] = image.at(x, y, c);
    return rgb;
}

}  // namespace

std::string denoiserLibrary()
{
    return api().path;
}

bool denoiserAvailable()
{
    try {
        api();
        return true;
    } catch (const DenoiserUnavailable&) {
        return false;
    }
}

io::Image denoiseImage(const io::Image& color, const io::Image& albedo, const io::Image& normal)
{
    const OidnApi& oidn = api();
    const auto sameSize = [&](const io::Image& image) {
        return image.width == color.width && image.height == color.height && image.channels >= 3;
    };
    if (color.channels < 3 || (albedo.width > 0 && !sameSize(albedo)) ||
        (normal.width > 0 && !sameSize(normal)) || (normal.width > 0 && albedo.width == 0))
        throw std::invalid_argument("denoising needs RGB images of one size (a normal only "
                                    "with an albedo)");
    std::vector<float> input = rgbOf(color);
    std::vector<float> albedoTexels = albedo.width > 0 ? rgbOf(albedo) : std::vector<float>();
    std::vector<float> normalTexels = normal.width > 0 ? rgbOf(normal) : std::vector<float>();
    std::vector<float> output(input.size());

    const auto width = static_cast<std::size_t>(color.width);
    const auto height = static_cast<std::size_t>(color.height);
    Handle device = oidn.newDevice(kDeviceTypeCpu);
    if (device == nullptr)
        throw std::runtime_error("Open Image Denoise could not make a CPU device");
    struct Release {
        const OidnApi& oidn;
        Handle device;
        Handle filter = nullptr;
        ~Release()
        {
            if (filter)
                oidn.releaseFilter(filter);
            oidn.releaseDevice(device);
        }
    } release{oidn, device};
    oidn.commitDevice(device);
    throwOnError(oidn, device, "making its device");
    Handle filter = oidn.newFilter(device, "RT");
    release.filter = filter;
    throwOnError(oidn, device, "making its filter");
    const auto share = [&](const char* name, std::vector<float>& texels) {
        oidn.setSharedFilterImage(filter, name, texels.data(), kFormatFloat3, width, height, 0, 0,
                                  0);
    };
    share("color", input);
    if (!albedoTexels.empty())
        share("albedo", albedoTexels);
    if (!normalTexels.empty())
        share("normal", normalTexels);
    share("output", output);
    oidn.setFilterBool(filter, "hdr", true);
    oidn.commitFilter(filter);
    throwOnError(oidn, device, "setting up its filter");
    oidn.executeFilter(filter);
    throwOnError(oidn, device, "denoising");

    io::Image denoised(color.width, color.height, 3);
    for (std::size_t i = 0; i < output.size(); ++i)
        denoised.pixels[i] = output[i];
    return denoised;
}

}  // namespace film
