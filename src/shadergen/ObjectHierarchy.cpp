#include "shadergen/ObjectHierarchy.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace shadergen {

void Box::add(const Box& other)
{
    lower = glm::min(lower, other.lower);
    upper = glm::max(upper, other.upper);
}

void Box::add(const glm::vec3& point)
{
    lower = glm::min(lower, point);
    upper = glm::max(upper, point);
}

float Box::halfArea() const
{
    if (empty())
        return 0.0f;
    const glm::vec3 e = upper - lower;
    return e.x * e.y + e.y * e.z + e.z * e.x;
}

namespace {

glm::vec3 centreOf(const Box& box)
{
    return 0.5f * (box.lower + box.upper);
}

struct Build {
    const std::vector<HierarchyObject>& objects;
    std::vector<int>& order;  // the bounded objects, partitioned in place
    std::vector<HierarchyNode>& nodes;
};

// Where to split order[begin, end): the index of the first object of the second half, or -1
// for a leaf. Binned SAH (Wald 2007): the objects' centres binned along each axis, each bin
// boundary costed as (area of each side's box) x (objects on that side).
int chooseSplit(Build& build, int begin, int end, const Box& bounds)
{
    const int count = end - begin;
    Box centres;
    for (int i = begin; i < end; ++i)
        centres.add(centreOf(*build.objects[build.order[i]].bounds));
    float bestCost = FLT_MAX;
    int bestAxis = -1;
    int bestBin = 0;
    for (int axis = 0; axis < 3; ++axis) {
        const float low = centres.lower[axis];
        const float extent = centres.upper[axis] - low;
        if (!(extent > 0.0f))
            continue;
        std::array<Box, kSahBins> binBoxes;
        std::array<int, kSahBins> binCounts{};
        const float scale = kSahBins / extent;
        auto binOf = [&](int object) {
            const float c = centreOf(*build.objects[object].bounds)[axis];
            return std::min(kSahBins - 1, static_cast<int>((c - low) * scale));
        };
        for (int i = begin; i < end; ++i) {
            const int bin = binOf(build.order[i]);
            binBoxes[bin].add(*build.objects[build.order[i]].bounds);
            ++binCounts[bin];
        }
        // The cost of each split from the right, then from the left.
        std::array<float, kSahBins> rightCost{};
        Box right;
        int rightCount = 0;
        for (int bin = kSahBins - 1; bin > 0; --bin) {
            right.add(binBoxes[bin]);
            rightCount += binCounts[bin];
            rightCost[bin] = right.halfArea() * rightCount;
        }
        Box left;
        int leftCount = 0;
        for (int bin = 0; bin + 1 < kSahBins; ++bin) {
            left.add(binBoxes[bin]);
            leftCount += binCounts[bin];
            if (leftCount == 0 || leftCount == count)
                continue;
            const float cost = left.halfArea() * leftCount + rightCost[bin + 1];
            if (cost < bestCost) {
                bestCost = cost;
                bestAxis = axis;
                bestBin = bin;
            }
        }
    }
    // A leaf where it costs less than any split (an inner node's visit counted as one
    // object's test), where the leaf is small enough.
    const float leafCost = bounds.halfArea() * (count - 1);
    if (count <= kMostObjectsPerLeaf && !(bestCost < leafCost))
        return -1;
    if (bestAxis < 0)
        // The centres coincide: halves, as they come.
        return count <= kMostObjectsPerLeaf ? -1 : begin + count / 2;
    const float low = centres.lower[bestAxis];
    const float scale = kSahBins / (centres.upper[bestAxis] - low);
    const auto middle =
        std::partition(build.order.begin() + begin, build.order.begin() + end, [&](int object) {
            const float c = centreOf(*build.objects[object].bounds)[bestAxis];
            return std::min(kSahBins - 1, static_cast<int>((c - low) * scale)) <= bestBin;
        });
    return static_cast<int>(middle - build.order.begin());
}

}  // namespace

