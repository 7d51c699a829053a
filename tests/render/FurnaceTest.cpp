// White furnaces (pbrt's test of energy conservation): a sphere under a constant environment
// of radiance 1 and nothing else. A surface that reflects all it receives vanishes (every
// pixel 1); one of albedo a shows a; none may ever show more than 1.
#include "support/PinholeCamera.h"
#include "support/RenderRun.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <sstream>

namespace render_tests {
namespace {

using namespace testing_support;

constexpr int kWidth = 64;
constexpr int kHeight = 48;

// A sphere of radius 1 at the origin seen from z = 4, alone under environment 1 1 1.
scene::Scene furnace(const std::string& pigment, const std::string& finish)
{
    return sceneFromText("environment 1 1 1\n0 0 4\n0 0 0\n0 1 0\n40\n0\n1\nsolid " + pigment +
                         "\n1\n" + finish + "\n1\n0 0 sphere 0 0 0 1\n");
}

const glm::dvec3 kCenter(0.0);
constexpr double kRadius = 1.0;

// Pixels wholly on the sphere, a little inside its silhouette (where grazing rays may take
// the tilted facing normal).
bool onSphere(const PinholeCamera& camera, int x, int y)
{
    return camera.wholePixel(x, y, [&](const glm::dvec3& direction) {
        return raySphere(glm::dvec3(camera.eye()), direction, kCenter, kRadius * 0.97) > 0.0;
    });
}

// The largest |pixel - expected| over the pixels `select` picks, and where.
struct Deviation {
    double largest = 0.0;
    int x = -1;
    int y = -1;
    int pixels = 0;
    std::string describe() const
    {
        std::ostringstream text;
        text << "largest deviation " << largest << " at pixel (" << x << ", " << y << ") of "
             << pixels << " pixels";
        return text.str();
    }
};

template <typename Select>
Deviation deviationFrom(const RenderedImage& image, double expected, Select select)
{
    Deviation deviation;
    for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < image.width(); ++x) {
            if (!select(x, y))
                continue;
            ++deviation.pixels;
            for (int c = 0; c < 3; ++c) {
                const double difference = std::abs(image.radiance.at(x, y, c) - expected);
                if (!(difference <= deviation.largest)) {
                    deviation.largest = difference;
                    deviation.x = x;
                    deviation.y = y;
                }
            }
        }
    return deviation;
}

TEST(WhiteFurnace, LambertianSphereOfAlbedoOneVanishes)
{
    const RenderedImage image =
        renderScene(furnace("1 1 1", "0 0 0  0 0 0 0"), kWidth, kHeight, 16, settingsWithSeed(3));
    const Deviation deviation = deviationFrom(image, 1.0, [](int, int) { return true; });
    EXPECT_LE(deviation.largest, 1e-4)
        << "every pixel should be exactly 1 (environment 1, albedo 1); " << deviation.describe();
    EXPECT_EQ(image.discardedSamples, 0u);
}

TEST(WhiteFurnace, LambertianSphereOfAlbedoHalfShowsHalf)
{
    const scene::Scene scene = furnace("0.5 0.5 0.5", "0 0 0  0 0 0 0");
    const RenderedImage image = renderScene(scene, kWidth, kHeight, 16, settingsWithSeed(3));
    const PinholeCamera camera(scene.camera, kWidth, kHeight);
    const Deviation deviation =
        deviationFrom(image, 0.5, [&](int x, int y) { return onSphere(camera, x, y); });
    ASSERT_GT(deviation.pixels, 300);
    EXPECT_LE(deviation.largest, 1e-4)
        << "every pixel on the sphere should be 0.5 (one bounce of albedo 0.5, then the "
        << "environment 1); " << deviation.describe();
}

TEST(WhiteFurnace, MirrorSphereVanishes)
{
    // R0 = 1 makes Schlick's Fresnel 1 at every angle: a perfect mirror.
    const RenderedImage image =
        renderScene(furnace("1 1 1", "0 0 0  0 1 0 0"), kWidth, kHeight, 8, settingsWithSeed(3));
    const Deviation deviation = deviationFrom(image, 1.0, [](int, int) { return true; });
    EXPECT_LE(deviation.largest, 1e-4)
        << "every pixel should be exactly 1; " << deviation.describe();
}

// Pigment 1 makes Schlick's Fresnel 1, so only the glossy lobe is sampled; its sample weight
// cos_i / max(cos_i, cos_o) is at most 1, so every sample, and every pixel, is at most 1.
class BlinnPhongFurnace : public ::testing::TestWithParam<int> {};

TEST_P(BlinnPhongFurnace, SphereIsNeverBrighterThanTheFurnace)
{
    const int exponent = GetParam();
    const RenderedImage image =
        renderScene(furnace("1 1 1", "0 0 0  " + std::to_string(exponent) + " 0 0 0"), kWidth,
                    kHeight, 32, settingsWithSeed(5));
    double brightest = 0.0;
    for (float value : image.radiance.pixels)
        brightest = std::max(brightest, static_cast<double>(value));
    EXPECT_LE(brightest, 1.0 + 1e-4)
        << "a Blinn-Phong sphere (exponent " << exponent << ") in a furnace of radiance 1 "
        << "should reflect at most 1; the brightest pixel is " << brightest;
}

INSTANTIATE_TEST_SUITE_P(Exponent, BlinnPhongFurnace, ::testing::Values(1, 20, 500),
                         [](const ::testing::TestParamInfo<int>& info) {
                             return "n" + std::to_string(info.param);
                         });

TEST(WhiteFurnace, SharpBlinnPhongSphereReflectsNearlyAllAtNormalIncidence)
{
    // At normal incidence the sample weight is cos(theta_i) = 2 cos^2(theta_h) - 1, and with
    // cos(theta_h) = u^(1 / (n + 1)) its mean is (n - 1) / (n + 3): 0.996 for n = 1000. Within
    // 5 degrees of normal incidence, where wi may fall further from the normal than wo, the
    // weight cos_i / cos_o loses a little more (about tan(5 degrees) times the lobe's width,
    // 0.2%). The centre of the sphere must show at least 0.99.
    const scene::Scene scene = furnace("1 1 1", "0 0 0  1000 0 0 0");
    const RenderedImage image = renderScene(scene, kWidth, kHeight, 64, settingsWithSeed(5));
    const PinholeCamera camera(scene.camera, kWidth, kHeight);
    double darkest = 2.0;
    int pixels = 0;
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x) {
            // Within 5 degrees of normal incidence: every ray of the pixel meets the sphere
            // within sin(5 degrees) of the centre line.
            const bool nearNormal = camera.wholePixel(x, y, [&](const glm::dvec3& direction) {
                const glm::dvec3 toCenter = kCenter - glm::dvec3(camera.eye());
                return glm::length(glm::cross(toCenter, direction)) <
                       kRadius * std::sin(glm::radians(5.0));
            });
            if (!nearNormal)
                continue;
            ++pixels;
            darkest = std::min(darkest, static_cast<double>(channelMean(image.radiance, x, y)));
        }
    ASSERT_GE(pixels, 4);
    EXPECT_GE(darkest, 0.99) << "the centre of a sharp Blinn-Phong sphere should reflect "
                                "nearly all of the furnace; its darkest pixel is "
                             << darkest;
}

