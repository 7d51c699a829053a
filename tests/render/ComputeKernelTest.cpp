// The compute kernel (settings/PathKernel.h) against the fragment kernel, in the context the
// executable made (OSMesa, or EGL: ctest runs both): the two run the same per-pixel code
// (shaders/modules/path_tracer_main.glsl), so for one seed every pixel holds the same number
// of samples, of the same sample indices, and the images agree within noise. (On llvmpipe the
// radiance agrees bit for bit, but the fragment stage flushes denormals to zero and compute
// does not; a GPU may contract arithmetic differently in the two stages: so no more than
// agreement within noise is asked.)
#include "render/KernelChoice.h"
#include "render/ProgressiveRenderer.h"
#include "support/ImageComparison.h"
#include "support/RenderRun.h"
#include "support/TestPaths.h"

#include <gtest/gtest.h>

namespace render_tests {
namespace {

using namespace testing_support;

class ComputeKernel : public ::testing::Test {
protected:
    void SetUp() override
    {
        if (!render::computeKernelAvailable())
            GTEST_SKIP() << "this context has no compute shaders (OpenGL 4.3)";
    }

    static settings::RenderSettings settings(settings::PathKernel kernel)
    {
        settings::RenderSettings settings = settingsWithSeed(kTestSeedForKernels);
        settings.kernel = kernel;
        return settings;
    }

    static constexpr std::uint64_t kTestSeedForKernels = 11;
};

// Glass, mirrors, textures and a sphere light: most of the path loop's branches.
scene::Scene classicScene1()
{
    return loadScene(sourceDirectory() / "scenes" / "scene1.in");
}

void expectSameSampleCounts(const RenderedImage& compute, const RenderedImage& fragment)
{
    for (int y = 0; y < fragment.height(); ++y)
        for (int x = 0; x < fragment.width(); ++x)
            ASSERT_EQ(compute.accumulation.samplesTaken(x, y),
                      fragment.accumulation.samplesTaken(x, y))
                << "pixel (" << x << ", " << y << ")";
}

TEST_F(ComputeKernel, TracesEveryPixelsSamplesAsTheFragmentKernelDoes)
{
    const scene::Scene scene = classicScene1();
    settings::RenderSettings compute = settings(settings::PathKernel::Compute);
    settings::RenderSettings fragment = settings(settings::PathKernel::Fragment);
    compute.secondsPerBand = fragment.secondsPerBand = 0.0;  // whole frames
    const RenderedImage computed = renderScene(scene, 64, 48, 16, compute);
    const RenderedImage reference = renderScene(scene, 64, 48, 16, fragment);

    expectSameSampleCounts(computed, reference);
    const Comparison comparison = compareImages(computed, reference);
    EXPECT_TRUE(comparison.passed()) << comparison.describe();
    // The same samples give the same spread: the moments are traced and written too.
    double computedVariance = 0.0;
    double referenceVariance = 0.0;
    for (int y = 0; y < reference.height(); ++y)
        for (int x = 0; x < reference.width(); ++x) {
            computedVariance += computed.varianceOfMean(x, y);
            referenceVariance += reference.varianceOfMean(x, y);
        }
    EXPECT_GT(referenceVariance, 0.0);
    EXPECT_NEAR(computedVariance / referenceVariance, 1.0, 0.05)
        << "the summed variance of the pixels' means: " << computedVariance << " against "
        << referenceVariance;
}

// Frames drawn in bands of one row (after the first band of eight): each band a dispatch of
// its own rows, which must land where the fragment kernel's scissored rows do.
TEST_F(ComputeKernel, FramesInBandsCoverEveryRowOnce)
{
    const scene::Scene scene = classicScene1();
    settings::RenderSettings banded = settings(settings::PathKernel::Compute);
    banded.secondsPerBand = 1e-9;
    settings::RenderSettings whole = settings(settings::PathKernel::Fragment);
    whole.secondsPerBand = 0.0;
    const RenderedImage computed = renderScene(scene, 37, 29, 4, banded);
    const RenderedImage reference = renderScene(scene, 37, 29, 4, whole);

    for (int y = 0; y < computed.height(); ++y)
        for (int x = 0; x < computed.width(); ++x)
            ASSERT_EQ(computed.accumulation.samplesTaken(x, y), 4.0f)
                << "pixel (" << x << ", " << y << ")";
    const Comparison comparison = compareImages(computed, reference);
    EXPECT_TRUE(comparison.passed()) << comparison.describe();
}

// The window's preview traces a coarse grid into the targets' lower-left corner.
TEST_F(ComputeKernel, APreviewFillsTheCornerTheFragmentKernelFills)
{
    const scene::Scene scene = classicScene1();
    render::ProgressiveRenderer compute(scene, 40, 30, settings(settings::PathKernel::Compute));
    render::ProgressiveRenderer fragment(scene, 40, 30, settings(settings::PathKernel::Fragment));
    compute.renderPreview(3, 2);
    fragment.renderPreview(3, 2);
    const film::Accumulation computed = compute.accumulation();
    const film::Accumulation reference = fragment.accumulation();
    int traced = 0;
    for (int y = 0; y < 30; ++y)
        for (int x = 0; x < 40; ++x) {
            ASSERT_EQ(computed.samplesTaken(x, y), reference.samplesTaken(x, y))
                << "pixel (" << x << ", " << y << ")";
            traced += reference.samplesTaken(x, y) > 0.0f;
        }
    EXPECT_EQ(traced, 14 * 10) << "the preview's 14 x 10 grid, and nothing else";
}

TEST_F(ComputeKernel, IsTheKernelTheRendererReportsWhenAskedFor)
{
    const render::ProgressiveRenderer renderer(classicScene1(), 8, 8,
                                               settings(settings::PathKernel::Compute));
    EXPECT_EQ(renderer.kernel().kernel, settings::PathKernel::Compute);
}

}  // namespace
}  // namespace render_tests
