// Light at a glass-air interface seen from inside the glass (Snell's window). The camera is
// inside the half-space y <= 0 of glass (index 1.5) and looks up at the interface y = 0
// under the default sky. Rays meeting it beyond the critical angle (41.8 degrees) must be
// reflected whole (total internal reflection) and then escape downwards through the glass:
// they see exactly sky(reflected direction). Rays inside the window are reflected with
// Schlick's probability F (R0 = 0.04, at the cosine on the air side) and otherwise refracted
// out, their radiance scaled by 1.5^2 on entering the denser medium.
#include "support/PinholeCamera.h"
#include "support/RenderRun.h"

#include <gtest/gtest.h>

#include <cmath>

namespace render_tests {
namespace {

using namespace testing_support;

constexpr int kWidth = 64;
constexpr int kHeight = 48;
constexpr double kIndex = 1.5;

// Looking up at 45 degrees from inside the glass: elevations from 15 to 75 degrees.
scene::Scene snellsWindow()
{
    return sceneFromText("0 -1 0\n0 0 -1\n0 1 0\n60\n0\n1 solid 1 1 1\n"
                         "1 0 0 0  0 0 1 1.5\n1\n0 0 polyhedron 1  0 1 0 0\n");
}

glm::dvec3 sky(const glm::dvec3& direction)
{
    return 0.5 * glm::dvec3(0.7, 0.8, 1.0) * (1.0 - 0.5 * direction.y);
}

double meanOfChannels(const glm::dvec3& value)
{
    return (value.x + value.y + value.z) / 3.0;
}

// cos(theta) at the interface beyond which no light passes: sin(theta_c) = 1 / 1.5.
const double kCriticalCosine = std::sqrt(1.0 - 1.0 / (kIndex * kIndex));

// Each compared pixel may be off by 5 of its standard deviations (the sky changes across a
// pixel, so the jitter alone makes noise) plus 0.2% (hit tolerance, float rounding).
struct Agreement {
    int pixels = 0;
    double worst = 0.0;  // in allowances
    int x = -1;
    int y = -1;
    double render = 0.0;
    double expected = 0.0;
};

template <typename Select, typename Expected>
Agreement agreementWith(const RenderedImage& image, const PinholeCamera& camera, Select select,
                        Expected expectedRadiance)
{
    Agreement agreement;
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x) {
            if (!camera.wholePixel(x, y, select))
                continue;
            ++agreement.pixels;
            const double expected = camera.pixelAverage(x, y, 16, expectedRadiance);
            const double render = channelMean(image.radiance, x, y);
            const double allowance = 5.0 * std::sqrt(image.varianceOfMean(x, y)) + 2e-3 * expected;
            const double off = std::abs(render - expected) / allowance;
            if (off > agreement.worst)
                agreement = {agreement.pixels, off, x, y, render, expected};
        }
    return agreement;
}

TEST(TotalInternalReflection, RaysBeyondTheCriticalAngleReflectAllTheirLight)
{
    const scene::Scene scene = snellsWindow();
    const RenderedImage image = renderScene(scene, kWidth, kHeight, 32, settingsWithSeed(17));
    const PinholeCamera camera(scene.camera, kWidth, kHeight);
    // direction.y is the cosine of incidence at the interface.
    const Agreement agreement = agreementWith(
        image, camera,
        [](const glm::dvec3& d) { return d.y > 0.05 && d.y < kCriticalCosine - 0.02; },
        [](const glm::dvec3& d) { return meanOfChannels(sky(glm::dvec3(d.x, -d.y, d.z))); });
    ASSERT_GT(agreement.pixels, 500);
    EXPECT_LE(agreement.worst, 1.0)
        << "beyond the critical angle every ray should reflect with weight 1 and see the sky "
           "below; at pixel ("
        << agreement.x << ", " << agreement.y << ") the render is " << agreement.render
        << ", expected " << agreement.expected << " (" << agreement.worst
        << " times the allowance of 5 sigma + 0.2%)";
    EXPECT_EQ(image.discardedSamples, 0u);
}

TEST(DielectricRefraction, LightLeavingTheDenserMediumIsSplitBySchlickAndScaledByIndexSquared)
{
    const scene::Scene scene = snellsWindow();
    const RenderedImage image = renderScene(scene, kWidth, kHeight, 256, settingsWithSeed(19));
    const PinholeCamera camera(scene.camera, kWidth, kHeight);

    auto expectedRadiance = [](const glm::dvec3& d) {
        const double cosIncident = d.y;
        const double sin2Transmitted = kIndex * kIndex * (1.0 - cosIncident * cosIncident);
        const double cosTransmitted = std::sqrt(1.0 - sin2Transmitted);
        const double r0 = std::pow((kIndex - 1.0) / (kIndex + 1.0), 2.0);
        const double fresnel = r0 + (1.0 - r0) * std::pow(1.0 - cosTransmitted, 5.0);
        // Snell: the tangential part scales by the index; the normal part is cosTransmitted.
        const glm::dvec3 transmitted(kIndex * d.x, cosTransmitted, kIndex * d.z);
        const glm::dvec3 reflected(d.x, -d.y, d.z);
        return fresnel * meanOfChannels(sky(reflected)) +
               (1.0 - fresnel) * kIndex * kIndex * meanOfChannels(sky(transmitted));
    };
    const Agreement agreement = agreementWith(
        image, camera, [](const glm::dvec3& d) { return d.y > kCriticalCosine + 0.02; },
        expectedRadiance);
    ASSERT_GT(agreement.pixels, 200);
    EXPECT_LE(agreement.worst, 1.0)
        << "inside Snell's window each pixel should be F sky(reflected) + (1 - F) 2.25 "
           "sky(refracted); at pixel ("
        << agreement.x << ", " << agreement.y << ") the render is " << agreement.render
        << ", expected " << agreement.expected << " (" << agreement.worst
        << " times the allowance of 5 sigma + 0.2%)";
}

}  // namespace
}  // namespace render_tests
