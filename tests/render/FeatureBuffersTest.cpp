// Feature buffers (--feature-buffers, film/Accumulation.h): each pixel's mean first-hit
// albedo, world-space normal and camera distance, against closed forms; carried by a resume
// and a merge; the same from both kernels; and Open Image Denoise, guided by them, bringing a
// noisy render nearer a converged one (skipped where the library is not installed).
#include "film/Denoiser.h"
#include "render/KernelChoice.h"
#include "render/ProgressiveRenderer.h"
#include "support/PinholeCamera.h"
#include "support/RenderRun.h"
#include "support/TestPaths.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <optional>

namespace render_tests {
namespace {

using namespace testing_support;

constexpr int kWidth = 48;
constexpr int kHeight = 36;

settings::RenderSettings withFeatures(std::uint64_t seed)
{
    settings::RenderSettings settings = settingsWithSeed(seed);
    settings.featureBuffers = true;
    return settings;
}

// A Lambertian floor y <= 0 of pigment (0.3, 0.5, 0.7), filling the view, under a point light.
scene::Scene lambertianFloor()
{
    return sceneFromText("0 3 0\n0 0 -3\n0 1 0\n40\n1\n0 4 0 5 5 5\n1 solid 0.3 0.5 0.7\n"
                         "1 0 0 0  0 0 0 1\n1\n0 0 polyhedron 1  0 1 0 0\n");
}

// A unit sphere at the origin seen from (0, 0, 4) against the sky.
scene::Scene unitSphere()
{
    return sceneFromText("0 0 4\n0 0 0\n0 1 0\n40\n0\n1 solid 0.8 0.8 0.8\n"
                         "1 0 0 0  0 0 0 1\n1\n0 0 sphere 0 0 0 1\n");
}

// Distance along the unit `direction` from `eye` to the unit sphere at the origin, if it hits.
std::optional<double> sphereDistance(const glm::dvec3& eye, const glm::dvec3& direction)
{
    const double b = glm::dot(eye, direction);
    const double c = glm::dot(eye, eye) - 1.0;
    const double discriminant = b * b - c;
    if (discriminant <= 0.0)
        return std::nullopt;
    const double t = -b - std::sqrt(discriminant);
    return t > 0.0 ? std::optional<double>(t) : std::nullopt;
}

TEST(FeatureBuffers, AlbedoOfALambertianPlaneIsItsPigmentAndItsNormalAndDepthTheClosedForm)
{
    const scene::Scene scene = lambertianFloor();
    const RenderedImage image = renderScene(scene, kWidth, kHeight, 8, withFeatures(3));
    const film::Accumulation& features = image.accumulation;
    ASSERT_TRUE(features.hasFeatures());
    const PinholeCamera camera(scene.camera, kWidth, kHeight);
    const double pigment[3] = {0.3, 0.5, 0.7};
    double worstAlbedo = 0.0;
    double worstNormal = 0.0;
    double worstDepth = 0.0;  // relative
    int compared = 0;
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x) {
            // Every ray of the pixel meets the floor (y = 0) at t = -eye.y / d.y.
            const auto hits = [&](const glm::dvec3& d) { return d.y < -1e-3; };
            if (!camera.wholePixel(x, y, hits))
                continue;
            ++compared;
            for (int c = 0; c < 3; ++c)
                worstAlbedo =
                    std::max(worstAlbedo, std::abs(features.albedoDepth.at(x, y, c) - pigment[c]));
            worstNormal =
                std::max({worstNormal, std::abs(double(features.normalCoverage.at(x, y, 0))),
                          std::abs(features.normalCoverage.at(x, y, 1) - 1.0),
                          std::abs(double(features.normalCoverage.at(x, y, 2)))});
            EXPECT_EQ(features.normalCoverage.at(x, y, 3), 1.0f) << "every sample hits";
            const double expected = camera.pixelAverage(
                x, y, 8, [&](const glm::dvec3& d) { return -camera.eye().y / d.y; });
            worstDepth = std::max(worstDepth,
                                  std::abs(features.albedoDepth.at(x, y, 3) - expected) / expected);
        }
    std::printf("plane: %d pixels, worst albedo %.3g, normal %.3g, relative depth %.3g\n", compared,
                worstAlbedo, worstNormal, worstDepth);
    EXPECT_GT(compared, kWidth * kHeight / 2);
    EXPECT_LT(worstAlbedo, 1e-5) << "the albedo is the pigment, whatever the lighting";
    EXPECT_LT(worstNormal, 1e-5) << "the floor's normal is (0, 1, 0)";
    // 8 jittered samples against the pixel's mean distance, which varies across a pixel by
    // up to about 1 %, the far rows' most (measured: 0.11 % at worst).
    EXPECT_LT(worstDepth, 0.003) << "the camera distance is -eye.y / d.y";
}

TEST(FeatureBuffers, NormalsOfASphereAreTheClosedForm)
{
    const scene::Scene scene = unitSphere();
    const RenderedImage image = renderScene(scene, kWidth, kHeight, 16, withFeatures(5));
    const film::Accumulation& features = image.accumulation;
    const PinholeCamera camera(scene.camera, kWidth, kHeight);
    const glm::dvec3 eye = camera.eye();
    double worstNormal = 0.0;
    double worstDepth = 0.0;
    int onSphere = 0;
    int offSphere = 0;
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x) {
            const auto hits = [&](const glm::dvec3& d) {
                return sphereDistance(eye, d).has_value();
            };
            const auto misses = [&](const glm::dvec3& d) { return !hits(d); };
            if (camera.wholePixel(x, y, misses)) {
                ++offSphere;
                EXPECT_EQ(features.normalCoverage.at(x, y, 3), 0.0f);
                for (int c = 0; c < 3; ++c)
                    EXPECT_EQ(features.normalCoverage.at(x, y, c), 0.0f) << "no surface, no normal";
                continue;
            }
            if (!camera.wholePixel(x, y, hits))
                continue;
            ++onSphere;
            for (int c = 0; c < 3; ++c) {
                // The normal at the hit is the hit point itself; its mean over the pixel.
                const double expected = camera.pixelAverage(x, y, 8, [&](const glm::dvec3& d) {
                    return (eye + *sphereDistance(eye, d) * d)[c];
                });
                worstNormal =
                    std::max(worstNormal, std::abs(features.normalCoverage.at(x, y, c) - expected));
            }
            const double depth = camera.pixelAverage(
                x, y, 8, [&](const glm::dvec3& d) { return *sphereDistance(eye, d); });
            worstDepth =
                std::max(worstDepth, std::abs(features.albedoDepth.at(x, y, 3) - depth) / depth);
        }
    std::printf("sphere: %d pixels on it, %d off; worst normal %.3g, relative depth %.3g\n",
                onSphere, offSphere, worstNormal, worstDepth);
    EXPECT_GT(onSphere, 100);
    EXPECT_GT(offSphere, 100);
    // 16 jittered samples of a normal that turns by up to about 0.1 across a rim pixel
    // (measured: 0.002 at worst, 0.06 % in depth).
    EXPECT_LT(worstNormal, 0.006) << "the normal of the unit sphere at p is p";
    EXPECT_LT(worstDepth, 0.003);
}

