#include "render/PathKernel.h"

namespace render {

namespace {

// One row per renderer whose faster kernel is known, matched by a substring of GL_RENDERER;
// the first match decides. Each row says where its figure comes from.
struct RendererKernel {
    const char* rendererContains;
    PathKernel kernel;
    const char* reason;
};

const RendererKernel kRendererKernels[] = {
    // Measured by bench/gpu-check.sh and bench/compare-kernels.sh side by side
    // (docs/PERFORMANCE.md, "Fragment and compute kernels").
    {"llvmpipe", PathKernel::Fragment,
     "llvmpipe: measured side by side on the seven classic scenes, the fragment kernel is "
     "the faster (docs/PERFORMANCE.md)"},
    // Not measured here: NVIDIA's H100 architecture whitepaper (2022) says only two of the
    // chip's TPCs can run pixel shaders, so a fragment kernel uses a few of its 132 SMs while
    // a compute dispatch uses them all. The H200 is the same chip (GH100).
    {"H100", PathKernel::Compute,
     "NVIDIA H100: only two of its TPCs shade fragments (NVIDIA's H100 whitepaper); not "
     "measured here"},
    {"H200", PathKernel::Compute,
     "NVIDIA H200: only two of its TPCs shade fragments (NVIDIA's H100 whitepaper, same "
     "GH100 chip); not measured here"},
    {"GH200", PathKernel::Compute,
     "NVIDIA GH200: only two of its TPCs shade fragments (NVIDIA's H100 whitepaper); not "
     "measured here"},
};

}  // namespace

const char* pathKernelName(PathKernel kernel)
{
    switch (kernel) {
    case PathKernel::Automatic: return "auto";
    case PathKernel::Fragment: return "fragment";
    case PathKernel::Compute: return "compute";
    }
    return "?";
}

std::optional<PathKernel> pathKernelNamed(const std::string& name)
{
    for (PathKernel kernel : {PathKernel::Automatic, PathKernel::Fragment, PathKernel::Compute})
        if (name == pathKernelName(kernel))
            return kernel;
    return std::nullopt;
}

KernelChoice automaticKernel(const std::string& glRenderer, bool computeAvailable)
{
    if (!computeAvailable)
        return {PathKernel::Fragment, "this OpenGL has no compute shaders (4.3)"};
    for (const RendererKernel& row : kRendererKernels)
        if (glRenderer.find(row.rendererContains) != std::string::npos)
            return {row.kernel, row.reason};
    return {PathKernel::Fragment,
            "nothing measured on this renderer: the fragment kernel (bench/gpu-check.sh "
            "measures both)"};
}

}  // namespace render
