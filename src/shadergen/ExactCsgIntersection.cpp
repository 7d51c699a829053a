#include "shadergen/ExactCsgIntersection.h"

#include "shadergen/ShapeCompiler.h"

#include <sstream>

namespace shadergen {

using namespace scene;

namespace {

// How often a line can cross a leaf's surface: twice for a convex solid (spheres, boxes,
// capped cylinders, a cone's one nappe, and the complement of a polyhedron's convex outside),
// four times for a torus; a user SDF's file says nothing, and its crossings are counted up to
// this many.
constexpr int kUserSdfCrossings = 16;

int crossingsAlongALine(const Geometry& geometry)
{
    if (std::holds_alternative<Torus>(geometry))
        return 4;
    if (std::holds_alternative<UserSdf>(geometry))
        return kUserSdfCrossings;
    return 2;
}

struct Leaf {
    Shape shape;  // its transform composed with every transform above it
};

// The leaves of `shape` under `above` (the transforms of its ancestors), or false where the
// tree has a smoothed operator or a leaf that cannot be met exactly as a solid.
bool collectLeaves(const Shape& shape, const std::optional<Transform>& above,
                   std::vector<Leaf>& leaves)
{
    std::optional<Transform> transform = above;
    if (shape.transform)
        transform = above ? compose(*above, *shape.transform) : *shape.transform;
    if (const auto* node = std::get_if<CsgNode>(&shape.geometry)) {
        if (describe(node->op).smoothing != CsgSmoothing::Sharp)
            return false;
        for (const Shape& child : node->children)
            if (!collectLeaves(child, transform, leaves))
                return false;
        return true;
    }
    // A disk has no inside: the walk's classification cannot see it.
    if (std::holds_alternative<Disk>(shape.geometry))
        return false;
    leaves.push_back({Shape{shape.geometry, transform}});
    return true;
}

}  // namespace

std::optional<ExactCsgCode> exactCsgIntersection(const Shape& shape, std::size_t object,
                                                 std::vector<glm::vec4>& parameters)
{
    if (!std::holds_alternative<CsgNode>(shape.geometry))
        return std::nullopt;
    std::vector<Leaf> leaves;
    if (!collectLeaves(shape, std::nullopt, leaves))
        return std::nullopt;
    const ShapeParameterAllocator allocate = [&](const std::vector<glm::vec4>& values) {
        const int first = static_cast<int>(parameters.size());
        parameters.insert(parameters.end(), values.begin(), values.end());
        return first;
    };
    const std::string id = std::to_string(object);
    std::ostringstream leafStatements;
    int crossings = 1;
    for (std::size_t i = 0; i < leaves.size(); ++i) {
        const std::optional<std::string> statements =
            exactIntersectionStatements(leaves[i].shape, i, allocate);
        if (!statements)
            return std::nullopt;
        leafStatements << *statements;
        crossings += crossingsAlongALine(leaves[i].shape.geometry);
    }
    // The solid's distance, whose sign says which side of its surface a point is on: sharp
    // operators take minima and maxima of their operands' distances, which keeps the sign of
    // the solid each builds.
    std::vector<glm::ivec4> unusedProgram;
    ShapeCompiler compiler(parameters, unusedProgram, "exactCsg" + id + "Shape");
    compiler.beginObject(object, "the exact CSG reference", 0);
    const std::string distance = compiler.emitFunction(shape);

    const std::string leafCrossing = "exactCsgLeafCrossing" + id;
    const std::string walk = "exactCsgCrossing" + id;
    std::ostringstream functions;
    functions
        << compiler.functions() << "// Object " << id << ": the first crossing of any of its "
        << leaves.size() << " leaves' surfaces in (tMin, hit.t).\n"
        << "void " << leafCrossing
        << "(vec3 origin, vec3 direction, float tMin, inout ExactHit hit)\n{\n"
        << leafStatements.str() << "}\n\n"
        << "// Object " << id
        << ": the first crossing of its surface in (tMin, hit.t), by the crossing walk\n"
           "// (shadergen/ExactCsgIntersection.h) over at most "
        << crossings << " leaf crossings.\n"
        << "bool " << walk
        << "(vec3 origin, vec3 direction, float tMin, int object, inout ExactHit hit)\n{\n"
        << "    ExactHit crossing = ExactHit(FLOAT_MAX, -1, vec3(0.0));\n"
        << "    " << leafCrossing << "(origin, direction, tMin, crossing);\n"
        << "    if (crossing.object < 0 || !(crossing.t < hit.t))\n"
        << "        return false;\n"
        << "    bool before = " << distance
        << "(origin + (0.5 * (tMin + crossing.t)) * direction) < 0.0;\n"
        << "    for (int i = 0; i < " << crossings << " && loopIterationAllowed(); ++i) {\n"
        << "        ExactHit next = ExactHit(FLOAT_MAX, -1, vec3(0.0));\n"
        << "        " << leafCrossing
        << "(origin, direction, exactCsgNextStart(crossing.t), next);\n"
        << "        float beyond = next.object >= 0 ? 0.5 * (crossing.t + next.t)\n"
        << "                                        : exactCsgBeyondEveryCrossing(crossing.t);\n"
        << "        bool after = " << distance << "(origin + beyond * direction) < 0.0;\n"
        << "        if (after != before) {\n"
        << "            hit = ExactHit(crossing.t, object,\n"
        << "                           exactCsgOutward(crossing.normal, direction, after));\n"
        << "            return true;\n"
        << "        }\n"
        << "        if (next.object < 0 || !(next.t < hit.t))\n"
        << "            return false;\n"
        << "        crossing = next;\n"
        << "        before = after;\n"
        << "    }\n"
        << "    return false;\n"
        << "}\n\n";
    return ExactCsgCode{functions.str(),
                        "    " + walk + "(origin, direction, tMin, " + id + ", hit);\n"};
}

}  // namespace shadergen