// The mixture of the glossy lobe and the diffuse base (pigment 0.6: Fresnel between 0.6 and
// 1) weighs samples by the mixture's pdf, so single samples may exceed 1 but their mean may
// not. Tested per 4x4 block with the renderer's variance: no block above 1 + 5 sigma.
TEST(WhiteFurnace, BlinnPhongMixtureSphereIsNeverBrighterThanTheFurnace)
{
    const RenderedImage image = renderScene(furnace("0.6 0.6 0.6", "0 0 0  50 0 0 0"), kWidth,
                                            kHeight, 64, settingsWithSeed(5));
    double worstZ = -1e9;
    for (int by = 0; by < kHeight; by += 4)
        for (int bx = 0; bx < kWidth; bx += 4) {
            double sum = 0.0;
            double variance = 0.0;
            for (int y = by; y < by + 4; ++y)
                for (int x = bx; x < bx + 4; ++x) {
                    sum += channelMean(image.radiance, x, y);
                    variance += image.varianceOfMean(x, y);
                }
            const double excess = sum / 16.0 - 1.0;
            const double sigma = std::sqrt(variance) / 16.0 + 1e-6;
            worstZ = std::max(worstZ, excess / sigma);
        }
    EXPECT_LE(worstZ, 5.0) << "some 4x4 block is brighter than the furnace by " << worstZ
                           << " standard deviations";
}

TEST(WhiteFurnace, DielectricSphereCreatesNoEnergyAndLosesAlmostNone)
{
    // Glass of index 1.5 with pigment 1: Fresnel splits, refraction scales radiance by the
    // squared index ratio, and the two scalings cancel on the way out. What leaves after 16
    // scattering events is lost, a negligible part for a sphere.
    const scene::Scene scene = furnace("1 1 1", "0 0 0  0 0 1 1.5");
    const RenderedImage image = renderScene(scene, kWidth, kHeight, 128, settingsWithSeed(9));
    const PinholeCamera camera(scene.camera, kWidth, kHeight);
    double sum = 0.0;
    double variance = 0.0;
    int pixels = 0;
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x) {
            if (!onSphere(camera, x, y))
                continue;
            sum += channelMean(image.radiance, x, y);
            variance += image.varianceOfMean(x, y);
            ++pixels;
        }
    ASSERT_GT(pixels, 300);
    const double mean = sum / pixels;
    // Most paths enter, leave and weigh exactly 1 (1/1.5^2 in, 1.5^2 out): the noise is tiny
    // and float rounding of the weights (1e-6) matters as much.
    const double sigma = std::sqrt(variance) / pixels + 1e-5;
    EXPECT_LE(mean, 1.0 + 5.0 * sigma)
        << "the glass sphere's pixels average " << mean << " (+- " << sigma
        << "): glass in a furnace of radiance 1 must not create energy";
    EXPECT_GE(mean, 1.0 - 5.0 * sigma - 2e-3)
        << "the glass sphere's pixels average " << mean << " (+- " << sigma
        << "): clear glass in a furnace should look like the furnace";
    EXPECT_EQ(image.discardedSamples, 0u);
}

