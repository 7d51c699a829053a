#include "shadergen/SceneShaderPlan.h"

#include "scene/PrimitiveKinds.h"
#include "scene/SceneBounds.h"
#include "shadergen/ExactSceneIntersection.h"

#include <map>

namespace shadergen {

using namespace scene;

bool worthBounding(const SceneObject& object)
{
    return std::holds_alternative<UserSdf>(object.shape.geometry) ||
           std::holds_alternative<CsgNode>(object.shape.geometry);
}

// Top-level shapes with a closed-form intersection (polyhedra: floors, walls, rooms; spheres,
// boxes, capped cylinders, disks, cones) are met by exact intersection, so a march ends at their
// exact crossing and never creeps along a wall or a floor seen at grazing angles, never
// stops short of one at a concave edge, never stops near a silhouette or a contact it does
// not meet, and spends no steps on them.
ScenePlan planScene(const Scene& scene, ShapeCompiler& compiler, bool marchBoxesCylindersAndDisks)
{
    ScenePlan plan;
    int nextBit = 0;
    auto takeBit = [&]() -> std::optional<std::uint32_t> {
        if (nextBit == kCullingBits)
            return std::nullopt;
        return 1u << nextBit++;
    };
    // Sphere lights take their bits first: rays leave every light that has one out of their
    // marches and meet it exactly instead (ray_queries_traced.glsl).
    std::map<std::size_t, std::uint32_t> lightBits;
    for (const SphereLight& light : sphereLights(scene))
        if (const auto bit = takeBit())
            lightBits[static_cast<std::size_t>(light.object)] = *bit;
    plan.objectCullingBits.assign(scene.objects.size(), 0u);
    // Whether any ray ever marches: a light with a bit is marched only by rays inside it,
    // which need a way in (a dielectric finish) or a camera inside it.
    plan.marchesAnything = false;
    for (const SphereLight& light : sphereLights(scene)) {
        const bool enterable = scene.finishes[scene.objects[light.object].finish].material() ==
                                   MaterialKind::Dielectric ||
                               glm::length(scene.camera.eye - light.center) < light.radius;
        if (enterable && lightBits.count(static_cast<std::size_t>(light.object)) != 0)
            ++plan.marchedSurfaceCount;
        if (enterable || lightBits.count(static_cast<std::size_t>(light.object)) == 0)
            plan.marchesAnything = true;
    }
    for (std::size_t i = 0; i < scene.objects.size(); ++i) {
        const SceneObject& object = scene.objects[i];
        const Shape& shape = object.shape;
        const ShapeBound bound = boundShape(shape);
        const int boundSlot = bound.finite ? compiler.allocateBound(bound) : -1;
        compiler.beginObject(i, scene.sourcePath.filename().string(), object.line);
        ObjectPlan& entry = plan.objects.emplace_back();
        entry.object = i;
        entry.line = object.line;
        entry.function = compiler.emitFunction(shape);
        // Every other shape with a closed form likewise (but the sphere lights with a culling
        // bit, which rays meet exactly as lights): a ray meets a sphere, a box, a capped
        // cylinder, a disk or a cone where the quadratic or the slabs say, with the shape's
        // own normal, and its silhouettes, edges and contacts have no tolerance band.
        const PrimitiveKind* kind = primitiveKindOf(shape.geometry);
        const bool marchedOnRequest = marchBoxesCylindersAndDisks && kind && kind->marchedOnRequest;
        if (lightBits.count(i) == 0 && !marchedOnRequest) {
            const ShapeParameterAllocator allocate = [&](const std::vector<glm::vec4>& values) {
                const int first = compiler.allocateValues(values);
                for (int k = 0; k < static_cast<int>(values.size()); ++k)
                    entry.exactSlots.push_back(first + k);
                return first;
            };
            if (std::optional<std::string> statements =
                    exactIntersectionStatements(shape, i, allocate)) {
                entry.exact = true;
                entry.exactIntersection = std::move(*statements);
                continue;
            }
        }
        // What is left to march is culled by its bounding ball, where it has one.
        std::optional<CullingPiece> piece;
        if (bound.finite)
            piece = CullingPiece{boundSlot, 0u};
        if (lightBits.count(i) == 0) {
            plan.marchesAnything = true;
            ++plan.marchedSurfaceCount;
        }
        if (piece) {
            if (const auto* user = std::get_if<UserSdf>(&shape.geometry);
                user && !user->hullPlanes.empty()) {
                std::vector<glm::vec4> planes;
                for (const glm::vec4& relative : user->hullPlanes) {
                    const glm::vec3 normal(relative);
                    glm::vec4 plane(normal, relative.w - glm::dot(normal, user->position));
                    if (shape.transform)
                        plane = applyTransformToPlane(*shape.transform, plane);
                    planes.push_back(plane);
                }
                piece->hullSlot = compiler.allocateValues(planes);
                piece->hullPlanes = static_cast<int>(planes.size());
            }
            const auto reserved = lightBits.find(i);
            const std::optional<std::uint32_t> bit =
                reserved != lightBits.end() ? std::optional<std::uint32_t>(reserved->second)
                                            : takeBit();
            if (bit) {
                piece->bit = *bit;
                entry.culling = piece;
                plan.objectCullingBits[i] = *bit;
            }
        }
        if (!entry.culling)
            plan.everyObjectCulled = false;
        if (worthBounding(object) && bound.finite)
            entry.boundSlot = boundSlot;
    }
    return plan;
}

}  // namespace shadergen
