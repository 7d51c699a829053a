#include "shadergen/ExactSceneIntersection.h"

#include <functional>
#include <sstream>
#include <stdexcept>

namespace shadergen {

using namespace scene;

namespace {

std::string slot(int index)
{
    return "uShapeParameters[" + std::to_string(index) + "]";
}

std::string shapeName(const Geometry& geometry)
{
    if (std::holds_alternative<Torus>(geometry)) {
        std::ostringstream name;
        name << "a torus whose minor radius is under " << kThinnestExactTorus
             << " of its major radius (its quartic loses too many digits in float32)";
        return name.str();
    }
    if (std::holds_alternative<UserSdf>(geometry))
        return "the user SDF '" + std::get<UserSdf>(geometry).name +
               "', whose file declares no // @intersect function";
    return "a CSG solid";
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
        out << "    {\n" << declarations << "        vec3 o = origin;\n        vec3 d = direction;\n"
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
    if (const auto* sphere = std::get_if<Sphere>(&geometry)) {
        // A similarity keeps a sphere a sphere: it is met in world space.
        const glm::vec3 center =
            transform ? applyTransform(*transform, sphere->center) : sphere->center;
        const float radius = transform ? transform->scale * sphere->radius : sphere->radius;
        out << "    exactSphere(origin, direction, " << slot(allocate({glm::vec4(center, radius)}))
            << ", tMin, " << id << ", hit);\n";
    } else if (const auto* polyhedron = std::get_if<Polyhedron>(&geometry)) {
        out << "    {\n        ConvexInterval outside = wholeRay();\n";
        for (const glm::vec4& plane : polyhedron->planes) {
            const glm::vec4 unit = plane / glm::length(glm::vec3(plane));
            const glm::vec4 world = transform ? applyTransformToPlane(*transform, unit) : unit;
            out << "        clipOutsideHalfSpace(outside, origin, direction, "
                << slot(allocate({world})) << ");\n";
        }
        out << "        exactHalfSpaceUnion(outside, tMin, " << id << ", hit);\n    }\n";
    } else if (const auto* disk = std::get_if<Disk>(&geometry)) {
        glm::vec3 center = disk->center;
        glm::vec3 normal = glm::normalize(disk->normal);
        float radius = disk->radius;
        if (transform) {
            center = applyTransform(*transform, center);
            normal = transform->rotation * normal;
            radius *= transform->scale;
        }
        const int s = allocate({glm::vec4(center, radius), glm::vec4(normal, 0.0f)});
        out << "    exactDisk(origin, direction, " << slot(s) << ", " << slot(s + 1)
            << ".xyz, tMin, " << id << ", hit);\n";
    } else if (const auto* box = std::get_if<Box>(&geometry)) {
        const int s =
            allocate({glm::vec4(box->center, 0.0f), glm::vec4(box->halfExtents, 0.0f)});
        out << inFrame(transform,
                       exactCall("exactBox(o, d, " + slot(s) + ".xyz, " + slot(s + 1) + ".xyz, ", id),
                       allocate);
    } else if (const auto* cylinder = std::get_if<Cylinder>(&geometry)) {
        const int s = allocate({glm::vec4(cylinder->center, cylinder->radius),
                                glm::vec4(cylinder->halfHeight, 0.0f, 0.0f, 0.0f)});
        out << inFrame(transform,
                       exactCall("exactCappedCylinder(o, d, " + slot(s) + ".xyz, " + slot(s) +
                                     ".w, " + slot(s + 1) + ".x, ",
                                 id),
                       allocate);
    } else if (const auto* torus = std::get_if<Torus>(&geometry);
               torus && torus->minorRadius >= kThinnestExactTorus * torus->majorRadius) {
        const int s = allocate({glm::vec4(torus->center, torus->majorRadius),
                                glm::vec4(torus->minorRadius, 0.0f, 0.0f, 0.0f)});
        out << inFrame(transform,
                       exactCall("exactTorus(o, d, " + slot(s) + ".xyz, " + slot(s) + ".w, " +
                                     slot(s + 1) + ".x, ",
                                 id),
                       allocate);
    } else if (const auto* cone = std::get_if<Cone>(&geometry)) {
        const glm::vec2 unit = glm::normalize(cone->slope);
        const int s = allocate({glm::vec4(cone->apex, 0.0f), glm::vec4(unit, 0.0f, 0.0f)});
        out << inFrame(transform,
                       exactCall("exactCone(o, d, " + slot(s) + ".xyz, " + slot(s + 1) + ".xy, ", id),
                       allocate);
    } else if (const auto* user = std::get_if<UserSdf>(&geometry);
               user && user->intersectFunction) {
        // The file's own intersection (// @intersect): bool F(origin, direction, x, tMin,
        // tMax, out t, out normal), in the frame its distance function is evaluated in.
        const int s = allocate({glm::vec4(user->position, 0.0f)});
        const std::string function = *user->intersectFunction;
        const MeetInFrame meet = [&](const std::string& tMin, const std::string& hit) {
            return "exactUserCrossing(" + function + "(o, d, " + slot(s) + ".xyz, " + tMin +
                   ", " + hit + ".t, crossing, outward), crossing, outward, " + id + ", " + hit +
                   ")";
        };
        out << inFrame(transform, meet, allocate,
                       "        float crossing;\n        vec3 outward;\n");
    } else {
        return std::nullopt;
    }
    return out.str();
}

std::string generateExactSceneIntersection(const Scene& scene,
                                           std::vector<glm::vec4>& shapeParameters)
{
    const ShapeParameterAllocator allocate = [&](const std::vector<glm::vec4>& values) {
        const int first = static_cast<int>(shapeParameters.size());
        shapeParameters.insert(shapeParameters.end(), values.begin(), values.end());
        return first;
    };
    std::string body;
    for (std::size_t i = 0; i < scene.objects.size(); ++i) {
        const SceneObject& object = scene.objects[i];
        const std::optional<std::string> statements =
            exactIntersectionStatements(object.shape, i, allocate);
        if (!statements)
            throw std::runtime_error(
                scene.sourcePath.string() + ":" + std::to_string(object.line) +
                ": --exact-geometry intersects spheres, polyhedra, boxes, cylinders, disks, cones, "
                "tori and user SDFs with an // @intersect function exactly; this object is " + shapeName(object.shape.geometry) +
                ", which has no exact intersection here");
        body += *statements;
    }
    return "// Every object's first crossing in (tMin, hit.t), exactly (exact_shapes.glsl).\n"
           "void exactSceneIntersect(vec3 origin, vec3 direction, float tMin, "
           "inout ExactHit hit)\n{\n" +
           body + "}\n";
}

}  // namespace shadergen
