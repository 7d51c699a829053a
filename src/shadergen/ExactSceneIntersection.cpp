#include "shadergen/ExactSceneIntersection.h"

#include "scene/PrimitiveKinds.h"
#include "shadergen/ExactCsgIntersection.h"
#include "shadergen/ShapeCompiler.h"

#include <functional>
#include <sstream>
#include <stdexcept>

namespace shadergen {

using namespace scene;

namespace {

std::string slot(int index)
{
    return parameterSlot(index);
}

// What a shape without an exact intersection is, for the message refusing it.
std::string shapeName(const Geometry& geometry)
{
    if (const PrimitiveKind* kind = primitiveKindOf(geometry))
        return std::string("a ") + kind->keyword +
               (kind->exactLimit != nullptr ? " where " + std::string(kind->exactLimit) : "");
    if (std::holds_alternative<UserSdf>(geometry))
        return "the user SDF '" + std::get<UserSdf>(geometry).name +
               "', whose file declares no // @intersect function";
    if (std::holds_alternative<CsgNode>(geometry))
        return "a CSG solid with a smoothed operator, or a leaf that is a disk or none of these "
               "shapes";
    return "a rounded box";
}

// "sphere, polyhedron, ... primitives": the kinds met exactly, for messages.
std::string kindsMetExactly()
{
    std::string text;
    for (const PrimitiveKind& kind : primitiveKinds())
        if (kind.exact != nullptr)
            text += (text.empty() ? "" : ", ") + std::string(kind.keyword);
    return text;
}

// `meet(tMin, hit)`: a bool expression that replaces the ExactHit `hit` by the shape's first
// crossing in (tMin, hit.t) of the ray (o, d) of its own frame, true when it did.
using MeetInFrame = std::function<std::string(const std::string&, const std::string&)>;

// The usual call of an exact* function of exact_shapes.glsl, `callHead` up to its tMin.
MeetInFrame exactCall(const std::string& callHead, const std::string& id)
{
    return [callHead, id](const std::string& tMin, const std::string& hit) {
        return callHead + tMin + ", " + id + ", " + hit + ")";
    };
}

// A shape intersected in its own frame: the ray is taken there (a similarity keeps it a ray,
// with distances divided by the scale), the hit brought back. `declarations` open the block.
std::string inFrame(const std::optional<Transform>& transform, const MeetInFrame& meet,
                    const ShapeParameterAllocator& allocate, const std::string& declarations = "")
{
    std::ostringstream out;
    if (!transform) {
        out << "    {\n"
            << declarations << "        vec3 o = origin;\n        vec3 d = direction;\n"
            << "        " << meet("tMin", "hit") << ";\n    }\n";
        return out.str();
    }
    const Transform& t = *transform;
    const int frame = allocate({glm::vec4(t.rotation[0], 0.0f), glm::vec4(t.rotation[1], 0.0f),
                                glm::vec4(t.rotation[2], 0.0f), glm::vec4(t.translation, t.scale)});
    const std::string f = std::to_string(frame);
    out << "    {\n"
        << declarations << "        float scale = " << slot(frame + 3) << ".w;\n"
        << "        vec3 o = toLocalPoint(origin, " << f << ");\n"
        << "        vec3 d = toLocalDirection(direction, " << f << ");\n"
        << "        ExactHit local = ExactHit(hit.t / scale, hit.object, hit.normal);\n"
        << "        if (" << meet("tMin / scale", "local") << ")\n"
        << "            hit = ExactHit(local.t * scale, local.object, toWorldDirection(local.normal, "
        << f << "));\n"
        << "    }\n";
    return out.str();
}

}  // namespace

std::optional<std::string> exactIntersectionStatements(const Shape& shape, std::size_t object,
                                                       const ShapeParameterAllocator& allocate)
{
    const Geometry& geometry = shape.geometry;
    const std::optional<Transform>& transform = shape.transform;
    const std::string id = std::to_string(object);
    std::ostringstream out;
    if (const PrimitiveKind* kind = primitiveKindOf(geometry)) {
        if (kind->exact == nullptr || !kind->metExactly(geometry))
            return std::nullopt;
        // A kind a similarity maps to one of its kind is met in world space, its parameters
        // transformed; the others in their own frame.
        const std::vector<glm::vec4> values = kind->exactParameters(geometry, transform);
        const int first = allocate(values);
        const std::string call = overSlots(kind->exact, [&](int k) { return slot(first + k); });
        if (!kind->unionOfTerms)
            return inFrame(kind->exactInWorld ? std::nullopt : transform, exactCall(call, id),
                           allocate);
        std::string terms;
        for (int term = 0; term < static_cast<int>(values.size()); ++term)
            terms +=
                overSlots(kind->exactTerm, [&](int) { return slot(first + term); }) + "\n        ";
        const MeetInFrame meet = [&](const std::string& tMin, const std::string& hit) {
            return terms + exactCall(call, id)(tMin, hit);
        };
        return inFrame(std::nullopt, meet, allocate,
                       "        " + std::string(kind->exactSetup) + "\n");
    }
    if (const auto* user = std::get_if<UserSdf>(&geometry); user && user->intersectFunction) {
        // The file's own intersection (// @intersect): bool F(origin, direction, x, tMin,
        // tMax, out t, out normal), in the frame its distance function is evaluated in.
        const int s = allocate({glm::vec4(user->position, 0.0f)});
        const std::string function = *user->intersectFunction;
        const MeetInFrame meet = [&](const std::string& tMin, const std::string& hit) {
            return "exactUserCrossing(" + function + "(o, d, " + slot(s) + ".xyz, " + tMin + ", " +
                   hit + ".t, crossing, outward), crossing, outward, " + id + ", " + hit + ")";
        };
        return inFrame(transform, meet, allocate,
                       "        float crossing;\n        vec3 outward;\n");
    }
    return std::nullopt;
}

std::string generateExactSceneIntersection(const Scene& scene,
                                           std::vector<glm::vec4>& shapeParameters)
{
    const ShapeParameterAllocator allocate = [&](const std::vector<glm::vec4>& values) {
        const int first = static_cast<int>(shapeParameters.size());
        shapeParameters.insert(shapeParameters.end(), values.begin(), values.end());
        return first;
    };
    std::string functions;
    std::string body;
    for (std::size_t i = 0; i < scene.objects.size(); ++i) {
        const SceneObject& object = scene.objects[i];
        if (std::optional<std::string> statements =
                exactIntersectionStatements(object.shape, i, allocate)) {
            body += *statements;
        } else if (std::optional<ExactCsgCode> csg =
                       exactCsgIntersection(object.shape, i, shapeParameters)) {
            functions += csg->functions;
            body += csg->statements;
        } else {
            throw std::runtime_error(
                scene.sourcePath.string() + ":" + std::to_string(object.line) +
                ": --exact-geometry intersects the primitives " + kindsMetExactly() +
                ", user SDFs with an // @intersect function, and union, intersection and "
                "difference blocks of these (disks excepted) exactly; this object is " +
                shapeName(object.shape.geometry) + ", which has no exact intersection here");
        }
    }
    return functions +
           "// Every object's first crossing in (tMin, hit.t), exactly (exact_shapes.glsl).\n"
           "void exactSceneIntersect(vec3 origin, vec3 direction, float tMin, "
           "inout ExactHit hit)\n{\n" +
           body + "}\n";
}

}  // namespace shadergen
