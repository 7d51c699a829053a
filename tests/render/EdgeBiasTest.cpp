// The default render against exact intersection (--exact-geometry) where sphere tracing
// goes wrong if it goes wrong anywhere: the rim of a visible sphere light, a silhouette
// against a wall of another brightness, a room's concave edges, and the floor around an
// object resting on it. The silhouette and the contact are a box's, which the default
// renderer meets exactly, as the reference does (and spheres, planes, cylinders, disks and
// cones); so that its sphere tracer, which every other shape relies on, is still judged
// here, the traced renders march boxes (RenderSettings::marchBoxesCylindersAndDisks).
// Image-wide means cannot see these errors (they sit in a few percent of the pixels), so
// each test compares only the pixels of its feature, found on the CPU from the scene's
// geometry, block by block against the two images' noise.
//
// The bias must stay below half the noise of a render of the test's sample count: a render
// that counts rays passing within its hit tolerance of a surface as hits fails by far.
//
// With EDGE_BIAS_TRACED_PROGRAM set to another build's raytracer, its default renders (run
// on the command line) are judged instead of this build's, against this build's exact
// intersection: how the tests show that a program before the edge-bias work fails them.
#include "io/ImageFile.h"
#include "support/CsgSolids.h"
#include "support/PinholeCamera.h"
#include "support/RenderRun.h"

#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <vector>

namespace render_tests {
namespace {

using namespace testing_support;

constexpr int kWidth = 96;
constexpr int kHeight = 72;
constexpr int kSamples = 256;
constexpr int kPixelsPerBlock = 2;

// A picture pixel mask, top row first.
struct PixelMask {
    std::vector<char> selected = std::vector<char>(kWidth * kHeight, 0);
    bool at(int x, int y) const { return selected[y * kWidth + x] != 0; }
    void set(int x, int y) { selected[y * kWidth + x] = 1; }
    int count() const
    {
        int n = 0;
        for (char s : selected)
            n += s;
        return n;
    }
    // Every pixel within `radius` pixels (chessboard distance) of a selected one.
    PixelMask dilated(int radius) const
    {
        PixelMask grown;
        for (int y = 0; y < kHeight; ++y)
            for (int x = 0; x < kWidth; ++x)
                if (at(x, y))
                    for (int dy = -radius; dy <= radius; ++dy)
                        for (int dx = -radius; dx <= radius; ++dx) {
                            const int nx = x + dx, ny = y + dy;
                            if (nx >= 0 && ny >= 0 && nx < kWidth && ny < kHeight)
                                grown.set(nx, ny);
                        }
        return grown;
    }
};

// The pixels whose area a boundary crosses: `side` (of a direction through the pixel) is
// not the same at its four corners and its centre and on a 4 x 4 grid inside it.
PixelMask boundaryPixels(const PinholeCamera& camera, const std::function<int(glm::dvec3)>& side)
{
    PixelMask mask;
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x) {
            const int first = side(camera.direction(x, y));
            bool mixed = false;
            for (int a = 0; a <= 4 && !mixed; ++a)
                for (int b = 0; b <= 4 && !mixed; ++b)
                    mixed = side(camera.direction(x + a / 4.0, y + b / 4.0)) != first;
            if (mixed)
                mask.set(x, y);
        }
    return mask;
}

// The bias of the default render over a feature, and the noise of a render of kSamples.
// Each image is rendered twice, default and exact with one seed, then both with another:
// with one seed the two renders draw the same numbers for the same samples, so their
// difference D is nearly free of noise where the paths agree, and the product of the two
// seeds' differences estimates the squared bias without bias of its own (E[D1 D2] =
// E[D1] E[D2] for independent seeds). Pixels of the feature are summed in blocks of
// kPixelsPerBlock (scan order); the ratio compared is
//     sum over blocks of D1 D2  /  sum over blocks of the variance of one render's block sum,
// the squared bias in units of the noise a user sees at this sample count.
struct EdgeComparison {
    int pixels = 0;
    int blocks = 0;
    double squaredBias = 0.0;       // sum over blocks of D1 D2
    double squaredNoise = 0.0;      // sum over blocks of the render's variance
    double meanRelativeBias = 0.0;  // signed, over the feature: sum (D1 + D2) / 2 / sum exact
    double biasOverNoise() const
    {
        return std::sqrt(std::max(squaredBias, 0.0) / std::max(squaredNoise, 1e-30));
    }
    std::string describe() const
    {
        std::ostringstream text;
        text << pixels << " pixels in " << blocks << " blocks: bias / noise = " << biasOverNoise()
             << " (squared bias " << squaredBias << ", squared noise " << squaredNoise
             << "); over the feature the default render is off by " << 100.0 * meanRelativeBias
             << " % on average";
        return text.str();
    }
};

struct RenderPair {
    RenderedImage traced;
    RenderedImage exact;
};

EdgeComparison compareOnMask(const RenderPair& first, const RenderPair& second,
                             const PixelMask& mask)
{
    EdgeComparison result;
    double d1 = 0.0, d2 = 0.0, variance = 0.0;
    double totalDifference = 0.0, totalExact = 0.0;
    int inBlock = 0;
    auto closeBlock = [&] {
        if (inBlock == 0)
            return;
        result.squaredBias += d1 * d2;
        result.squaredNoise += variance;
        ++result.blocks;
        d1 = d2 = variance = 0.0;
        inBlock = 0;
    };
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x) {
            if (!mask.at(x, y))
                continue;
            const double exact1 = channelMean(first.exact.radiance, x, y);
            const double exact2 = channelMean(second.exact.radiance, x, y);
            d1 += channelMean(first.traced.radiance, x, y) - exact1;
            d2 += channelMean(second.traced.radiance, x, y) - exact2;
            variance += first.traced.varianceOfMean(x, y);
            totalDifference += 0.5 * (channelMean(first.traced.radiance, x, y) - exact1 +
                                      channelMean(second.traced.radiance, x, y) - exact2);
            totalExact += 0.5 * (exact1 + exact2);
            ++result.pixels;
            if (++inBlock == kPixelsPerBlock)
                closeBlock();
        }
    closeBlock();
    result.meanRelativeBias = totalDifference / std::max(totalExact, 1e-9);
    return result;
}

