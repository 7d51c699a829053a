#pragma once
// Which GPU kernel drives the path tracer (--kernel): both run the same per-pixel code
// (shaders/modules/path_tracer_main.glsl: the path loop, the accumulation, the sample
// counts), so they give a pixel the same samples; they differ in how the GPU is asked to run
// it, and so in speed, device by device. Which one Automatic stands for on a renderer is
// render/KernelChoice.h's decision.
#include <optional>
#include <string>

namespace settings {

enum class PathKernel {
    // The kernel measured faster on the renderer at hand (render::automaticKernel).
    Automatic,
    // A full-screen triangle's fragments (OpenGL 3.3): fragment_kernel.glsl.
    Fragment,
    // A compute dispatch (OpenGL 4.3): compute_kernel.glsl.
    Compute,
};

// "auto", "fragment", "compute" (for --kernel, messages and metadata).
inline const char* pathKernelName(PathKernel kernel)
{
    switch (kernel) {
    case PathKernel::Automatic: return "auto";
    case PathKernel::Fragment: return "fragment";
    case PathKernel::Compute: return "compute";
    }
    return "?";
}

inline std::optional<PathKernel> pathKernelNamed(const std::string& name)
{
    for (PathKernel kernel : {PathKernel::Automatic, PathKernel::Fragment, PathKernel::Compute})
        if (name == pathKernelName(kernel))
            return kernel;
    return std::nullopt;
}

}  // namespace settings