TEST(FeatureBuffers, AreNotKeptUnlessAsked)
{
    const RenderedImage image = renderScene(unitSphere(), 16, 12, 1, settingsWithSeed(5));
    EXPECT_FALSE(image.accumulation.hasFeatures());
}

// The means of two shards' features, merged, are those of one render of all their samples:
// within the noise of the features that vary from sample to sample (glass, mirrors and the
// textures of scene 1).
TEST(FeatureBuffers, MergeOfTwoShardsMatchesOneRenderWithinNoise)
{
    const scene::Scene scene = loadScene(sourceDirectory() / "scenes" / "scene1.in");
    const RenderedImage first = renderScene(scene, kWidth, kHeight, 16, withFeatures(1));
    const RenderedImage second = renderScene(scene, kWidth, kHeight, 16, withFeatures(2));
    const RenderedImage whole = renderScene(scene, kWidth, kHeight, 32, withFeatures(3));
    const film::Accumulation merged =
        film::combineAccumulations({&first.accumulation, &second.accumulation});
    ASSERT_TRUE(merged.hasFeatures());
    // Mean absolute difference per channel over the image, merged against whole; and, for
    // scale, one shard against the other (twice the noise of 16 samples against 32).
    double mergedDifference[8] = {};
    double shardDifference[8] = {};
    const auto channel = [](const film::Accumulation& a, int x, int y, int c) {
        return c < 4 ? a.albedoDepth.at(x, y, c) : a.normalCoverage.at(x, y, c - 4);
    };
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x)
            for (int c = 0; c < 8; ++c) {
                mergedDifference[c] +=
                    std::abs(channel(merged, x, y, c) - channel(whole.accumulation, x, y, c));
                shardDifference[c] += std::abs(channel(first.accumulation, x, y, c) -
                                               channel(second.accumulation, x, y, c));
            }
    const char* names[8] = {"albedo.R", "albedo.G", "albedo.B", "Z",
                            "N.X",      "N.Y",      "N.Z",      "coverage"};
    // 32 samples against 32 differ by sqrt(2) sigma_32; 16 against 16 by sqrt(2) sigma_16,
    // sqrt(2) times more: the ratio of the two is about 0.71 where the merge is right.
    for (int c = 0; c < 8; ++c) {
        const double ratio = mergedDifference[c] / std::max(shardDifference[c], 1e-9);
        std::printf("%-9s merged-whole %.5f, shard-shard %.5f (mean per pixel), ratio %.3f\n",
                    names[c], mergedDifference[c] / (kWidth * kHeight),
                    shardDifference[c] / (kWidth * kHeight), ratio);
        EXPECT_LT(ratio, 0.9) << names[c]
                              << ": the merge must be as near one render of all its samples as "
                                 "32 samples are to 32 others";
    }
}