// The default render of `sceneText` by the program EDGE_BIAS_TRACED_PROGRAM names, read
// back from its EXR image and statistics.
RenderedImage renderWithOtherProgram(const std::string& program, const std::string& sceneText,
                                     std::uint64_t seed)
{
    const std::filesystem::path folder =
        std::filesystem::temp_directory_path() /
        ("edge-bias-" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) + "-" +
         std::to_string(seed));
    std::filesystem::create_directories(folder);
    std::ofstream(folder / "scene.in") << sceneText;
    const std::string command =
        "'" + program + "' '" + (folder / "scene.in").string() + "' " + std::to_string(kWidth) +
        " " + std::to_string(kHeight) + " --headless --quiet --spp " + std::to_string(kSamples) +
        " --seed " + std::to_string(seed) + " --output '" + (folder / "image.exr").string() +
        "' --stats-output '" + (folder / "statistics.exr").string() + "'";
    if (std::system(command.c_str()) != 0)
        throw std::runtime_error("failed: " + command);
    RenderedImage image;
    image.radiance = io::readImage(folder / "image.exr");
    image.statistics = io::readImage(folder / "statistics.exr");
    std::filesystem::remove_all(folder);
    return image;
}

// The traced render's accuracy settings: the default's unless a test says otherwise.
struct MarchSettings {
    float hitTolerance = settings::RenderSettings{}.hitTolerance;
    int maxMarchSteps = settings::RenderSettings{}.maxMarchSteps;
};

RenderPair renderPair(const std::string& sceneText, std::uint64_t seed,
                      const MarchSettings& march = {})
{
    const scene::Scene scene = sceneFromText(sceneText);
    settings::RenderSettings settings = settingsWithSeed(seed);
    settings.samplesPerFrame = 16;
    settings.hitTolerance = march.hitTolerance;
    settings.maxMarchSteps = march.maxMarchSteps;
    RenderPair pair;
    if (const char* program = std::getenv("EDGE_BIAS_TRACED_PROGRAM")) {
        pair.traced = renderWithOtherProgram(program, sceneText, seed);
    } else {
        settings.marchBoxesCylindersAndDisks = true;
        pair.traced = renderScene(scene, kWidth, kHeight, kSamples, settings);
        settings.marchBoxesCylindersAndDisks = false;
    }
    settings.exactGeometry = true;
    pair.exact = renderScene(scene, kWidth, kHeight, kSamples, settings);
    return pair;
}

