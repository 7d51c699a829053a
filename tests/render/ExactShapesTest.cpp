// Shapes met by exact intersection, in the default render and the --exact-geometry
// reference, against their silhouettes found on the CPU without their intersection
// formulas: a black solid against the sky is black wherever every ray through a pixel meets
// it and sky-coloured wherever none does. The cone {a |q.xz| + b q.y < 0} is convex and its
// bound convex along any ray, so whether a ray enters it is whether the bound's minimum
// along the ray (found by ternary search) is negative. The torus (a quartic) and the seed's
// CSG solid (the `csg` user SDF, whose file declares its intersection by intervals) are
// found by sphere tracing their exact distances in double precision.
#include "support/PinholeCamera.h"
#include "support/RenderRun.h"

#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
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

// Whether the ray meets the solid whose exact distance `solid.distance` is, sphere traced in
// double precision up to 2000 units.
template <typename Solid>
bool sphereTracedHit(const Solid& solid, const glm::dvec3& origin, const glm::dvec3& direction)
{
    double t = 0.0;
    for (int step = 0; step < 100000 && t < 2000.0; ++step) {
        const double d = solid.distance(origin + t * direction);
        if (d < 1e-9)
            return true;
        t += std::max(d, 1e-7);
    }
    return false;
}

// scenes/sdf/csg.glsl's distance, in double precision, turned by `toLocal` about the origin.
struct DrilledRoundedCube {
    glm::dmat3 toLocal{1.0};

    double distance(const glm::dvec3& p) const
    {
        const glm::dvec3 q = toLocal * p;
        const glm::dvec3 outside = glm::abs(q) - glm::dvec3(1.0);
        const double box = glm::length(glm::max(outside, glm::dvec3(0.0))) +
                           std::min(std::max(outside.x, std::max(outside.y, outside.z)), 0.0);
        const double roundedCube = std::max(glm::length(q) - 1.35, box);
        const double drills =
            std::min(std::min(glm::length(glm::dvec2(q.x, q.y)), glm::length(glm::dvec2(q.y, q.z))),
                     glm::length(glm::dvec2(q.x, q.z))) -
            0.7;
        return std::max(roundedCube, -drills);
    }

    bool metBy(const glm::dvec3& origin, const glm::dvec3& direction) const
    {
        return sphereTracedHit(*this, origin, direction);
    }
};

// A torus around y, turned by `toLocal` about the origin.
struct TorusSolid {
    glm::dvec3 center;
    double majorRadius;
    double minorRadius;
    glm::dmat3 toLocal{1.0};

    double distance(const glm::dvec3& p) const
    {
        const glm::dvec3 q = toLocal * p - center;
        return glm::length(glm::dvec2(glm::length(glm::dvec2(q.x, q.z)) - majorRadius, q.y)) -
               minorRadius;
    }

    bool metBy(const glm::dvec3& origin, const glm::dvec3& direction) const
    {
        return sphereTracedHit(*this, origin, direction);
    }
};

std::string blackSolidScene(const std::string& camera, const std::string& solid)
{
    std::ostringstream text;
    text << camera << "0\n1\nsolid 0 0 0\n1\n0 0 0 0 0 0 0\n1\n0 0 " << solid << "\n";
    return text.str();
}

std::string coneScene(const std::string& cone)
{
    return blackSolidScene("0 0.5 6\n0 -0.5 0\n0 1 0\n50\n", cone);
}

