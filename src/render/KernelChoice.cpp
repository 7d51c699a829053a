#include "render/KernelChoice.h"

#include "gl/EntryPoints.h"

#include <stdexcept>

namespace render {

using settings::PathKernel;

namespace {

// One row per renderer whose faster kernel is known, matched by a substring of GL_RENDERER;
// the first match decides. Each row says where its figure comes from.
struct RendererKernel {
    const char* rendererContains;
    PathKernel kernel;
    const char* reason;
};

const RendererKernel kRendererKernels[] = {
    // Measured side by side by bench/gpu-check.sh (docs/PERFORMANCE.md, "Fragment and
    // compute kernels").
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

bool computeKernelAvailable()
{
    GLint major = 0;
    GLint minor = 0;
    glGetIntegerv(GL_MAJOR_VERSION, &major);
    glGetIntegerv(GL_MINOR_VERSION, &minor);
    return major > 4 || (major == 4 && minor >= 3);
}

KernelChoice chooseKernel(PathKernel asked)
{
    const GLubyte* renderer = glGetString(GL_RENDERER);
    const std::string rendererName =
        renderer != nullptr ? reinterpret_cast<const char*>(renderer) : "";
    switch (asked) {
    case PathKernel::Fragment:
        return {PathKernel::Fragment, "asked for (--kernel fragment)"};
    case PathKernel::Compute:
        if (!computeKernelAvailable()) {
            const GLubyte* version = glGetString(GL_VERSION);
            throw std::runtime_error(
                "the compute kernel needs OpenGL 4.3; this context (" + rendererName + ") offers " +
                (version != nullptr ? reinterpret_cast<const char*>(version) : "none") +
                ": use --kernel fragment");
        }
        return {PathKernel::Compute, "asked for (--kernel compute)"};
    case PathKernel::Automatic:
        break;
    }
    return automaticKernel(rendererName, computeKernelAvailable());
}

}  // namespace render