// The default render's bias over the feature must stay below half its noise at kSamples.
void expectMatchesExactGeometry(const std::string& sceneText, const PixelMask& mask,
                                const std::string& feature, const MarchSettings& march = {})
{
    const EdgeComparison comparison =
        compareOnMask(renderPair(sceneText, 11, march), renderPair(sceneText, 12, march), mask);
    std::cout << feature << ": " << comparison.describe() << "\n";
    ASSERT_GE(comparison.blocks, 12) << feature << ": too few pixels to judge";
    EXPECT_LT(comparison.biasOverNoise(), 0.5)
        << feature << " differs from exact intersection by more than half the noise of " << kSamples
        << " samples: " << comparison.describe();
}

// A closed room (walls of three colours) seen from inside; the camera looks at -z.
const char* const kRoomCamera = "0 0 4\n0 0 0\n0 1 0\n50\n";
const char* const kRoomObjects =
    "0 0 polyhedron 4\n    0 1 0 2\n    0 -1 0 2\n    0 0 1 2\n    0 0 -1 5\n"
    "1 0 polyhedron 1\n    1 0 0 2\n"
    "2 0 polyhedron 1\n    -1 0 0 2\n";
const char* const kRoomPigments = "solid 0.8 0.8 0.8\nsolid 0.8 0.2 0.1\nsolid 0.1 0.7 0.2\n";

TEST(EdgeBias, VisibleSphereLightRimMatchesExactIntersection)
{
    // A sphere light floating in front of the lit back wall: its rim against the wall.
    const std::string scene = std::string("environment none\n") + kRoomCamera + "0\n4\n" +
                              kRoomPigments + "solid 0 0 0\n2\n0 0 0 0 0 0 0\n6 6 6 0 0 0 0\n" +
                              "4\n" + kRoomObjects + "3 1 sphere 0.2 0.3 -0.5 0.7\n";
    const PinholeCamera camera(sceneFromText(scene).camera, kWidth, kHeight);
    const glm::dvec3 center(0.2, 0.3, -0.5);
    const PixelMask rim = boundaryPixels(camera, [&](glm::dvec3 d) {
        return raySphere(camera.eye(), d, center, 0.7) > 0.0 ? 1 : 0;
    });
    expectMatchesExactGeometry(scene, rim, "the sphere light's rim");
}

TEST(EdgeBias, DiffuseBoxSilhouetteAgainstABrighterWallMatchesExactIntersection)
{
    // A dark box in front of the bright back wall, under a point light.
    const std::string scene = std::string("environment none\n") + kRoomCamera +
                              "1\n0.5 1.6 1.5  12 12 12\n4\n" + kRoomPigments +
                              "solid 0.15 0.15 0.15\n1\n0 0 0 0 0 0 0\n4\n" + kRoomObjects +
                              "3 0 box -0.2 -0.1 -0.8  0.5 0.6 0.4\n";
    const PinholeCamera camera(sceneFromText(scene).camera, kWidth, kHeight);
    const glm::dvec3 center(-0.2, -0.1, -0.8), halfExtents(0.5, 0.6, 0.4);
    const PixelMask silhouette = boundaryPixels(camera, [&](glm::dvec3 d) {
        return rayBox(camera.eye(), d, center, halfExtents) > 0.0 ? 1 : 0;
    });
    expectMatchesExactGeometry(scene, silhouette, "the box's silhouette");
}

// Which wall of the room of kRoomObjects a ray from the eye meets first.
int roomWall(const glm::dvec3& eye, const glm::dvec3& d)
{
    const glm::dvec4 planes[] = {{0, 1, 0, 2},  {0, -1, 0, 2}, {0, 0, 1, 2},
                                 {0, 0, -1, 5}, {1, 0, 0, 2},  {-1, 0, 0, 2}};
    int nearest = -1;
    double best = 1e30;
    for (int i = 0; i < 6; ++i) {
        const glm::dvec3 n(planes[i]);
        const double rate = glm::dot(n, d);
        if (rate >= 0.0)
            continue;
        const double t = -(glm::dot(n, eye) + planes[i].w) / rate;
        if (t > 0.0 && t < best) {
            best = t;
            nearest = i;
        }
    }
    return nearest;
}

