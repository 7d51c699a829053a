// The kernel --kernel auto runs on each renderer (render/KernelChoice.h): decided per renderer,
// from the table of measured (or documented) winners; the fragment kernel wherever compute
// shaders are missing or nothing is known.
#include "render/KernelChoice.h"

#include <gtest/gtest.h>

namespace render_tests {
namespace {

using settings::PathKernel;

TEST(AutomaticKernel, OnLlvmpipeIsTheOneMeasuredFaster)
{
    const render::KernelChoice choice =
        render::automaticKernel("llvmpipe (LLVM 15.0.6, 256 bits)", true);
    EXPECT_EQ(choice.kernel, PathKernel::Fragment);
    EXPECT_NE(choice.reason.find("measured"), std::string::npos) << choice.reason;
}

TEST(AutomaticKernel, OnAGraphicsLightDataCentreGpuIsTheComputeKernel)
{
    for (const char* renderer : {"NVIDIA H100 80GB HBM3/PCIe/SSE2", "NVIDIA H200/PCIe/SSE2",
                                 "NVIDIA GH200 480GB/PCIe/SSE2"})
        EXPECT_EQ(render::automaticKernel(renderer, true).kernel, PathKernel::Compute) << renderer;
}

TEST(AutomaticKernel, WithoutComputeShadersIsTheFragmentKernel)
{
    EXPECT_EQ(render::automaticKernel("NVIDIA H200/PCIe/SSE2", false).kernel, PathKernel::Fragment);
}

TEST(AutomaticKernel, OnARendererNotMeasuredIsTheFragmentKernelAndSaysSo)
{
    const render::KernelChoice choice =
        render::automaticKernel("NVIDIA GeForce GTX 970/PCIe/SSE2", true);
    EXPECT_EQ(choice.kernel, PathKernel::Fragment);
    EXPECT_NE(choice.reason.find("nothing measured"), std::string::npos) << choice.reason;
}

TEST(PathKernelNames, ReadBackAsTheKernelTheyName)
{
    for (PathKernel kernel : {PathKernel::Automatic, PathKernel::Fragment, PathKernel::Compute})
        EXPECT_EQ(settings::pathKernelNamed(settings::pathKernelName(kernel)), kernel);
    EXPECT_FALSE(settings::pathKernelNamed("vertex").has_value());
}

}  // namespace
}  // namespace render_tests