TEST(FeatureBuffers, ResumeGoesOnAsTheRenderThatNeverStopped)
{
    const scene::Scene scene = loadScene(sourceDirectory() / "scenes" / "scene1.in");
    const settings::RenderSettings settings = withFeatures(21);
    const RenderedImage whole = renderScene(scene, 32, 24, 6, settings);
    const RenderedImage first = renderScene(scene, 32, 24, 2, settings);
    render::ProgressiveRenderer second(scene, 32, 24, settings);
    second.resumeFrom(first.accumulation);
    while (second.samplesPerPixel() < 6)
        second.renderFrame({}, 2);
    second.completeSamples();
    const film::Accumulation resumed = second.accumulation();
    int differing = 0;
    for (std::size_t i = 0; i < resumed.albedoDepth.pixels.size(); ++i)
        differing +=
            (resumed.albedoDepth.pixels[i] != whole.accumulation.albedoDepth.pixels[i]) +
            (resumed.normalCoverage.pixels[i] != whole.accumulation.normalCoverage.pixels[i]);
    EXPECT_EQ(differing, 0) << "the features must be those of the render that never stopped";

    render::ProgressiveRenderer withoutFeatures(scene, 32, 24, settingsWithSeed(21));
    EXPECT_THROW(withoutFeatures.resumeFrom(first.accumulation), std::invalid_argument);
}

TEST(FeatureBuffers, TheComputeKernelKeepsTheSameFeatures)
{
    if (!render::computeKernelAvailable())
        GTEST_SKIP() << "this context has no compute shaders (OpenGL 4.3)";
    const scene::Scene scene = loadScene(sourceDirectory() / "scenes" / "scene1.in");
    settings::RenderSettings compute = withFeatures(11);
    settings::RenderSettings fragment = withFeatures(11);
    compute.kernel = settings::PathKernel::Compute;
    fragment.kernel = settings::PathKernel::Fragment;
    compute.secondsPerBand = fragment.secondsPerBand = 0.0;
    const RenderedImage computed = renderScene(scene, 32, 24, 4, compute);
    const RenderedImage reference = renderScene(scene, 32, 24, 4, fragment);
    double difference = 0.0;
    for (std::size_t i = 0; i < reference.accumulation.albedoDepth.pixels.size(); ++i)
        difference += std::abs(computed.accumulation.albedoDepth.pixels[i] -
                               reference.accumulation.albedoDepth.pixels[i]) +
                      std::abs(computed.accumulation.normalCoverage.pixels[i] -
                               reference.accumulation.normalCoverage.pixels[i]);
    EXPECT_LT(difference / reference.accumulation.albedoDepth.pixels.size(), 1e-3);
}