TEST(EdgeBias, ConcaveRoomEdgesMatchExactIntersection)
{
    // The empty room under a point light behind the camera: every edge where two walls meet.
    const std::string scene = std::string("environment none\n") + "0 0 4\n0 -0.3 0\n0 1 0\n70\n" +
                              "1\n0.4 1.5 3.5  12 12 12\n3\n" + kRoomPigments +
                              "1\n0 0 0 0 0 0 0\n3\n" + kRoomObjects;
    const PinholeCamera camera(sceneFromText(scene).camera, kWidth, kHeight);
    const PixelMask edges =
        boundaryPixels(camera, [&](glm::dvec3 d) { return roomWall(camera.eye(), d); });
    expectMatchesExactGeometry(scene, edges, "the room's edges");
}

// The floor pixels (y = -2 of the room) seen past an object resting on it (`hitsObject`)
// whose floor point lies within `reach` of the object's footprint (`distanceToFootprint`
// of x, z).
PixelMask floorAroundContact(const PinholeCamera& camera,
                             const std::function<bool(glm::dvec3)>& hitsObject,
                             const std::function<double(double, double)>& distanceToFootprint,
                             double reach)
{
    PixelMask mask;
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x) {
            const glm::dvec3 d = camera.direction(x + 0.5, y + 0.5);
            if (d.y >= 0.0 || hitsObject(d))
                continue;
            const glm::dvec3 p = camera.eye() + d * ((-2.0 - camera.eye().y) / d.y);
            if (distanceToFootprint(p.x, p.z) < reach)
                mask.set(x, y);
        }
    return mask;
}

const char* const kContactCamera = "0 0.2 3\n0 -1.6 0\n0 1 0\n45\n";
const glm::dvec3 kRestingBoxCenter(0.1, -1.6, -0.3);
const glm::dvec3 kRestingBoxHalfExtents(0.45, 0.4, 0.35);
const char* const kRestingBox = "0 0 box 0.1 -1.6 -0.3  0.45 0.4 0.35\n";

PixelMask floorAroundRestingBox(const PinholeCamera& camera)
{
    return floorAroundContact(
        camera,
        [&](glm::dvec3 d) {
            return rayBox(camera.eye(), d, kRestingBoxCenter, kRestingBoxHalfExtents) > 0.0;
        },
        [](double x, double z) {
            const double outsideX =
                std::max(0.0, std::abs(x - kRestingBoxCenter.x) - kRestingBoxHalfExtents.x);
            const double outsideZ =
                std::max(0.0, std::abs(z - kRestingBoxCenter.z) - kRestingBoxHalfExtents.z);
            return std::hypot(outsideX, outsideZ);
        },
        0.3);
}

// A sphere of radius 0.4 resting on the floor: its contact point is (0.1, -2, -0.3).
const glm::dvec3 kRestingSphereCenter(0.1, -1.6, -0.3);
const char* const kRestingSphere = "0 0 sphere 0.1 -1.6 -0.3 0.4\n";

// The floor within 0.4 of the contact point, where the gap under the sphere is thinnest.
PixelMask floorAroundRestingSphere(const PinholeCamera& camera)
{
    return floorAroundContact(
        camera,
        [&](glm::dvec3 d) { return raySphere(camera.eye(), d, kRestingSphereCenter, 0.4) > 0.0; },
        [](double x, double z) {
            return std::hypot(x - kRestingSphereCenter.x, z - kRestingSphereCenter.z);
        },
        0.4);
}

TEST(EdgeBias, FloorAroundABoxRestingOnItMatchesExactIntersectionUnderAPointLight)
{
    const std::string scene = std::string("environment none\n") + kContactCamera +
                              "1\n-0.8 1.5 1.0  10 10 10\n3\n" + kRoomPigments +
                              "1\n0 0 0 0 0 0 0\n4\n" + kRoomObjects + kRestingBox;
    const PinholeCamera camera(sceneFromText(scene).camera, kWidth, kHeight);
    expectMatchesExactGeometry(scene, floorAroundRestingBox(camera),
                               "the floor around the box's contact (point light)");
}

