// The hierarchy over the objects (shadergen/ObjectHierarchy.h), walked on the host in the
// shader's order (shape_interpreter.glsl), against a loop over every object: the same nearest
// hit for rays from inside boxes and along their faces, the same nearest distance for points.
// And the comparison catches a broken hierarchy: a leaf's box shrunk, two leaves' objects
// swapped, a skip that jumps a subtree.
#include "shadergen/ObjectHierarchy.h"

#include <gtest/gtest.h>

#include <cfloat>
#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

using namespace shadergen;

namespace {

// The test's shapes: balls (met exactly, or "marched" for the culled walk) and, where
// `radius` < 0, planes y = centre.y (unbounded).
struct Ball {
    glm::vec3 centre;
    float radius;
    bool marched;
};

std::vector<Ball> randomScene(std::mt19937& rng, int count, int planes)
{
    std::uniform_real_distribution<float> position(-10.0f, 10.0f);
    std::uniform_real_distribution<float> size(0.01f, 1.5f);
    std::uniform_int_distribution<int> coin(0, 3);
    std::vector<Ball> balls;
    for (int i = 0; i < count; ++i) {
        glm::vec3 centre(position(rng), position(rng), position(rng));
        // Some share their centre with the one before (boxes whose centres coincide).
        if (i > 0 && coin(rng) == 0)
            centre = balls.back().centre;
        balls.push_back({centre, size(rng), coin(rng) == 1});
    }
    for (int i = 0; i < planes; ++i)
        balls.push_back({glm::vec3(0.0f, position(rng), 0.0f), -1.0f, false});
    std::shuffle(balls.begin(), balls.end(), rng);
    return balls;
}

std::vector<HierarchyObject> hierarchyObjects(const std::vector<Ball>& balls)
{
    std::vector<HierarchyObject> objects;
    for (const Ball& ball : balls) {
        HierarchyObject object;
        object.marched = ball.marched;
        if (ball.radius >= 0.0f) {
            Box box;
            const float pad = 1e-4f * ball.radius + 1e-6f * glm::length(ball.centre) + 1e-7f;
            box.add(ball.centre - glm::vec3(ball.radius + pad));
            box.add(ball.centre + glm::vec3(ball.radius + pad));
            object.bounds = box;
        }
        objects.push_back(object);
    }
    return objects;
}

// The nearest crossing of the ball (or plane) in (tMin, tMax), else tMax.
float crossing(const Ball& ball, const glm::vec3& o, const glm::vec3& d, float tMin, float tMax)
{
    if (ball.radius < 0.0f) {
        if (d.y == 0.0f)
            return tMax;
        const float t = (ball.centre.y - o.y) / d.y;
        return t > tMin && t < tMax ? t : tMax;
    }
    const glm::vec3 oc = o - ball.centre;
    const float b = glm::dot(oc, d);
    const float c = glm::dot(oc, oc) - ball.radius * ball.radius;
    const float discriminant = b * b - c;
    if (discriminant < 0.0f)
        return tMax;
    const float root = std::sqrt(discriminant);
    for (const float t : {-b - root, -b + root})
        if (t > tMin && t < tMax)
            return t;
    return tMax;
}

float distanceTo(const Ball& ball, const glm::vec3& p)
{
    return ball.radius < 0.0f ? std::abs(p.y - ball.centre.y)
                              : glm::length(p - ball.centre) - ball.radius;
}

struct Hit {
    float t = FLT_MAX;
    int object = -1;
};

Hit linearRay(const std::vector<Ball>& balls, const glm::vec3& o, const glm::vec3& d)
{
    Hit hit;
    for (int i = 0; i < static_cast<int>(balls.size()); ++i) {
        const float t = crossing(balls[i], o, d, 0.0f, hit.t);
        if (t < hit.t)
            hit = {t, i};
    }
    return hit;
}

Hit hierarchyRay(const ObjectHierarchy& h, const std::vector<Ball>& balls, const glm::vec3& o,
                 const glm::vec3& d)
{
    Hit hit;
    traverseRay(h, o, d, 0.0f, FLT_MAX, [&](int object, float tMax) {
        const float t = crossing(balls[object], o, d, 0.0f, tMax);
        if (t < tMax)
            hit = {t, object};
        return std::min(t, tMax);
    });
    return hit;
}

Hit linearPoint(const std::vector<Ball>& balls, const glm::vec3& p, bool marchedOnly)
{
    Hit nearest;
    for (int i = 0; i < static_cast<int>(balls.size()); ++i) {
        if (marchedOnly && !balls[i].marched)
            continue;
        const float d = distanceTo(balls[i], p);
        if (d < nearest.t)
            nearest = {d, i};
    }
    return nearest;
}

Hit hierarchyPoint(const ObjectHierarchy& h, const std::vector<Ball>& balls, const glm::vec3& p,
                   bool marchedOnly)
{
    Hit nearest;
    traversePoint(h, p, marchedOnly, [&](int object, float known) {
        if (marchedOnly && !balls[object].marched)
            return known;
        const float d = distanceTo(balls[object], p);
        if (d < known)
            nearest = {d, object};
        return std::min(d, known);
    });
    return nearest;
}

glm::vec3 randomDirection(std::mt19937& rng)
{
    std::normal_distribution<float> gauss;
    glm::vec3 d(gauss(rng), gauss(rng), gauss(rng));
    return glm::normalize(d);
}

// The queries the hierarchy is judged on: rays from inside objects' boxes in random
// directions, rays along the faces of objects' boxes (axis directions, origin on the face),
// rays from outside everything; points inside boxes and anywhere. Counts the queries whose
// nearest hit (or distance) differs from the loop's.
int mismatches(const ObjectHierarchy& h, const std::vector<Ball>& balls, std::mt19937 rng)
{
    const std::vector<HierarchyObject> objects = hierarchyObjects(balls);
    std::uniform_int_distribution<int> pick(0, static_cast<int>(balls.size()) - 1);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    std::uniform_real_distribution<float> anywhere(-14.0f, 14.0f);
    int wrong = 0;
    auto judgeRay = [&](const glm::vec3& o, const glm::vec3& d) {
        const Hit a = linearRay(balls, o, d);
        const Hit b = hierarchyRay(h, balls, o, d);
        if (a.object != b.object && a.t != b.t)
            ++wrong;
    };
    auto judgePoint = [&](const glm::vec3& p) {
        for (const bool marchedOnly : {false, true}) {
            const Hit a = linearPoint(balls, p, marchedOnly);
            const Hit b = hierarchyPoint(h, balls, p, marchedOnly);
            if (a.t != b.t) {
                if (getenv("DEBUG_H"))
                    printf("point %g %g %g %d: %d %g vs %d %g\n", p.x, p.y, p.z, marchedOnly,
                           a.object, a.t, b.object, b.t);
                ++wrong;
            }
        }
    };
    for (int i = 0; i < 3000; ++i) {
        const HierarchyObject& object = objects[pick(rng)];
        if (!object.bounds)
            continue;
        const Box& box = *object.bounds;
        const glm::vec3 inside =
            glm::mix(box.lower, box.upper, glm::vec3(unit(rng), unit(rng), unit(rng)));
        judgeRay(inside, randomDirection(rng));
        judgePoint(inside);
        // Along a face: the origin on the face (axis `a` at a bound), the direction along
        // another axis, both ways, so that the ray lies in the face's plane.
        const int a = i % 3;
        glm::vec3 onFace = inside;
        onFace[a] = (i & 1) ? box.lower[a] : box.upper[a];
        glm::vec3 along(0.0f);
        along[(a + 1 + (i / 3) % 2) % 3] = (i / 6) % 2 ? 1.0f : -1.0f;
        judgeRay(onFace - 20.0f * along, along);
        judgeRay(onFace, along);
        const glm::vec3 outside(anywhere(rng), anywhere(rng), anywhere(rng));
        judgeRay(outside, randomDirection(rng));
        judgePoint(outside);
    }
    return wrong;
}

// mismatches, printed: how many of the queries a corruption changes.
int reportedMismatches(const ObjectHierarchy& h, const std::vector<Ball>& balls, std::mt19937 rng)
{
    const int wrong = mismatches(h, balls, rng);
    std::printf("%d of the queries differ from the loop's\n", wrong);
    return wrong;
}

struct Case {
    std::vector<Ball> balls;
    ObjectHierarchy hierarchy;
};

Case randomCase(unsigned seed, int count, int planes)
{
    std::mt19937 rng(seed);
    Case c;
    c.balls = randomScene(rng, count, planes);
    c.hierarchy = buildObjectHierarchy(hierarchyObjects(c.balls));
    return c;
}

// The first leaf, and a leaf in the root's other subtree.
std::pair<int, int> twoLeavesApart(const ObjectHierarchy& h)
{
    int first = -1;
    for (int i = 0; i < static_cast<int>(h.nodes.size()); ++i)
        if (h.nodes[i].count > 0) {
            if (first < 0)
                first = i;
            else if (i >= h.nodes[1].skip)
                return {first, i};
        }
    return {first, -1};
}

}  // namespace