double relativeRmse(const io::Image& image, const io::Image& reference)
{
    double error = 0.0;
    double energy = 0.0;
    for (int y = 0; y < reference.height; ++y)
        for (int x = 0; x < reference.width; ++x)
            for (int c = 0; c < 3; ++c) {
                const double d = image.at(x, y, c) - reference.at(x, y, c);
                error += d * d;
                energy += reference.at(x, y, c) * reference.at(x, y, c);
            }
    return std::sqrt(error / energy);
}

io::Image rgbOf(const io::Image& rgba)
{
    io::Image rgb(rgba.width, rgba.height, 3);
    for (int y = 0; y < rgba.height; ++y)
        for (int x = 0; x < rgba.width; ++x)
            for (int c = 0; c < 3; ++c)
                rgb.at(x, y, c) = rgba.at(x, y, c);
    return rgb;
}

TEST(FeatureBuffers, OpenImageDenoiseBringsANoisyRenderNearerTheConvergedOne)
{
    if (!film::denoiserAvailable()) {
        try {
            film::denoiserLibrary();
        } catch (const film::DenoiserUnavailable& error) {
            GTEST_SKIP() << error.what();
        }
    }
    const scene::Scene scene = loadScene(sourceDirectory() / "scenes" / "scene3.in");
    const RenderedImage noisy = renderScene(scene, 64, 48, 4, withFeatures(1));
    const RenderedImage converged = renderScene(scene, 64, 48, 256, settingsWithSeed(2));
    const film::Accumulation& a = noisy.accumulation;
    const io::Image denoised =
        film::denoiseImage(noisy.radiance, rgbOf(a.albedoDepth), rgbOf(a.normalCoverage));
    const double raw = relativeRmse(noisy.radiance, converged.radiance);
    const double after = relativeRmse(denoised, converged.radiance);
    EXPECT_LT(after, 0.7 * raw) << "relative RMSE " << raw << " raw, " << after << " denoised ("
                                << film::denoiserLibrary() << ")";
}

// The window's à-trous filter (render/PreviewDenoiser.h): nearer the converged image than the
// noisy one it filters, and never in what is written (toneMapped).
TEST(PreviewDenoiser, BringsANoisyRenderNearerTheConvergedOneAndStaysOutOfTheFiles)
{
    const scene::Scene scene = loadScene(sourceDirectory() / "scenes" / "scene3.in");
    render::ProgressiveRenderer renderer(scene, 64, 48, withFeatures(1));
    for (int frame = 0; frame < 4; ++frame)
        renderer.renderFrame({}, 1);
    renderer.completeSamples();
    const io::Image picture = renderer.toneMapped();
    renderer.setPreviewDenoising(true);
    const io::Image filtered = renderer.previewDenoisedRadiance();
    EXPECT_EQ(renderer.toneMapped().pixels, picture.pixels) << "display only";
    const RenderedImage converged = renderScene(scene, 64, 48, 256, settingsWithSeed(2));
    const double raw = relativeRmse(renderer.radiance(), converged.radiance);
    const double after = relativeRmse(filtered, converged.radiance);
    std::printf("preview denoiser: relative RMSE %.3f raw, %.3f filtered\n", raw, after);
    EXPECT_LT(after, 0.7 * raw);

    render::ProgressiveRenderer withoutFeatures(scene, 16, 12, settingsWithSeed(1));
    EXPECT_FALSE(withoutFeatures.canPreviewDenoise());
    EXPECT_THROW(withoutFeatures.previewDenoisedRadiance(), std::logic_error);
}

}  // namespace
}  // namespace render_tests