TEST(EdgeBias, FloorAroundABoxRestingOnItMatchesExactIntersectionUnderASphereLight)
{
    const std::string scene = std::string("environment none\n") + kContactCamera + "0\n4\n" +
                              kRoomPigments + "solid 0 0 0\n2\n0 0 0 0 0 0 0\n" +
                              "10 10 10 0 0 0 0\n5\n" + kRoomObjects + kRestingBox +
                              "3 1 sphere -0.9 1.2 0.8 0.35\n";
    const PinholeCamera camera(sceneFromText(scene).camera, kWidth, kHeight);
    expectMatchesExactGeometry(scene, floorAroundRestingBox(camera),
                               "the floor around the box's contact (sphere light)");
}

// The same features with spheres, which the default renderer meets by exact intersection
// (top-level spheres are never marched): they hold by construction today and failed before.
TEST(EdgeBias, DiffuseSphereSilhouetteAgainstABrighterWallMatchesExactIntersection)
{
    const std::string scene = std::string("environment none\n") + kRoomCamera +
                              "1\n0.5 1.6 1.5  12 12 12\n4\n" + kRoomPigments +
                              "solid 0.15 0.15 0.15\n1\n0 0 0 0 0 0 0\n4\n" + kRoomObjects +
                              "3 0 sphere -0.2 -0.1 -0.8 0.7\n";
    const PinholeCamera camera(sceneFromText(scene).camera, kWidth, kHeight);
    const glm::dvec3 center(-0.2, -0.1, -0.8);
    const PixelMask silhouette = boundaryPixels(camera, [&](glm::dvec3 d) {
        return raySphere(camera.eye(), d, center, 0.7) > 0.0 ? 1 : 0;
    });
    expectMatchesExactGeometry(scene, silhouette, "the sphere's silhouette");
}

TEST(EdgeBias, FloorAroundASphereRestingOnItMatchesExactIntersectionUnderAPointLight)
{
    const std::string scene = std::string("environment none\n") + kContactCamera +
                              "1\n-0.8 1.5 1.0  10 10 10\n3\n" + kRoomPigments +
                              "1\n0 0 0 0 0 0 0\n4\n" + kRoomObjects + kRestingSphere;
    const PinholeCamera camera(sceneFromText(scene).camera, kWidth, kHeight);
    expectMatchesExactGeometry(scene, floorAroundRestingSphere(camera),
                               "the floor around the sphere's contact (point light)");
}

TEST(EdgeBias, FloorAroundASphereRestingOnItMatchesExactIntersectionUnderASphereLight)
{
    const std::string scene = std::string("environment none\n") + kContactCamera + "0\n4\n" +
                              kRoomPigments + "solid 0 0 0\n2\n0 0 0 0 0 0 0\n" +
                              "10 10 10 0 0 0 0\n5\n" + kRoomObjects + kRestingSphere +
                              "3 1 sphere -0.9 1.2 0.8 0.35\n";
    const PinholeCamera camera(sceneFromText(scene).camera, kWidth, kHeight);
    expectMatchesExactGeometry(scene, floorAroundRestingSphere(camera),
                               "the floor around the sphere's contact (sphere light)");
}

// --- marched CSG solids resting on a floor (issue 36) ------------------------------------
// CSG solids are marched by every render; --exact-geometry meets them by walking their
// leaves' exact crossings (shadergen/ExactCsgIntersection.h, tests in ExactCsgTest.cpp). Where a
// solid stands on the floor, the one-pixel line of the crease held a band of samples whose
// normals the gradient's stencil tilted (its taps reached past the solid's bottom edge):
// 3-4 % too dark over the line at the default tolerance.

// The pixels along the line where a solid standing on the floor y = 0 meets it: of the rays
// through each (on a 6 x 6 grid), some meet the floor and some meet the solid within
// `height` of it.
template <typename Solid>
PixelMask creasePixels(const PinholeCamera& camera, const Solid& solid, double height)
{
    PixelMask mask;
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x) {
            bool floor = false;
            bool foot = false;
            for (int a = 0; a < 6; ++a)
                for (int b = 0; b < 6; ++b) {
                    const glm::dvec3 d = camera.direction(x + (a + 0.5) / 6.0, y + (b + 0.5) / 6.0);
                    const double floorT = d.y < 0.0 ? -camera.eye().y / d.y : 1e30;
                    const double solidT =
                        sphereTracedCrossing(solid, camera.eye(), d, std::min(floorT, 200.0));
                    if (solidT >= 0.0)
                        foot = foot || camera.eye().y + solidT * d.y < height;
                    else
                        floor = floor || floorT < 1e30;
                }
            if (floor && foot)
                mask.set(x, y);
        }
    return mask;
}

