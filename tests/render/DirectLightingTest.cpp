// Direct lighting with closed forms: a Lambertian plane, alone under one light with no
// environment, so that every pixel is rho / pi times the irradiance at the point it sees,
// averaged over the pixel (the renderer jitters uniformly inside it). Compared pixel by
// pixel against the renderer's own variance estimate.
#include "support/PinholeCamera.h"
#include "support/RenderRun.h"

#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

namespace render_tests {
namespace {

using namespace testing_support;

constexpr int kWidth = 64;
constexpr int kHeight = 48;
constexpr double kAlbedo = 0.8;
constexpr double kPi = 3.14159265358979323846;

// The camera looks down at the floor y = 0 from (0, 3, 2); every pixel sees the floor.
const char* const kCameraAndNoEnvironment = "environment none\n0 3 2\n0 0 0\n0 1 0\n50\n";

// Where the ray meets the floor y = 0.
glm::dvec3 floorPoint(const PinholeCamera& camera, const glm::dvec3& direction)
{
    const glm::dvec3 eye(camera.eye());
    return eye + direction * (-eye.y / direction.y);
}

struct PixelAgreement {
    double worstZ = 0.0;  // |render - expected| / (its noise + a relative allowance)
    double worstRelativeError = 0.0;
    int worstX = -1;
    int worstY = -1;
    double render = 0.0;
    double expected = 0.0;
    int pixels = 0;
    std::string describe() const
    {
        std::ostringstream text;
        text << pixels << " pixels; worst at (" << worstX << ", " << worstY << "): render "
             << render << ", expected " << expected << " (" << worstZ
             << " allowances off); largest relative error " << worstRelativeError;
        return text.str();
    }
};

// Each compared pixel may be off by 5 of its standard deviations (noise) plus `relative`
// of its value (the hit point's tolerance, float rounding, the quadrature of the pixel).
template <typename Expected, typename Select>
PixelAgreement compareWithClosedForm(const RenderedImage& image, double relative, Expected expected,
                                     Select select)
{
    PixelAgreement agreement;
    for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < image.width(); ++x) {
            if (!select(x, y))
                continue;
            ++agreement.pixels;
            const double want = expected(x, y);
            const double got = channelMean(image.radiance, x, y);
            const double allowance =
                5.0 * std::sqrt(image.varianceOfMean(x, y)) + relative * want + 1e-7;
            const double z = std::abs(got - want) / allowance;
            agreement.worstRelativeError =
                std::max(agreement.worstRelativeError, std::abs(got - want) / want);
            if (z > agreement.worstZ) {
                agreement.worstZ = z;
                agreement.worstX = x;
                agreement.worstY = y;
                agreement.render = got;
                agreement.expected = want;
            }
        }
    return agreement;
}

TEST(PointLight, LambertianPlaneMatchesInverseSquareCosineLaw)
{
    const glm::dvec3 light(0.5, 1.0, -0.3);
    const double intensity = 2.0;
    const scene::Scene scene = sceneFromText(std::string(kCameraAndNoEnvironment) +
                                             "1\n0.5 1 -0.3  2 2 2\n1 solid 0.8 0.8 0.8\n"
                                             "1 0 0 0  0 0 0 0\n1\n0 0 polyhedron 1  0 1 0 0\n");
    // 256 samples: the irradiance changes by up to 12% across a pixel near the light, so
    // the jitter alone gives each pixel about 0.2% of noise at this count.
    const RenderedImage image = renderScene(scene, kWidth, kHeight, 256, settingsWithSeed(11));
    const PinholeCamera camera(scene.camera, kWidth, kHeight);

    // L = rho / pi * I cos(theta) / d^2 at the point each sample sees.
    auto radiance = [&](const glm::dvec3& direction) {
        const glm::dvec3 toLight = light - floorPoint(camera, direction);
        const double distance = glm::length(toLight);
        const double cosine = toLight.y / distance;
        return kAlbedo / kPi * intensity * cosine / (distance * distance);
    };
    const PixelAgreement agreement = compareWithClosedForm(
        image, 2e-3, [&](int x, int y) { return camera.pixelAverage(x, y, 16, radiance); },
        [](int, int) { return true; });
    EXPECT_LE(agreement.worstZ, 1.0)
        << "rho/pi I cos(theta)/d^2 per pixel: " << agreement.describe();
    EXPECT_LT(agreement.worstRelativeError, 0.01) << agreement.describe();
}

// A sphere light of radius R and radiance Le, wholly above the plane's horizon, gives
// irradiance E = pi Le (R / d)^2 cos(theta) (d: distance to its centre, theta: angle of the
// centre from the normal), so the plane shows rho Le (R / d)^2 cos(theta).
class SphereLight : public ::testing::TestWithParam<bool> {};

TEST_P(SphereLight, LambertianPlaneMatchesAnalyticIrradianceOfASphere)
{
    const bool multipleImportanceSampling = GetParam();
    const glm::dvec3 center(0.3, 1.2, -0.2);
    const double radius = 0.2;
    const double emitted = 5.0;
    // The light's pigment is black: it emits and reflects nothing.
    const scene::Scene scene =
        sceneFromText(std::string(kCameraAndNoEnvironment) +
                      "0\n2\nsolid 0.8 0.8 0.8\nsolid 0 0 0\n2\n0 0 0  0 0 0 0\n5 5 5  0 0 0 0\n2\n"
                      "0 0 polyhedron 1  0 1 0 0\n1 1 sphere 0.3 1.2 -0.2 0.2\n");
    settings::RenderSettings settings = settingsWithSeed(13);
    settings.multipleImportanceSampling = multipleImportanceSampling;
    const RenderedImage image = renderScene(scene, kWidth, kHeight, 64, settings);
    const PinholeCamera camera(scene.camera, kWidth, kHeight);

    auto radiance = [&](const glm::dvec3& direction) {
        const glm::dvec3 toCenter = center - floorPoint(camera, direction);
        const double distance = glm::length(toCenter);
        const double cosine = toCenter.y / distance;
        return kAlbedo * emitted * (radius / distance) * (radius / distance) * cosine;
    };
    // Pixels that see the light itself, or its silhouette, are not the plane's.
    auto seesOnlyPlane = [&](int x, int y) {
        return camera.wholePixel(x, y, [&](const glm::dvec3& direction) {
            return raySphere(glm::dvec3(camera.eye()), direction, center, radius * 1.1) < 0.0;
        });
    };
    const PixelAgreement agreement = compareWithClosedForm(
        image, 2e-3, [&](int x, int y) { return camera.pixelAverage(x, y, 16, radiance); },
        seesOnlyPlane);
    ASSERT_GT(agreement.pixels, 2500);
    EXPECT_LE(agreement.worstZ, 1.0)
        << (multipleImportanceSampling ? "with" : "without")
        << " MIS, rho Le (R/d)^2 cos(theta) per pixel: " << agreement.describe();
}

INSTANTIATE_TEST_SUITE_P(Sampling, SphereLight, ::testing::Bool(),
                         [](const ::testing::TestParamInfo<bool>& info) {
                             return std::string(info.param ? "WithMis" : "LightSamplingOnly");
                         });

}  // namespace
}  // namespace render_tests
