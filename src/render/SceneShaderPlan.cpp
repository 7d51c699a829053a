#include "render/SceneShaderPlan.h"

#include "scene/SceneBounds.h"

#include <map>

namespace render {

using namespace scene;

namespace {

// A plane n.x + w <= 0 (unit n) of a shape's local space, in world space.
glm::vec4 worldPlane(const glm::vec4& localPlane, const std::optional<Transform>& transform)
{
    return transform ? applyTransformToPlane(*transform, localPlane) : localPlane;
}

// The half-space an infinite cone lies in, scaled by how much slower than the distance to
// that plane the cone's distance bound dot((a, b), (|p.xz|, p.y)) may grow: the cone opens
// downwards (b > 0) below its apex, upwards (b < 0) above it. None when it opens wider
// than a half-space (a < 0) or is flat.
std::optional<glm::vec4> coneHalfSpace(const Cone& cone, const std::optional<Transform>& transform)
{
    const glm::vec2 unit = glm::normalize(cone.slope);
    if (unit.x < 0.0f || unit.y == 0.0f)
        return std::nullopt;
    const float side = unit.y > 0.0f ? 1.0f : -1.0f;
    const glm::vec4 local(0.0f, side, 0.0f, -side * cone.apex.y);
    return std::abs(unit.y) * worldPlane(local, transform);
}

}  // namespace

bool worthBounding(const SceneObject& object)
{
    return std::holds_alternative<UserSdf>(object.shape.geometry) ||
           std::holds_alternative<CsgNode>(object.shape.geometry);
}

// Top-level polyhedra (unions of half-spaces: floors, walls, rooms) and spheres are met by
// exact intersection, so a march ends at their exact crossing and never creeps along a wall
// or a floor seen at grazing angles, never stops short of one at a concave edge, and spends
// no steps on them.
ScenePlan planScene(const Scene& scene, ShapeCompiler& compiler)
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
        const bool enterable =
            scene.finishes[scene.objects[light.object].finish].material() == MaterialKind::Dielectric ||
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
        // Spheres likewise (but the lights with a culling bit, which rays meet exactly as
        // lights): a ray meets a sphere where the quadratic says, its normal is the radius's
        // direction, and its silhouette and contacts have no tolerance band.
        const auto* sphere = std::get_if<Sphere>(&shape.geometry);
        if (sphere && lightBits.count(i) == 0) {
            entry.exact = true;
            const glm::vec3 center =
                shape.transform ? applyTransform(*shape.transform, sphere->center) : sphere->center;
            const float radius = shape.transform ? shape.transform->scale * sphere->radius
                                                 : sphere->radius;
            entry.exactSphereSlot = compiler.allocateValue(glm::vec4(center, radius));
            continue;
        }
        if (const auto* polyhedron = std::get_if<Polyhedron>(&shape.geometry)) {
            entry.exact = true;
            for (const glm::vec4& plane : polyhedron->planes) {
                const glm::vec4 unit = plane / glm::length(glm::vec3(plane));
                entry.exactPlaneSlots.push_back(
                    compiler.allocateValue(worldPlane(unit, shape.transform)));
            }
            continue;
        }
        std::optional<CullingPiece> piece;
        const auto* cone = std::get_if<Cone>(&shape.geometry);
        if (bound.finite) {
            piece = CullingPiece{false, boundSlot, 0u};
        } else if (cone) {
            if (const auto plane = coneHalfSpace(*cone, shape.transform))
                piece = CullingPiece{true, compiler.allocateValue(*plane), 0u};
        }
        if (lightBits.count(i) == 0) {
            plan.marchesAnything = true;
            ++plan.marchedSurfaceCount;
        }
        if (piece) {
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

}  // namespace render
