// Image regression: every case of support/RegressionCases.cpp is rendered at a modest sample
// count with a seed of its own and compared with its reference by the noise-aware
// comparison (support/ImageComparison.h, derived in tests/README.md). On failure the
// side-by-side picture is written into the build tree and its path printed.
#include "render/KernelChoice.h"
#include "support/ImageComparison.h"
#include "support/ReferenceImage.h"
#include "support/RegressionCases.h"
#include "support/RenderRun.h"
#include "support/SideBySide.h"
#include "support/TestPaths.h"

#include <gtest/gtest.h>

#include <iostream>

namespace testing_support {

// Test names in ctest show the case's name rather than its bytes (found by argument-dependent
// lookup, so it lives in RegressionCase's namespace).
void PrintTo(const RegressionCase& regressionCase, std::ostream* out)
{
    *out << regressionCase.name;
}

namespace {

void expectAgreesWithReference(const RegressionCase& regressionCase,
                               const settings::RenderSettings& settings, const std::string& label)
{
    RenderedImage reference;
    ASSERT_NO_THROW(reference = readReference(referencePath(regressionCase)))
        << "the reference of " << regressionCase.name << " is missing or unreadable: make it "
        << "with tools/update-references.sh " << regressionCase.name;
    ASSERT_EQ(reference.width(), regressionCase.width);
    ASSERT_EQ(reference.height(), regressionCase.height);

    const RenderedImage render =
        renderScene(loadScene(scenePath(regressionCase)), regressionCase.width,
                    regressionCase.height, regressionCase.testSamplesPerPixel, settings);
    const Comparison comparison = compareImages(render, reference);
    std::cout << regressionCase.name << " (" << label << " shader):\n" << comparison.describe();

    if (comparison.passed())
        return;
    const auto picture =
        writeSideBySide(failureDirectory() / (regressionCase.name + "-" + label + ".png"),
                        reference, render, comparison, ComparisonSettings{}.blockSize);
    ADD_FAILURE() << regressionCase.feature << ": the render (" << label << " shader, "
                  << regressionCase.testSamplesPerPixel << " spp, seed " << settings.seed
                  << ") is expected to agree with " << referencePath(regressionCase).string()
                  << " within noise, but it differs:\n"
                  << comparison.describe() << "reference | render | |difference| x"
                  << kDifferenceMagnification << " | z per block: " << picture.string();
}

std::string caseName(const ::testing::TestParamInfo<RegressionCase>& info)
{
    return info.param.name;
}

class ImageRegression : public ::testing::TestWithParam<RegressionCase> {};

TEST_P(ImageRegression, RenderAgreesWithReference)
{
    expectAgreesWithReference(GetParam(), settingsWithSeed(kTestSeed), "specialized");
}

INSTANTIATE_TEST_SUITE_P(Case, ImageRegression, ::testing::ValuesIn(regressionCases()), caseName);

// The general shader (every feature, shapes interpreted from uniforms) must converge to the
// same image as the specialised one the references were made with. It runs many times
// slower on llvmpipe, so these cases render 16 samples; the threshold accounts for that.
class GeneralShaderRegression : public ::testing::TestWithParam<RegressionCase> {};

TEST_P(GeneralShaderRegression, GeneralShaderAgreesWithReference)
{
    settings::RenderSettings settings = settingsWithSeed(kTestSeed);
    settings.variant = settings::ShaderVariant::General;
    expectAgreesWithReference(GetParam(), settings, "general");
}

std::vector<RegressionCase> casesForGeneralShader()
{
    std::vector<RegressionCase> cases;
    for (const char* name : {"scene5", "prim_user_sdf", "csg_smooth_union_poly",
                             "csg_smooth_difference_exp", "xf_rotate", "tex_image"}) {
        RegressionCase regressionCase = *findRegressionCase(name);
        regressionCase.testSamplesPerPixel = 16;
        cases.push_back(regressionCase);
    }
    return cases;
}

INSTANTIATE_TEST_SUITE_P(Case, GeneralShaderRegression,
                         ::testing::ValuesIn(casesForGeneralShader()), caseName);

// The compute kernel runs the fragment kernel's per-pixel code (render/PathKernel.h): on the
// seven classic scenes, the ones its speed is measured on, it must agree with the same
// references. Skipped where the context has no compute shaders (OpenGL 4.3).
class ComputeKernelRegression : public ::testing::TestWithParam<RegressionCase> {};

TEST_P(ComputeKernelRegression, ComputeKernelAgreesWithReference)
{
    if (!render::computeKernelAvailable())
        GTEST_SKIP() << "this context has no compute shaders (OpenGL 4.3)";
    settings::RenderSettings settings = settingsWithSeed(kTestSeed);
    settings.kernel = settings::PathKernel::Compute;
    expectAgreesWithReference(GetParam(), settings, "compute-kernel");
}

std::vector<RegressionCase> classicCases()
{
    std::vector<RegressionCase> cases;
    for (int scene = 1; scene <= 7; ++scene)
        cases.push_back(*findRegressionCase("scene" + std::to_string(scene)));
    return cases;
}

INSTANTIATE_TEST_SUITE_P(Case, ComputeKernelRegression, ::testing::ValuesIn(classicCases()),
                         caseName);

}  // namespace
}  // namespace testing_support