TEST(ObjectHierarchy, EveryBoundedObjectIsInOneLeafAndEveryBoxHoldsWhatIsBelowIt)
{
    const Case c = randomCase(1, 500, 3);
    const ObjectHierarchy& h = c.hierarchy;
    EXPECT_EQ(h.unbounded.size(), 3u);
    std::vector<int> seen(c.balls.size(), 0);
    for (int object : h.leafObjects)
        ++seen[object];
    for (int object : h.unbounded)
        ++seen[object];
    for (int count : seen)
        EXPECT_EQ(count, 1);
    const std::vector<HierarchyObject> objects = hierarchyObjects(c.balls);
    for (int i = 0; i < static_cast<int>(h.nodes.size()); ++i) {
        const HierarchyNode& node = h.nodes[i];
        EXPECT_TRUE(node.skip == -1 || node.skip > i) << "node " << i;
        // Every node of its subtree lies between it and its skip, inside its box.
        const int end = node.skip < 0 ? static_cast<int>(h.nodes.size()) : node.skip;
        for (int j = i; j < end; ++j) {
            EXPECT_TRUE(glm::all(glm::lessThanEqual(node.bounds.lower, h.nodes[j].bounds.lower)));
            EXPECT_TRUE(
                glm::all(glm::greaterThanEqual(node.bounds.upper, h.nodes[j].bounds.upper)));
            for (int k = h.nodes[j].first; k < h.nodes[j].first + h.nodes[j].count; ++k) {
                const Box& box = *objects[h.leafObjects[k]].bounds;
                EXPECT_TRUE(glm::all(glm::lessThanEqual(node.bounds.lower, box.lower)));
                EXPECT_TRUE(glm::all(glm::greaterThanEqual(node.bounds.upper, box.upper)));
            }
        }
    }
}

