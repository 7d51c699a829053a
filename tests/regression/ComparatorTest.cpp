// The comparison must catch regressions and must not fail on noise alone. Render-based
// cases perturb the scene of the mat_dielectric regression case (glass, a point light, the
// sky) the way a regression would and compare with its stored reference; synthetic cases
// check the statistic against distributions known exactly.
#include "support/ImageComparison.h"
#include "support/ReferenceImage.h"
#include "support/RegressionCases.h"
#include "support/RenderRun.h"

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <random>

namespace testing_support {
namespace {

// --- the threshold ---------------------------------------------------------------------

TEST(ComparisonThreshold, IsTheBernsteinBoundAtTheFalsePositiveRate)
{
    const int blocks = 768;
    const double cap = 16.0;
    const double rate = 1e-4;
    const double t = cappedZSquaredThreshold(blocks, cap, rate) - blocks;
    const double bound = std::exp(-(t * t / 2.0) / (blocks * (cap - 1.0) + cap * t / 3.0));
    EXPECT_NEAR(bound, rate, 1e-9) << "the threshold n + t should make Bernstein's bound "
                                      "exp(-(t^2/2) / (n (c - 1) + c t / 3)) equal the rate";
}

// --- synthetic images: pixels drawn from known distributions ---------------------------

// An image whose every pixel is the mean of `samples` draws of `draw`, with the statistics
// the renderer would report for it.
template <typename Draw>
RenderedImage syntheticImage(int width, int height, int samples, Draw draw, std::mt19937_64& rng)
{
    RenderedImage image;
    image.radiance = io::Image(width, height, 3);
    image.statistics = io::Image(width, height, 3);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            double sum = 0.0;
            double squares = 0.0;
            for (int i = 0; i < samples; ++i) {
                const double value = draw(x, y, rng);
                sum += value;
                squares += value * value;
            }
            const double mean = sum / samples;
            const double sampleVariance = (squares - samples * mean * mean) / (samples - 1);
            for (int c = 0; c < 3; ++c)
                image.radiance.at(x, y, c) = static_cast<float>(mean);
            image.statistics.at(x, y, 0) = static_cast<float>(samples);
            image.statistics.at(x, y, 2) = static_cast<float>(sampleVariance / samples);
        }
    return image;
}

// A firefly distribution: almost always 0.1, once in 5000 draws 500. Its mean (0.19998) is
// dominated by the rare draws, as in a caustic.
double fireflyDraw(int, int, std::mt19937_64& rng)
{
    return std::uniform_real_distribution<double>(0.0, 1.0)(rng) < 2e-4 ? 500.0 : 0.1;
}

TEST(ComparisonOfSyntheticImages, HeavyTailedNoiseAloneDoesNotFail)
{
    std::mt19937_64 rng(12345);
    const RenderedImage reference = syntheticImage(64, 48, 2048, fireflyDraw, rng);
    for (int trial = 0; trial < 8; ++trial) {
        const RenderedImage render = syntheticImage(64, 48, 64, fireflyDraw, rng);
        const Comparison comparison = compareImages(render, reference);
        EXPECT_TRUE(comparison.passed())
            << "trial " << trial << ": two estimates of one firefly-ridden image should agree\n"
            << comparison.describe();
    }
}

TEST(ComparisonOfSyntheticImages, SmallUniformBiasIsCaught)
{
    // Normal noise of standard deviation 1 per sample; the render is biased by 0.1 per pixel,
    // 1.6 standard deviations of a 2x2 block's difference at 64 and 2048 samples
    // (sqrt(4 (1/64 + 1/2048)) = 0.254).
    std::mt19937_64 rng(777);
    auto normal = [](double mean) {
        return [mean](int, int, std::mt19937_64& generator) {
            return mean + std::normal_distribution<double>(0.0, 1.0)(generator);
        };
    };
    const RenderedImage reference = syntheticImage(64, 48, 2048, normal(5.0), rng);
    const RenderedImage render = syntheticImage(64, 48, 64, normal(5.1), rng);
    const Comparison comparison = compareImages(render, reference);
    EXPECT_FALSE(comparison.passed())
        << "a bias of 0.1 (2% of the value) in every pixel should be reported\n"
        << comparison.describe();
}

// --- renders of a perturbed scene against the stored reference -------------------------

class PerturbedRender : public ::testing::Test {
protected:
    void SetUp() override
    {
        regressionCase_ = *findRegressionCase("mat_dielectric");
        ASSERT_NO_THROW(reference_ = readReference(referencePath(regressionCase_)))
            << "make the reference with tools/update-references.sh mat_dielectric";
        scene_ = loadScene(scenePath(regressionCase_));
    }