// Pixels every ray of which meets the solid are black; pixels none of whose rays do see the
// sky, which is at least 0.2 in every direction of these views. Returns the pixels judged.
template <typename Solid>
int expectSilhouette(const std::string& sceneText, const Solid& solid, bool exactGeometry)
{
    const scene::Scene scene = sceneFromText(sceneText);
    settings::RenderSettings settings = settingsWithSeed(3);
    settings.exactGeometry = exactGeometry;
    const RenderedImage image = renderScene(scene, kWidth, kHeight, kSamples, settings);
    const PinholeCamera camera(scene.camera, kWidth, kHeight);
    int inside = 0;
    int outside = 0;
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x) {
            const float value = channelMean(image.radiance, x, y);
            auto meets = [&](glm::dvec3 d) { return solid.metBy(camera.eye(), d); };
            auto misses = [&](glm::dvec3 d) { return !solid.metBy(camera.eye(), d); };
            if (camera.wholePixel(x, y, meets)) {
                ++inside;
                EXPECT_LT(value, 1e-6f) << "pixel (" << x << ", " << y << ") is on the solid";
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

TEST(ExactShapes, ATorusIsMetWithinItsSilhouette)
{
    // Seen from above at an angle, so that its hole shows the sky.
    const std::string scene =
        blackSolidScene("0 3 4.5\n0 0 0\n0 1 0\n45\n", "torus 0 0 0  1.5 0.45");
    const TorusSolid torus{{0, 0, 0}, 1.5, 0.45};
    expectSilhouette(scene, torus, false);
    expectSilhouette(scene, torus, true);
}

TEST(ExactShapes, AFarTorusSeenNearlyEdgeOnIsMetWithinItsSilhouette)
{
    // 300 of its sizes away with a narrow view, turned so that rays graze its rim: the
    // quartic's coefficients would lose their digits if it were not solved from the ray's
    // point nearest the centre.
    const glm::dmat3 turn(glm::rotate(glm::dmat4(1.0), glm::radians(8.0), glm::dvec3(1, 0, 0)));
    const std::string scene =
        blackSolidScene("0 40 600\n0 0 0\n0 1 0\n0.4\n", "rotate 1 0 0 8 torus 0 0 0  1.5 0.45");
    const TorusSolid torus{{0, 0, 0}, 1.5, 0.45, glm::transpose(turn)};
    expectSilhouette(scene, torus, false);
    expectSilhouette(scene, torus, true);
}

// Where the ray first crosses the surface of the solid with exact distance `solid.distance`
// (leaving it, from inside), sphere traced on |distance| in double precision up to 2000 units.
template <typename Solid>
std::optional<double> firstCrossing(const Solid& solid, const glm::dvec3& origin,
                                    const glm::dvec3& direction)
{
    double t = 0.0;
    for (int step = 0; step < 100000 && t < 2000.0; ++step) {
        const double d = std::abs(solid.distance(origin + t * direction));
        if (d < 1e-7)
            return t;
        t += d;
    }
    return std::nullopt;
}

// Every pixel whose rays all cross the torus, and whose depth is smooth across it (no
// pixel straddling the near side and the far one), has the camera depth (--feature-buffers)
// of the first crossing: the nearest of the quartic's roots beyond the eye, in the default
// render and the --exact-geometry reference. Returns the pixels judged.
int expectTorusDepth(const std::string& camera, const TorusSolid& torus, bool exactGeometry)
{
    const scene::Scene scene = sceneFromText(blackSolidScene(camera, "torus 0 0 0  1.5 0.45"));
    settings::RenderSettings settings = settingsWithSeed(4);
    settings.exactGeometry = exactGeometry;
    settings.featureBuffers = true;
    const RenderedImage image = renderScene(scene, kWidth, kHeight, kSamples, settings);
    const PinholeCamera view(scene.camera, kWidth, kHeight);
    const glm::dvec3 eye = view.eye();
    auto crossing = [&](const glm::dvec3& d) { return firstCrossing(torus, eye, d); };
    int judged = 0;
    double worst = 0.0;
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x) {
            if (!view.wholePixel(x, y, [&](glm::dvec3 d) { return crossing(d).has_value(); }))
                continue;
            const auto corners = {*crossing(view.direction(x, y)),
                                  *crossing(view.direction(x + 1, y)),
                                  *crossing(view.direction(x, y + 1)),
                                  *crossing(view.direction(x + 1, y + 1))};
            const auto [low, high] = std::minmax(corners);
            if (high > 1.05 * low)
                continue;  // a depth edge, or a surface seen so obliquely that jitter shows
            const double expected =
                view.pixelAverage(x, y, 8, [&](const glm::dvec3& d) { return *crossing(d); });
            const double depth = image.accumulation.albedoDepth.at(x, y, 3);
            worst = std::max(worst, std::abs(depth - expected) / expected);
            EXPECT_NEAR(depth, expected, 0.01 * expected) << "pixel (" << x << ", " << y << ")";
            ++judged;
        }
    std::printf("%s: %d pixels judged, worst relative depth error %.3g\n",
                exactGeometry ? "exact geometry" : "default", judged, worst);
    return judged;
}

TEST(ExactShapes, ATorusIsMetAtItsNearestCrossingThroughItsHoleAndFromInsideItsTube)
{
    const TorusSolid torus{{0, 0, 0}, 1.5, 0.45};
    for (bool exactGeometry : {false, true}) {
        // Low and across: rays cross the near side of the ring, or pass the hole and cross
        // the far side.
        EXPECT_GT(expectTorusDepth("0 0.7 5\n0 0 0\n0 1 0\n40\n", torus, exactGeometry), 600);
        // Straight down the axis (the quartic's odd term vanishes along it): the inner rim
        // and, through the hole, nothing.
        EXPECT_GT(expectTorusDepth("0 6 0\n0 0 0\n0 0 -1\n40\n", torus, exactGeometry), 400);
        // From inside the tube, along it: every ray leaves the solid through its wall.
        EXPECT_GT(expectTorusDepth("1.5 0 0\n1.5 0.1 -1\n0 1 0\n70\n", torus, exactGeometry),
                  kWidth * kHeight / 2);
    }
}

const char* const kCsgCamera = "3 2.2 4\n0 0 0\n0 1 0\n40\n";

TEST(ExactShapes, AUserSdfWithADeclaredIntersectionIsMetWithinItsSilhouette)
{
    const std::string scene = blackSolidScene(kCsgCamera, "csg 0 0 0");
    expectSilhouette(scene, DrilledRoundedCube{}, false);
    expectSilhouette(scene, DrilledRoundedCube{}, true);
}

TEST(ExactShapes, ATurnedUserSdfIsMetInItsOwnFrame)
{
    const glm::dmat3 turn(glm::rotate(glm::dmat4(1.0), glm::radians(30.0), glm::dvec3(1, 1, 0)));
    const std::string scene = blackSolidScene(kCsgCamera, "rotate 1 1 0 30 csg 0 0 0");
    expectSilhouette(scene, DrilledRoundedCube{glm::transpose(turn)}, false);
    expectSilhouette(scene, DrilledRoundedCube{glm::transpose(turn)}, true);
}

}  // namespace
}  // namespace render_tests
