// The scene's bounding sphere, from which scale-dependent tolerances and the far distance
// derive, and the bounds of single shapes.
#include "scene/SceneBounds.h"
#include "scene/SceneTestSupport.h"

#include <cmath>

namespace scene_tests {
namespace {

using namespace scene;

bool contains(const SceneBounds& bounds, const glm::vec3& point)
{
    return glm::length(point - bounds.center) <= bounds.radius * (1.0f + 1e-5f);
}

bool containsSphere(const ShapeBound& outer, const glm::vec3& center, float radius)
{
    return outer.finite &&
           glm::length(center - outer.center) + radius <= outer.radius * (1.0f + 1e-5f);
}

ShapeBound boundOf(const std::string& object)
{
    return boundShape(parse(sceneWithObjects(1, object)).objects.at(0).shape);
}

TEST(SceneBounds, HoldCameraLightsAndEveryFiniteShape)
{
    const Scene scene = parse("0 0 30\n0 0 0\n0 1 0\n45\n1\n-20 5 0  1 1 1\n1 solid 1 1 1\n"
                              "1 0 0 0 0 0 0 0\n2\n0 0 sphere 10 0 0 2\n"
                              "0 0 box 0 -8 0 1 1 1\n");
    const SceneBounds bounds = computeSceneBounds(scene);
    EXPECT_TRUE(contains(bounds, {0.0f, 0.0f, 30.0f})) << "the camera";
    EXPECT_TRUE(contains(bounds, {-20.0f, 5.0f, 0.0f})) << "the point light";
    EXPECT_TRUE(contains(bounds, {12.0f, 0.0f, 0.0f})) << "the sphere's far side";
    EXPECT_TRUE(contains(bounds, {1.0f, -9.0f, 1.0f})) << "the box's corner";
}

TEST(SceneBounds, ReachThePointOfEachPlaneNearestTheCamera)
{
    const SceneBounds bounds =
        computeSceneBounds(parse(sceneWithObjects(1, "0 0 polyhedron 1  0 1 0 40\n")));
    EXPECT_TRUE(contains(bounds, {0.0f, -40.0f, 5.0f}))
        << "the plane y = -40 is nearest the camera (0, 0, 5) at (0, -40, 5)";
}

TEST(SceneBounds, ScaleTheFarDistanceAndTheHitFloor)
{
    const SceneBounds small =
        computeSceneBounds(parse("0 0 0.005\n0 0 0\n0 1 0\n45\n0\n1 solid 1 1 1\n1 0 0 0 0 0 0 0\n"
                                 "1\n0 0 sphere 0 0 0 0.001\n"));
    const SceneBounds large =
        computeSceneBounds(parse("0 0 5000\n0 0 0\n0 1 0\n45\n0\n1 solid 1 1 1\n1 0 0 0 0 0 0 0\n"
                                 "1\n0 0 sphere 0 0 0 1000\n"));
    EXPECT_FLOAT_EQ(small.farDistance(), 100.0f * small.radius);
    EXPECT_NEAR(large.farDistance() / small.farDistance(), 1e6, 1e3)
        << "a scene a million times larger has a far distance a million times larger";
    EXPECT_NEAR(large.minimumHitDistance() / small.minimumHitDistance(), 1e6, 1e3);
}

TEST(ShapeBounds, SphereIsItself)
{
    const ShapeBound bound = boundOf("0 0 sphere 1 2 3 0.5\n");
    ASSERT_TRUE(bound.finite);
    EXPECT_EQ(bound.center, glm::vec3(1.0f, 2.0f, 3.0f));
    EXPECT_FLOAT_EQ(bound.radius, 0.5f);
}

TEST(ShapeBounds, PlanesAndConesAreInfinite)
{
    EXPECT_FALSE(boundOf("0 0 polyhedron 1 0 1 0 0\n").finite);
    EXPECT_FALSE(boundOf("0 0 cone 0 0 0 1 1\n").finite);
}

TEST(ShapeBounds, FiniteShapesHoldTheirExtremePoints)
{
    EXPECT_TRUE(containsSphere(boundOf("0 0 box 0 0 0 1 2 3\n"), {1.0f, 2.0f, 3.0f}, 0.0f));
    EXPECT_TRUE(containsSphere(boundOf("0 0 torus 0 0 0 2 0.5\n"), {2.5f, 0.0f, 0.0f}, 0.0f));
    EXPECT_TRUE(containsSphere(boundOf("0 0 cylinder 0 0 0 1 2\n"), {1.0f, 2.0f, 0.0f}, 0.0f));
    EXPECT_TRUE(containsSphere(boundOf("0 0 disk 0 0 0 0 1 0 3\n"), {3.0f, 0.0f, 0.0f}, 0.0f));
}

TEST(ShapeBounds, RoundedBoxHoldsItsFlatFacesAndRoundedCorners)
{
    const ShapeBound bound = boundOf("0 0 rounded_box 1 0 0 1 2 3 0.5\n");
    EXPECT_TRUE(containsSphere(bound, {1.0f, 2.0f, 0.0f}, 0.0f)) << "the middle of a face";
    // The corner's rounding: a sphere of the radius about the inner box's corner.
    EXPECT_TRUE(containsSphere(bound, {1.5f, 1.5f, 2.5f}, 0.5f));
}

TEST(ShapeBounds, UserSdfIsFiniteOnlyWithADeclaredBound)
{
    const ShapeBound declared = boundOf("0 0 twisted_bar 1 0 0\n");
    ASSERT_TRUE(declared.finite) << "twisted_bar.glsl declares @bound 1.2";
    EXPECT_FLOAT_EQ(declared.radius, 1.2f);
    EXPECT_EQ(declared.center, glm::vec3(1.0f, 0.0f, 0.0f));
}

TEST(ShapeBounds, TransformsMoveAndScaleTheBound)
{
    const ShapeBound bound = boundOf("0 0 translate 0 5 0 scale 3 sphere 1 0 0 0.5\n");
    ASSERT_TRUE(bound.finite);
    EXPECT_TRUE(glm::length(bound.center - glm::vec3(3.0f, 5.0f, 0.0f)) < 1e-5f);
    EXPECT_FLOAT_EQ(bound.radius, 1.5f);
}

TEST(ShapeBounds, UnionHoldsEveryChild)
{
    const ShapeBound bound = boundOf("0 0 union { sphere -3 0 0 1 sphere 3 0 0 1 }\n");
    EXPECT_TRUE(containsSphere(bound, {-3.0f, 0.0f, 0.0f}, 1.0f));
    EXPECT_TRUE(containsSphere(bound, {3.0f, 0.0f, 0.0f}, 1.0f));
}

TEST(ShapeBounds, IntersectionIsBoundedByItsSmallestFiniteChild)
{
    const ShapeBound bound = boundOf("0 0 intersection { polyhedron 1 0 1 0 0 sphere 0 0 0 1 }\n");
    ASSERT_TRUE(bound.finite) << "a half-space cut by a sphere is finite";
    EXPECT_FLOAT_EQ(bound.radius, 1.0f);
}

TEST(ShapeBounds, DifferenceIsBoundedByItsFirstChild)
{
    const ShapeBound bound = boundOf("0 0 difference { sphere 0 0 0 1 polyhedron 1 0 1 0 0 }\n");
    EXPECT_TRUE(containsSphere(bound, glm::vec3(0.0f), 1.0f))
        << "a sphere minus a half-space is finite and within the sphere's bound";
}

TEST(ShapeBounds, SmoothUnionGrowsByTheBlendMargin)
{
    const ShapeBound sharp = boundOf("0 0 union { sphere -1 0 0 1 sphere 1 0 0 1 }\n");
    const ShapeBound smooth =
        boundOf("0 0 smooth_union exp 4 { sphere -1 0 0 1 sphere 1 0 0 1 }\n");
    // The exponential smooth-min lies below the min by at most log(children) / k.
    EXPECT_NEAR(smooth.radius - sharp.radius, std::log(2.0f) / 4.0f, 1e-5f);
}

TEST(NearestBoundHit, MeetsSpheresAndWallsFromOutsideAndPassesThoseTheOriginIsIn)
{
    // A ball at z = -10 before a wall z <= -20, and a floor y <= -1.
    const Scene scene = parse(sceneWithObjects(
        3, "0 0 sphere 0 0 -10 2\n0 0 polyhedron 1 0 0 1 20\n0 0 polyhedron 1 0 1 0 1\n"));
    const ObjectBounds bounds = objectBounds(scene);
    ASSERT_EQ(bounds.spheres.size(), 1u);
    ASSERT_EQ(bounds.halfSpaceUnions.size(), 2u);
    const glm::vec3 back(0.0f, 0.0f, -1.0f);
    EXPECT_NEAR(nearestBoundHit(bounds, {0, 0, 0}, back).value_or(-1.0f), 8.0f, 1e-4f);
    // Beside the ball: the wall behind it.
    EXPECT_NEAR(nearestBoundHit(bounds, {5, 0, 0}, back).value_or(-1.0f), 20.0f, 1e-4f);
    // Down: the floor, one unit below.
    EXPECT_NEAR(nearestBoundHit(bounds, {5, 0, 0}, {0, -1, 0}).value_or(-1.0f), 1.0f, 1e-4f);
    // From the ball's centre, and from the floor upwards: nothing in the way.
    EXPECT_FALSE(nearestBoundHit(bounds, {0, 0, -10}, {0, 1, 0}).has_value());
    EXPECT_FALSE(nearestBoundHit(bounds, {5, -1, 0}, {0, 1, 0}).has_value());
    // Away from everything.
    EXPECT_FALSE(nearestBoundHit(bounds, {0, 0, 0}, {0, 0, 1}).has_value());
}

TEST(NearestBoundHit, FollowsTransformsAndCsgOperands)
{
    // A union of two balls, moved 10 along x by a transform.
    const Scene scene = parse(
        sceneWithObjects(1, "0 0 translate 10 0 0 union { sphere 0 0 -5 1  sphere 0 0 -9 1 }\n"));
    const ObjectBounds bounds = objectBounds(scene);
    EXPECT_EQ(bounds.spheres.size(), 2u) << "a union is its children";
    EXPECT_NEAR(nearestBoundHit(bounds, {10, 0, 0}, {0, 0, -1}).value_or(-1.0f), 4.0f, 1e-4f);
    EXPECT_FALSE(nearestBoundHit(bounds, {0, 0, 0}, {0, 0, -1}).has_value());
}

}  // namespace
}  // namespace scene_tests