// A reddish solid on a grey floor in the open, under the sky and the given point lights.
std::string solidOnAFloorInTheOpen(const std::string& pointLights, const std::string& solid)
{
    return std::string("environment sky\n") + "0 1.5 3.4\n0 0.35 0\n0 1 0\n40\n" + pointLights +
           "2\nsolid 0.8 0.8 0.8\nsolid 0.8 0.35 0.25\n1\n0 0 0 0 0 0 0\n" +
           "2\n0 0 polyhedron 1  0 1 0 0\n1 0 " + solid + "\n";
}

TEST(EdgeBias, CreaseOfAMarchedCsgDifferenceOnAFloorMatchesExactIntersection)
{
    const glm::dmat3 turn(glm::rotate(glm::dmat4(1.0), glm::radians(25.0), glm::dvec3(0, 1, 0)));
    const std::string scene = solidOnAFloorInTheOpen(
        "1\n2.5 4 3  15 15 15\n", std::string("rotate 0 1 0 25 ") + DrilledScoopedBox::kShape);
    const PinholeCamera camera(sceneFromText(scene).camera, kWidth, kHeight);
    expectMatchesExactGeometry(scene,
                               creasePixels(camera, DrilledScoopedBox{glm::transpose(turn)}, 0.05),
                               "the crease where a CSG difference stands on the floor");
}

// The rounded cube of the test below, standing on the floor.
struct ScaledRoundedCube {
    RoundedCube cube;
    double distance(const glm::dvec3& p) const
    {
        // Scaled by 0.7 about its centre: distances in the unscaled cube's frame, times 0.7.
        return 0.7 * cube.distance(cube.center + (p - cube.center) / 0.7);
    }
};

const char* const kRoundedCubeOnTheFloor = "translate 0 0.7 0 rotate 0 1 0 -35 scale 0.7 "
                                           "intersection { sphere 0 0 0 1.3  box 0 0 0 1 1 1 }";

ScaledRoundedCube roundedCubeOnTheFloor()
{
    const glm::dmat3 turn(glm::rotate(glm::dmat4(1.0), glm::radians(-35.0), glm::dvec3(0, 1, 0)));
    return ScaledRoundedCube{RoundedCube{glm::dvec3(0.0, 0.7, 0.0), glm::transpose(turn)}};
}

TEST(EdgeBias, CreaseOfAMarchedCsgIntersectionOnAFloorMatchesExactIntersection)
{
    // The seed's rounded cube stands on its flat bottom; the sky alone lights it.
    const std::string scene = solidOnAFloorInTheOpen("0\n", kRoundedCubeOnTheFloor);
    const PinholeCamera camera(sceneFromText(scene).camera, kWidth, kHeight);
    expectMatchesExactGeometry(scene, creasePixels(camera, roundedCubeOnTheFloor(), 0.05),
                               "the crease where a CSG intersection stands on the floor");
}

// The converged march, the reference for marched solids without an exact intersection
// (smooth unions, user SDFs; docs/ACCURACY.md), is held to exact intersection where there is
// one: the same crease, at its settings.
TEST(EdgeBias, TheConvergedMarchMatchesExactIntersectionAtACsgCrease)
{
    const std::string scene = solidOnAFloorInTheOpen("0\n", kRoundedCubeOnTheFloor);
    const PinholeCamera camera(sceneFromText(scene).camera, kWidth, kHeight);
    MarchSettings converged;
    converged.hitTolerance = 0.015625f;
    converged.maxMarchSteps = 4096;
    expectMatchesExactGeometry(scene, creasePixels(camera, roundedCubeOnTheFloor(), 0.05),
                               "the crease of a CSG intersection, converged march", converged);
}

}  // namespace
}  // namespace render_tests
