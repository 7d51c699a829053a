#pragma once
// A bounding-volume hierarchy over a scene's objects (issue 33): what lets the general shader
// find surfaces among 100,000 objects at a cost that grows with the logarithm of their number.
// Built on the host by binned SAH over each object's world-space box (a CSG tree is one object
// with one box), flattened depth first, each node with the index of the node that follows its
// subtree, so that the shader walks it without a stack (shape_interpreter.glsl): a ray or a
// point that meets a node's box goes on to the next node, one that misses it goes to its
// `skip`. Objects without a finite bound (planes, cones) stay out of it, in a short list every
// query tests. No OpenGL: render/SceneDataBuffers uploads it.
#include <glm/glm.hpp>

#include <cfloat>
#include <functional>
#include <optional>
#include <vector>

namespace shadergen {

// An axis-aligned box; empty (lower > upper) until something is added.
struct Box {
    glm::vec3 lower{FLT_MAX};
    glm::vec3 upper{-FLT_MAX};

    bool empty() const { return lower.x > upper.x; }
    void add(const Box& other);
    void add(const glm::vec3& point);
    // Half the surface area (SAH compares ratios only); 0 when empty.
    float halfArea() const;
};

// The objects of a leaf, or an inner node whose first child is the next node and whose
// second child is the first node after the first child's subtree.
struct HierarchyNode {
    Box bounds;
    int skip = -1;  // the node after this one's subtree in depth-first order; -1: the end
    int first = 0;  // a leaf's objects: ObjectHierarchy::leafObjects[first, first + count)
    int count = 0;  // 0: an inner node
    bool holdsMarched = false;  // an object below it is marched (not met exactly)
};

struct ObjectHierarchy {
    std::vector<HierarchyNode> nodes;  // depth first; nodes[0] the root; empty without objects
    std::vector<int> leafObjects;      // the objects of the leaves, leaf after leaf
    std::vector<int> unbounded;        // objects without a finite box, tested by every query
};

// What the hierarchy needs of each object.
struct HierarchyObject {
    std::optional<Box> bounds;  // world space; none: unbounded
    bool marched = false;       // found by marching its distance rather than met exactly
};

// A leaf holds at most this many objects (more only where their boxes' centres coincide).
constexpr int kMostObjectsPerLeaf = 4;
// The candidate split planes per axis of the binned SAH build.
constexpr int kSahBins = 12;

// Builds the hierarchy. `checkpoint`, where given, is called before the first node and every
// 1024 nodes after: it may throw to abandon the build (an interrupt during set-up).
ObjectHierarchy buildObjectHierarchy(const std::vector<HierarchyObject>& objects,
                                     const std::function<void()>& checkpoint = {});

// --- the shader's traversals, on the host (tests compare them with a loop over every object) --

// Whether the ray's parameter interval within `box`, clipped to [tMin, tMax], is not empty.
// Inclusive of the faces: a ray along a face meets the box. A direction component below 1e-30
// counts as zero: that slab holds the ray all along or never.
bool rayMeetsBox(const Box& box, const glm::vec3& origin, const glm::vec3& direction,
                 const glm::vec3& inverseDirection, float tMin, float tMax);
// 1 / direction, with 1 for the components rayMeetsBox counts as zero.
glm::vec3 safeInverse(const glm::vec3& direction);

// Visits, in the shader's order, every object whose leaf box the ray crosses within
// [tMin, tMax] (the unbounded objects first): `visit(object, tMax)` returns the new tMax (the
// nearest hit so far), which prunes the rest. Returns the final tMax.
float traverseRay(const ObjectHierarchy& hierarchy, const glm::vec3& origin,
                  const glm::vec3& direction, float tMin, float tMax,
                  const std::function<float(int object, float tMax)>& visit);

// Squared distance from `point` to `box` (0 inside).
float squaredDistanceToBox(const Box& box, const glm::vec3& point);

// Visits, in the shader's order, every object whose leaf box is nearer `point` than the
// nearest distance so far (the unbounded objects first): `visit(object, nearest)` returns the
// new nearest distance. Returns it. `marchedOnly`: nodes holding no marched object are skipped
// (the culled distances the sphere tracer marches).
float traversePoint(const ObjectHierarchy& hierarchy, const glm::vec3& point, bool marchedOnly,
                    const std::function<float(int object, float nearest)>& visit);

}  // namespace shadergen
