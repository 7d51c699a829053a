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

// A shard of `seed` holding that seed's sample indices from `firstIndex` to `lastIndex` - 1
// and none before: resumed from an accumulation whose pixels hold `firstIndex` samples, all
// discarded (so each pixel's next index is firstIndex, film/Accumulation.h), with nothing
// kept, so that the means and moments are those of the new samples alone.
film::Accumulation shardOfIndices(const scene::Scene& scene, int width, int height,
                                  std::uint64_t seed, int firstIndex, int lastIndex)
{
    film::Accumulation skipped(width, height);
    skipped.addEmptyFeatures();
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x)
            skipped.moments.at(x, y, 3) = static_cast<float>(firstIndex);
    render::ProgressiveRenderer renderer(scene, width, height, withFeatures(seed));
    renderer.resumeFrom(skipped);
    while (renderer.samplesPerPixel() < lastIndex)
        renderer.renderFrame({}, lastIndex - renderer.samplesPerPixel());
    renderer.completeSamples();
    return renderer.accumulation();
}

// Two shards of one seed holding disjoint index ranges, 0 to 7 and 8 to 31 (unequal, so
// that weights swapped show), merged, hold exactly the samples of one render of indices 0
// to 31: every mean, feature and count must be that render's to float rounding (the GPU's
// running means against the merge's double-precision combination), pixel by pixel. Returns
// the worst pixel's difference per channel, relative, with the worst difference of the two
// shards beside it, for scale.
struct MergeDifferences {
    static constexpr int kChannels = 14;
    // 0-2 radiance, 3-5 its M2, 6-8 albedo, 9 depth, 10-12 normal, 13 coverage.
    static constexpr const char* kNames[kChannels] = {
        "radiance.R", "radiance.G", "radiance.B", "M2.R", "M2.G", "M2.B", "albedo.R",
        "albedo.G",   "albedo.B",   "Z",          "N.X",  "N.Y",  "N.Z",  "coverage"};
    double mergedWhole[kChannels] = {};
    double shardShard[kChannels] = {};
    int countMismatches = 0;
};

MergeDifferences mergeOfDisjointShardsAgainstWhole(const scene::Scene& scene, std::uint64_t seed)
{
    constexpr int kFirst = 8;
    constexpr int kAll = 32;
    const film::Accumulation first =
        renderScene(scene, kWidth, kHeight, kFirst, withFeatures(seed)).accumulation;
    const film::Accumulation second = shardOfIndices(scene, kWidth, kHeight, seed, kFirst, kAll);
    const film::Accumulation whole =
        renderScene(scene, kWidth, kHeight, kAll, withFeatures(seed)).accumulation;
    const film::Accumulation merged = film::combineAccumulations({&first, &second});
    MergeDifferences result;
    if (!merged.hasFeatures()) {
        ++result.countMismatches;
        return result;
    }
    const auto channel = [](const film::Accumulation& a, int x, int y, int c) -> double {
        if (c < 3)
            return a.estimate.at(x, y, c);
        if (c < 6)
            return a.moments.at(x, y, c - 3);
        if (c < 10)
            return a.albedoDepth.at(x, y, c - 6);
        return a.normalCoverage.at(x, y, c - 10);
    };
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x) {
            // Samples kept add up to the whole's, discarded to the whole's plus the skipped;
            // the first shard holds indices 0 to 7 in every pixel.
            result.countMismatches +=
                (merged.samplesKept(x, y) != whole.samplesKept(x, y)) +
                (merged.samplesDiscarded(x, y) != whole.samplesDiscarded(x, y) + kFirst) +
                (first.samplesTaken(x, y) != kFirst);
            for (int c = 0; c < MergeDifferences::kChannels; ++c) {
                const double wholeValue = channel(whole, x, y, c);
                // Rounding is relative to the magnitude: of a mean, or for M2 of the sum of
                // squares it is the difference of (n mean^2 + M2).
                double scale = std::max(1.0, std::abs(wholeValue));
                if (c >= 3 && c < 6) {
                    const double mean = whole.estimate.at(x, y, c - 3);
                    scale = std::max(1.0, wholeValue + whole.samplesKept(x, y) * mean * mean);
                }
                result.mergedWhole[c] = std::max(
                    result.mergedWhole[c], std::abs(channel(merged, x, y, c) - wholeValue) / scale);
                result.shardShard[c] =
                    std::max(result.shardShard[c],
                             std::abs(channel(first, x, y, c) - channel(second, x, y, c)) / scale);
            }
        }
    return result;
}

// Scene 1 (glass, mirrors and textures: features that vary from sample to sample, and every
// pixel covered) and a sphere against the sky (its rim pixels partly covered, where the
// depths combine weighted by the samples that hit).
TEST(FeatureBuffers, MergeOfTwoShardsOfDisjointSamplesIsTheRenderOfAllOfThem)
{
    const std::pair<const char*, scene::Scene> scenes[] = {
        {"scene1", loadScene(sourceDirectory() / "scenes" / "scene1.in")},
        {"sphere", unitSphere()}};
    for (const auto& [name, scene] : scenes) {
        const MergeDifferences differences = mergeOfDisjointShardsAgainstWhole(scene, 7);
        EXPECT_EQ(differences.countMismatches, 0) << name << ": sample counts";
        for (int c = 0; c < MergeDifferences::kChannels; ++c) {
            std::printf("%-6s %-10s worst pixel: merged-whole %.3g, shard-shard %.3g (relative)\n",
                        name, MergeDifferences::kNames[c], differences.mergedWhole[c],
                        differences.shardShard[c]);
            // Float rounding of 32 running-mean steps (measured: 4.5e-7 at worst); the
            // shards differ by 0.1 to 4 where the channel varies.
            EXPECT_LT(differences.mergedWhole[c], 4e-6)
                << name << " " << MergeDifferences::kNames[c]
                << ": the merge of disjoint samples must be the render of all of them, pixel "
                   "by pixel";
        }
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