    RenderedImage render(const scene::Scene& scene, std::uint64_t seed = kTestSeed) const
    {
        return renderScene(scene, regressionCase_.width, regressionCase_.height,
                           regressionCase_.testSamplesPerPixel, settingsWithSeed(seed));
    }

    void expectReported(const RenderedImage& perturbed, const std::string& perturbation) const
    {
        const Comparison comparison = compareImages(perturbed, reference_);
        std::cout << perturbation << ":\n" << comparison.describe();
        EXPECT_FALSE(comparison.passed())
            << "the comparison should report a render with " << perturbation
            << " as different from the reference, but it found:\n"
            << comparison.describe();
    }

    RegressionCase regressionCase_;
    RenderedImage reference_;
    scene::Scene scene_;
};

TEST_F(PerturbedRender, DielectricRenderedAsMirrorIsReported)
{
    scene::Scene changed = scene_;
    ASSERT_EQ(changed.finishes[1].material(), scene::MaterialKind::Dielectric);
    changed.finishes[1].transmission = 0.0f;
    changed.finishes[1].reflection = 1.0f;
    expectReported(render(changed), "the glass sphere turned into a mirror");
}

TEST_F(PerturbedRender, PointLightMovedByFivePercentIsReported)
{
    scene::Scene changed = scene_;
    ASSERT_EQ(changed.pointLights.size(), 1u);
    // 5% further from the scene's centre (the origin): about 10% less light on the floor.
    changed.pointLights[0].position *= 1.05f;
    expectReported(render(changed), "the point light moved 5% further away");
}

TEST_F(PerturbedRender, RemovedEnvironmentIsReported)
{
    scene::Scene changed = scene_;
    changed.environment = {scene::EnvironmentKind::None, glm::vec3(0.0f)};
    expectReported(render(changed), "the sky removed");
}

TEST_F(PerturbedRender, OnePixelShiftIsReported)
{
    RenderedImage shifted = render(scene_);
    const RenderedImage original = shifted;
    // Every pixel takes its left neighbour's estimate and statistics; the first column
    // repeats.
    for (int y = 0; y < shifted.height(); ++y)
        for (int x = 1; x < shifted.width(); ++x)
            for (int c = 0; c < 3; ++c) {
                shifted.radiance.at(x, y, c) = original.radiance.at(x - 1, y, c);
                shifted.statistics.at(x, y, c) = original.statistics.at(x - 1, y, c);
            }
    expectReported(shifted, "the image shifted one pixel to the right");
}

TEST_F(PerturbedRender, RendersWithDifferentSeedsAgree)
{
    const RenderedImage first = render(scene_, kTestSeed);
    const RenderedImage second = render(scene_, kTestSeed + 1);
    const Comparison comparison = compareImages(first, second);
    std::cout << "seed " << kTestSeed << " against seed " << kTestSeed + 1 << ":\n"
              << comparison.describe();
    EXPECT_TRUE(comparison.passed())
        << "two renders of one scene that differ only in their seeds should agree, but:\n"
        << comparison.describe();
}

}  // namespace
}  // namespace testing_support