TEST(ObjectHierarchy, TraversalFindsWhatALoopOverEveryObjectFinds)
{
    for (const unsigned seed : {2u, 3u, 4u}) {
        for (const int count : {1, 5, 300}) {
            const Case c = randomCase(seed, count, seed % 2 ? 2 : 0);
            EXPECT_EQ(mismatches(c.hierarchy, c.balls, std::mt19937(seed)), 0)
                << "seed " << seed << ", " << count << " objects";
        }
    }
}

TEST(ObjectHierarchy, ASceneOfOnlyUnboundedObjectsHasNoNodes)
{
    const Case c = randomCase(5, 0, 3);
    EXPECT_TRUE(c.hierarchy.nodes.empty());
    EXPECT_EQ(mismatches(c.hierarchy, c.balls, std::mt19937(5)), 0);
}

// The comparison above fails on a broken hierarchy: each corruption below is caught.
TEST(ObjectHierarchy, TheComparisonCatchesALeafBoxShrunk)
{
    Case c = randomCase(6, 300, 1);
    const int leaf = twoLeavesApart(c.hierarchy).first;
    Box& box = c.hierarchy.nodes[leaf].bounds;
    const glm::vec3 centre = 0.5f * (box.lower + box.upper);
    box.lower = glm::mix(centre, box.lower, 0.5f);
    box.upper = glm::mix(centre, box.upper, 0.5f);
    EXPECT_GT(reportedMismatches(c.hierarchy, c.balls, std::mt19937(6)), 0);
}

TEST(ObjectHierarchy, TheComparisonCatchesTwoLeavesObjectsSwapped)
{
    Case c = randomCase(7, 300, 1);
    const auto [a, b] = twoLeavesApart(c.hierarchy);
    ASSERT_GE(b, 0);
    std::swap(c.hierarchy.nodes[a].first, c.hierarchy.nodes[b].first);
    std::swap(c.hierarchy.nodes[a].count, c.hierarchy.nodes[b].count);
    EXPECT_GT(reportedMismatches(c.hierarchy, c.balls, std::mt19937(7)), 0);
}

TEST(ObjectHierarchy, TheComparisonCatchesAChildSwappedForItsSibling)
{
    // The root's first child's subtree replaced by its sibling's: the second child is visited
    // twice, the first never.
    Case c = randomCase(8, 300, 1);
    ASSERT_EQ(c.hierarchy.nodes[0].count, 0);
    c.hierarchy.nodes[0].count = 0;
    const int second = c.hierarchy.nodes[1].skip;
    c.hierarchy.nodes.erase(c.hierarchy.nodes.begin() + 1, c.hierarchy.nodes.begin() + second);
    const int removed = second - 1;
    for (HierarchyNode& node : c.hierarchy.nodes)
        if (node.skip > 0)
            node.skip -= removed;
    EXPECT_GT(reportedMismatches(c.hierarchy, c.balls, std::mt19937(8)), 0);
}

TEST(ObjectHierarchy, TheComparisonCatchesASkipPastASibling)
{
    Case c = randomCase(9, 300, 1);
    c.hierarchy.nodes[1].skip = c.hierarchy.nodes[0].skip;  // never reaches the second child
    EXPECT_GT(reportedMismatches(c.hierarchy, c.balls, std::mt19937(9)), 0);
}

TEST(ObjectHierarchy, LeavesHoldAFewObjectsAndTheBuildCanBeAbandoned)
{
    const Case c = randomCase(10, 2000, 0);
    std::size_t largest = 0;
    for (const HierarchyNode& node : c.hierarchy.nodes)
        largest = std::max<std::size_t>(largest, node.count);
    // Coinciding centres (a quarter of the objects share their neighbour's) may pair up.
    EXPECT_LE(largest, static_cast<std::size_t>(kMostObjectsPerLeaf));
    int calls = 0;
    struct Abandoned {};
    EXPECT_THROW(buildObjectHierarchy(hierarchyObjects(c.balls),
                                      [&] {
                                          if (++calls == 1)
                                              throw Abandoned{};
                                      }),
                 Abandoned);
    EXPECT_EQ(calls, 1);
}
