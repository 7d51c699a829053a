#pragma once
// Which GPU kernel drives the path tracer (--kernel): both run the same per-pixel code
// (shaders/modules/path_tracer_main.glsl: the path loop, the accumulation, the sample
// counts), so they give a pixel the same samples; they differ in how the GPU is asked to run
// it, and so in speed, device by device.
#include <optional>
#include <string>

namespace render {

enum class PathKernel {
    // The kernel measured faster on the renderer at hand (automaticKernel).
    Automatic,
    // A full-screen triangle's fragments (OpenGL 3.3): fragment_kernel.glsl.
    Fragment,
    // A compute dispatch (OpenGL 4.3): compute_kernel.glsl.
    Compute,
};

// "auto", "fragment", "compute" (for --kernel, messages and metadata).
const char* pathKernelName(PathKernel kernel);
std::optional<PathKernel> pathKernelNamed(const std::string& name);

struct KernelChoice {
    PathKernel kernel = PathKernel::Fragment;
    std::string reason;  // why, for --features and the docs
};

// The kernel Automatic runs on the OpenGL renderer named `glRenderer` (GL_RENDERER):
// decided per renderer from measurements (docs/PERFORMANCE.md), the fragment kernel where
// compute shaders are missing or nothing was measured. Never Automatic.
KernelChoice automaticKernel(const std::string& glRenderer, bool computeAvailable);

}  // namespace render
