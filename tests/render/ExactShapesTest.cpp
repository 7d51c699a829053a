// Shapes met by exact intersection, in the default render and the --exact-geometry
// reference, against their silhouettes found on the CPU without their intersection
// formulas: a black cone against the sky is black wherever every ray through a pixel meets
// the solid and sky-coloured wherever none does. The solid {a |q.xz| + b q.y < 0} is convex
// and its bound convex along any ray, so whether a ray enters it is whether the bound's
// minimum along the ray (found by ternary search) is negative.
#include "support/PinholeCamera.h"
#include "support/RenderRun.h"

#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include <sstream>

namespace render_tests {
namespace {

using namespace testing_support;

constexpr int kWidth = 64;
constexpr int kHeight = 48;
constexpr int kSamples = 8;

struct ConeSolid {
    glm::dvec3 apex;
    glm::dvec2 slope;
    glm::dmat3 toLocal{1.0};  // world to the cone's frame (a rotation about the apex)

    double bound(const glm::dvec3& p) const
    {
        const glm::dvec3 q = toLocal * (p - apex);
        return glm::dot(glm::normalize(slope), glm::dvec2(glm::length(glm::dvec2(q.x, q.z)), q.y));
    }

    bool metBy(const glm::dvec3& origin, const glm::dvec3& direction) const
    {
        double low = 0.0;
        double high = 200.0;
        for (int i = 0; i < 200; ++i) {
            const double a = low + (high - low) / 3.0;
            const double b = high - (high - low) / 3.0;
            if (bound(origin + a * direction) < bound(origin + b * direction))
                high = b;
            else
                low = a;
        }
        return bound(origin + 0.5 * (low + high) * direction) < 0.0;
    }
};

std::string coneScene(const std::string& cone)
{
    std::ostringstream text;
    text << "0 0.5 6\n0 -0.5 0\n0 1 0\n50\n"
         << "0\n1\nsolid 0 0 0\n1\n0 0 0 0 0 0 0\n1\n0 0 " << cone << "\n";
    return text.str();
}

// Pixels every ray of which meets the cone are black; pixels none of whose rays do see the
// sky, which is at least 0.2 in every direction of this view. Returns the pixels judged.
int expectSilhouette(const std::string& sceneText, const ConeSolid& cone, bool exactGeometry)
{
    const scene::Scene scene = sceneFromText(sceneText);
    render::RenderSettings settings = settingsWithSeed(3);
    settings.exactGeometry = exactGeometry;
    const RenderedImage image = renderScene(scene, kWidth, kHeight, kSamples, settings);
    const PinholeCamera camera(scene.camera, kWidth, kHeight);
    int inside = 0;
    int outside = 0;
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x) {
            const float value = channelMean(image.radiance, x, y);
            auto meets = [&](glm::dvec3 d) { return cone.metBy(camera.eye(), d); };
            auto misses = [&](glm::dvec3 d) { return !cone.metBy(camera.eye(), d); };
            if (camera.wholePixel(x, y, meets)) {
                ++inside;
                EXPECT_LT(value, 1e-6f) << "pixel (" << x << ", " << y << ") is on the cone";
            } else if (camera.wholePixel(x, y, misses)) {
                ++outside;
                EXPECT_GT(value, 0.2f) << "pixel (" << x << ", " << y << ") sees the sky";
            }
        }
    EXPECT_GT(inside, kWidth * kHeight / 10);
    EXPECT_GT(outside, kWidth * kHeight / 10);
    return inside + outside;
}

TEST(ExactShapes, AConeOpeningDownwardsIsMetWithinItsSilhouette)
{
    const ConeSolid cone{{0.0, 1.0, 0.0}, {1.0, 0.6}};
    const std::string scene = coneScene("cone 0 1 0  1 0.6");
    expectSilhouette(scene, cone, false);
    expectSilhouette(scene, cone, true);
}

TEST(ExactShapes, AConeOpeningUpwardsIsMetWithinItsSilhouette)
{
    const ConeSolid cone{{0.0, -1.5, 0.0}, {1.0, -0.8}};
    const std::string scene = coneScene("cone 0 -1.5 0  1 -0.8");
    expectSilhouette(scene, cone, false);
    expectSilhouette(scene, cone, true);
}

TEST(ExactShapes, ATurnedConeIsMetInItsOwnFrame)
{
    // Turned by 25 degrees about z around the origin: its apex moves with it.
    const glm::dmat3 turn(glm::rotate(glm::dmat4(1.0), glm::radians(25.0), glm::dvec3(0, 0, 1)));
    ConeSolid cone{turn * glm::dvec3(0.0, 1.0, 0.0), {1.0, 0.6}, glm::transpose(turn)};
    const std::string scene = coneScene("rotate 0 0 1 25 cone 0 1 0  1 0.6");
    expectSilhouette(scene, cone, false);
    expectSilhouette(scene, cone, true);
}

}  // namespace
}  // namespace render_tests