ObjectHierarchy buildObjectHierarchy(const std::vector<HierarchyObject>& objects,
                                     const std::function<void()>& checkpoint)
{
    ObjectHierarchy hierarchy;
    std::vector<int> order;
    for (int i = 0; i < static_cast<int>(objects.size()); ++i) {
        if (objects[i].bounds && !objects[i].bounds->empty())
            order.push_back(i);
        else
            hierarchy.unbounded.push_back(i);
    }
    if (order.empty())
        return hierarchy;
    Build build{objects, order, hierarchy.nodes};
    // Depth first with a stack of its own (a chain of lopsided splits may run deep): a node's
    // first child is pushed last, so that it is made right after its parent.
    struct Task {
        int begin, end;
        int parent;  // -1 for the root
        bool secondChild;
    };
    std::vector<Task> tasks{{0, static_cast<int>(order.size()), -1, false}};
    std::vector<int> secondChild;  // per node: its second child, or -1
    while (!tasks.empty()) {
        const Task task = tasks.back();
        tasks.pop_back();
        const int index = static_cast<int>(hierarchy.nodes.size());
        if (checkpoint && index % 1024 == 0)
            checkpoint();
        if (task.secondChild)
            secondChild[task.parent] = index;
        HierarchyNode node;
        for (int i = task.begin; i < task.end; ++i) {
            node.bounds.add(*objects[order[i]].bounds);
            node.holdsMarched = node.holdsMarched || objects[order[i]].marched;
        }
        const int split = chooseSplit(build, task.begin, task.end, node.bounds);
        if (split < 0) {
            node.first = task.begin;
            node.count = task.end - task.begin;
        } else {
            tasks.push_back({split, task.end, index, true});
            tasks.push_back({task.begin, split, index, false});
        }
        hierarchy.nodes.push_back(node);
        secondChild.push_back(-1);
    }
    // Each node's skip: a first child's is its sibling, a second child's its parent's.
    for (int i = 0; i < static_cast<int>(hierarchy.nodes.size()); ++i) {
        const HierarchyNode& node = hierarchy.nodes[i];
        if (node.count > 0)
            continue;
        hierarchy.nodes[i + 1].skip = secondChild[i];
        hierarchy.nodes[secondChild[i]].skip = node.skip;
    }
    hierarchy.leafObjects = std::move(order);
    return hierarchy;
}

namespace {

// Components this small count as zero: the ray runs parallel to that axis's slabs.
constexpr float kParallel = 1e-30f;

}  // namespace

glm::vec3 safeInverse(const glm::vec3& direction)
{
    glm::vec3 inverse;
    for (int k = 0; k < 3; ++k)
        inverse[k] = std::abs(direction[k]) < kParallel ? 1.0f : 1.0f / direction[k];
    return inverse;
}

bool rayMeetsBox(const Box& box, const glm::vec3& origin, const glm::vec3& direction,
                 const glm::vec3& inverseDirection, float tMin, float tMax)
{
    float enter = tMin;
    float leave = tMax;
    for (int k = 0; k < 3; ++k) {
        float near;
        float far;
        if (std::abs(direction[k]) < kParallel) {
            // Parallel to the slab: inside it all along, or never. (Its planes' parameters
            // would be 0 for an origin on a face, and the interval [0, 0] lose the ray.)
            const bool inside = box.lower[k] <= origin[k] && origin[k] <= box.upper[k];
            near = inside ? -FLT_MAX : FLT_MAX;
            far = inside ? FLT_MAX : -FLT_MAX;
        } else {
            const float t0 = (box.lower[k] - origin[k]) * inverseDirection[k];
            const float t1 = (box.upper[k] - origin[k]) * inverseDirection[k];
            near = std::min(t0, t1);
            far = std::max(t0, t1);
        }
        enter = std::max(enter, near);
        leave = std::min(leave, far);
    }
    return enter <= leave;
}

// The walk both queries share, as the shader's: the unbounded objects first, then the nodes
// in their depth-first order, a node that `opens` fails skipped with its subtree by its skip
// link. `value` is the query's running answer (the ray's far end, the nearest distance),
// passed through `visit`.
template <typename Opens>
float walkHierarchy(const ObjectHierarchy& hierarchy, float value, Opens opens,
                    const std::function<float(int object, float value)>& visit)
{
    for (int object : hierarchy.unbounded)
        value = visit(object, value);
    int node = hierarchy.nodes.empty() ? -1 : 0;
    while (node >= 0) {
        const HierarchyNode& n = hierarchy.nodes[node];
        if (!opens(n, value)) {
            node = n.skip;
            continue;
        }
        for (int i = n.first; i < n.first + n.count; ++i)
            value = visit(hierarchy.leafObjects[i], value);
        node = n.count > 0 ? n.skip : node + 1;
    }
    return value;
}

float traverseRay(const ObjectHierarchy& hierarchy, const glm::vec3& origin,
                  const glm::vec3& direction, float tMin, float tMax,
                  const std::function<float(int object, float tMax)>& visit)
{
    const glm::vec3 inverse = safeInverse(direction);
    return walkHierarchy(
        hierarchy, tMax,
        [&](const HierarchyNode& n, float far) {
            return rayMeetsBox(n.bounds, origin, direction, inverse, tMin, far);
        },
        visit);
}

float squaredDistanceToBox(const Box& box, const glm::vec3& point)
{
    const glm::vec3 outside = glm::max(glm::max(box.lower - point, point - box.upper), 0.0f);
    return glm::dot(outside, outside);
}

float traversePoint(const ObjectHierarchy& hierarchy, const glm::vec3& point, bool marchedOnly,
                    const std::function<float(int object, float nearest)>& visit)
{
    return walkHierarchy(
        hierarchy, FLT_MAX,
        [&](const HierarchyNode& n, float nearest) {
            // A point inside a box always looks in: a negative nearest (inside some solid)
            // must still find the solid it is deepest in, as the loop over every object does.
            const float boxDistance = std::sqrt(squaredDistanceToBox(n.bounds, point));
            return !(marchedOnly && !n.holdsMarched) &&
                   (boxDistance < nearest || boxDistance <= 0.0f);
        },
        visit);
}

}  // namespace shadergen