// --- the rough materials (GGX) --------------------------------------------------------------

// The mean of the sphere's whole pixels and one standard deviation of it.
struct SphereMean {
    double mean = 0.0;
    double sigma = 0.0;
    int pixels = 0;
};

SphereMean meanOnSphere(const scene::Scene& scene, const RenderedImage& image)
{
    const PinholeCamera camera(scene.camera, kWidth, kHeight);
    SphereMean result;
    double sum = 0.0;
    double variance = 0.0;
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x) {
            if (!onSphere(camera, x, y))
                continue;
            sum += channelMean(image.radiance, x, y);
            variance += image.varianceOfMean(x, y);
            ++result.pixels;
        }
    result.mean = sum / result.pixels;
    result.sigma = std::sqrt(variance) / result.pixels;
    return result;
}

RenderedImage renderFurnace(const scene::Scene& scene, bool energyCompensation, int samples)
{
    settings::RenderSettings settings = settingsWithSeed(11);
    settings.energyCompensation = energyCompensation;
    return renderScene(scene, kWidth, kHeight, samples, settings);
}

// A white conductor (Schlick's Fresnel with R0 = 1 is 1 at every angle) reflects all it
// receives; the single-scattering GGX lobe loses what bounces between microfacets more than
// once, and the compensation (Turquin 2019, from the generated albedo table) gives it back.
class RoughConductorFurnace : public ::testing::TestWithParam<float> {};

TEST_P(RoughConductorFurnace, WhiteConductorReflectsAllItReceivesWithEnergyCompensation)
{
    const float alpha = GetParam();
    const scene::Scene scene = furnace("1 1 1", "rough_conductor " + std::to_string(alpha));
    const SphereMean compensated = meanOnSphere(scene, renderFurnace(scene, true, 64));
    const SphereMean single = meanOnSphere(scene, renderFurnace(scene, false, 64));
    ASSERT_GT(compensated.pixels, 300);
    std::cout << "rough conductor, alpha " << alpha
              << ", R0 = 1, in the furnace: " << compensated.mean << " +- " << compensated.sigma
              << " with energy compensation, " << single.mean << " +- " << single.sigma
              << " without (sphere's mean over " << compensated.pixels << " pixels)\n";
    EXPECT_NEAR(compensated.mean, 1.0, 0.02)
        << "a white rough conductor (alpha " << alpha << ") with energy compensation should "
        << "reflect all of the furnace, within 2 %; it reads " << compensated.mean
        << " (without compensation " << single.mean << ")";
    EXPECT_LE(single.mean, 1.0 + 5.0 * single.sigma)
        << "single scattering alone must not create energy";
}

std::string alphaName(const ::testing::TestParamInfo<float>& info);

INSTANTIATE_TEST_SUITE_P(Alpha, RoughConductorFurnace, ::testing::Values(0.3f, 1.0f), alphaName);

// Clear rough glass reflects or transmits at each microfacet, with no absorption: in the
// furnace it loses only what scatters between microfacets more than once, which it has no
// compensation for (much of it from inside, where most microfacets reflect totally: about
// half of what meets the inside at alpha = 1 is lost), and it must never create energy.
class RoughDielectricFurnace : public ::testing::TestWithParam<float> {};

TEST_P(RoughDielectricFurnace, ClearRoughGlassCreatesNoEnergy)
{
    const float alpha = GetParam();
    const scene::Scene scene =
        furnace("1 1 1", "rough_dielectric " + std::to_string(alpha) + " 1.5");
    const RenderedImage image = renderFurnace(scene, true, 128);
    const SphereMean sphere = meanOnSphere(scene, image);
    ASSERT_GT(sphere.pixels, 300);
    std::cout << "rough dielectric, alpha " << alpha
              << ", index 1.5, in the furnace: " << sphere.mean << " +- " << sphere.sigma << "\n";
    EXPECT_LE(sphere.mean, 1.0 + 5.0 * sphere.sigma + 1e-4)
        << "rough glass (alpha " << alpha << ") must not create energy; it reads " << sphere.mean;
    EXPECT_EQ(image.discardedSamples, 0u);
}

std::string alphaName(const ::testing::TestParamInfo<float>& info)
{
    std::string digits = std::to_string(info.param);
    digits.erase(digits.find_last_not_of('0') + 1);
    if (digits.back() == '.')
        digits.pop_back();
    digits.erase(std::remove(digits.begin(), digits.end(), '.'), digits.end());
    return "a" + digits;
}

INSTANTIATE_TEST_SUITE_P(Alpha, RoughDielectricFurnace, ::testing::Values(0.05f, 0.3f, 1.0f),
                         alphaName);

}  // namespace
}  // namespace render_tests
