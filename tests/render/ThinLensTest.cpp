// The thin-lens camera (scene format: `lens APERTURE FOCUS` after the field of view): a small
// glowing ball on the plane of focus images as sharply as through the pinhole; off that
// plane every point of it spreads into a disc, the circle of confusion, whose radius on the
// plane of focus is A |d - f| / d (A the aperture radius, f the focus distance, d the
// point's distance; similar triangles through the lens). The image through the lens is the
// pinhole's convolved with that disc, so its second moment about the centre grows by R^2 / 2
// (a uniform disc of radius R has mean r^2 = R^2 / 2, and moments of a convolution add),
// which measures R without knowing the ball's own image.
#include "support/RenderRun.h"

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <sstream>
#include <string>

namespace render_tests {
namespace {

using namespace testing_support;

constexpr int kSide = 96;
constexpr double kFieldOfViewDegrees = 20.0;
constexpr double kApertureRadius = 0.3;
constexpr double kFocusDistance = 4.0;
constexpr double kBallRadius = 0.05;

// A ball of radiance 1 at distance `distance` straight ahead, in the dark, seen through the
// lens (or through the pinhole when `lens` is false).
scene::Scene glowingBall(double distance, bool lens)
{
    std::ostringstream text;
    text << "environment none\n0 0 0\n0 0 -1\n0 1 0\n" << kFieldOfViewDegrees << "\n";
    if (lens)
        text << "lens " << kApertureRadius << " " << kFocusDistance << "\n";
    text << "0\n1 solid 0 0 0\n1 1 1 1  0 0 0 1\n1\n0 0 sphere 0 0 " << -distance << " "
         << kBallRadius << "\n";
    return sceneFromText(text.str());
}

// Pixels per unit of tan(angle) at the image's centre: the film maps tan linearly.
double pixelsPerTangent()
{
    return kSide / (2.0 * std::tan(kFieldOfViewDegrees * 3.14159265358979323846 / 360.0));
}

// The power of the image (its sum) and its second moment about the image's centre, in
// pixels squared.
struct Moments {
    double power = 0.0;
    double secondMoment = 0.0;
};

Moments momentsOf(const scene::Scene& scene, int samples)
{
    const RenderedImage image = renderScene(scene, kSide, kSide, samples, settingsWithSeed(17));
    Moments moments;
    double weighted = 0.0;
    for (int y = 0; y < kSide; ++y)
        for (int x = 0; x < kSide; ++x) {
            const double value = channelMean(image.radiance, x, y);
            const double dx = x + 0.5 - kSide / 2.0;
            const double dy = y + 0.5 - kSide / 2.0;
            moments.power += value;
            weighted += value * (dx * dx + dy * dy);
        }
    moments.secondMoment = weighted / moments.power;
    return moments;
}

// The radius of the disc that widened the pinhole's image into the lens's.
double blurRadius(const Moments& lens, const Moments& pinhole)
{
    return std::sqrt(std::max(0.0, 2.0 * (lens.secondMoment - pinhole.secondMoment)));
}

TEST(ThinLens, PointOnThePlaneOfFocusStaysSharp)
{
    const Moments pinhole = momentsOf(glowingBall(kFocusDistance, false), 64);
    const Moments lens = momentsOf(glowingBall(kFocusDistance, true), 256);
    const double radius = blurRadius(lens, pinhole);
    std::cout << "in focus: blur radius " << radius << " pixels (image second moments "
              << lens.secondMoment << " through the lens, " << pinhole.secondMoment
              << " through the pinhole)\n";
    EXPECT_LT(radius, 0.5) << "a ball on the plane of focus should image as through the pinhole; "
                              "its image is blurred by a disc of radius "
                           << radius << " pixels";
}

TEST(ThinLens, PointOffThePlaneOfFocusSpreadsIntoADiscOfThePredictedRadius)
{
    const double distance = 2.0 * kFocusDistance;
    const Moments pinhole = momentsOf(glowingBall(distance, false), 64);
    const Moments lens = momentsOf(glowingBall(distance, true), 512);
    const double predicted = kApertureRadius * std::abs(distance - kFocusDistance) /
                             (distance * kFocusDistance) * pixelsPerTangent();
    const double radius = blurRadius(lens, pinhole);
    std::cout << "out of focus: blur radius " << radius << " pixels, predicted " << predicted
              << "; image power " << lens.power << " through the lens, " << pinhole.power
              << " through the pinhole\n";
    EXPECT_NEAR(radius, predicted, 0.03 * predicted)
        << "a ball at twice the focus distance should spread into a disc of radius " << predicted
        << " pixels (A |d - f| / (d f), in pixels)";
    // The lens moves the ball's light around the film; it neither adds nor loses any.
    EXPECT_NEAR(lens.power, pinhole.power, 0.03 * pinhole.power)
        << "the blurred image should hold the sharp one's power";
}

}  // namespace
}  // namespace render_tests
