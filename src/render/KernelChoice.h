#pragma once
// Which kernel --kernel auto runs on a renderer (settings/PathKernel.h), decided per renderer
// from measurements (docs/PERFORMANCE.md), and the choice made in the context now current.
#include "settings/PathKernel.h"

#include <string>

namespace render {

struct KernelChoice {
    settings::PathKernel kernel = settings::PathKernel::Fragment;
    std::string reason;  // why, for --features and the docs
};

// The kernel Automatic runs on the OpenGL renderer named `glRenderer` (GL_RENDERER): the
// fragment kernel where compute shaders are missing or nothing was measured. Never
// Automatic. No GL is called.
KernelChoice automaticKernel(const std::string& glRenderer, bool computeAvailable);

// Whether the context now current runs compute shaders (OpenGL 4.3).
bool computeKernelAvailable();
// The kernel `asked` stands for in the context now current (Automatic: automaticKernel's
// choice for its GL_RENDERER). Throws std::runtime_error for Compute where the context has
// no compute shaders.
KernelChoice chooseKernel(settings::PathKernel asked);

}  // namespace render
