#include "scene/SceneBounds.h"

#include "scene/Lights.h"
#include "scene/PrimitiveKinds.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace scene {

namespace {

struct Box3 {
    glm::vec3 low{std::numeric_limits<float>::max()};
    glm::vec3 high{std::numeric_limits<float>::lowest()};

    void add(const glm::vec3& point)
    {
        low = glm::min(low, point);
        high = glm::max(high, point);
    }
    void add(const glm::vec3& center, float radius)
    {
        add(center - glm::vec3(radius));
        add(center + glm::vec3(radius));
    }
    bool empty() const { return low.x > high.x; }
};

ShapeBound enclose(const std::vector<ShapeBound>& bounds, float margin)
{
    Box3 box;
    for (const ShapeBound& bound : bounds) {
        if (!bound.finite)
            return {};
        box.add(bound.center, bound.radius);
    }
    const glm::vec3 center = 0.5f * (box.low + box.high);
    return finiteBound(center, 0.5f * glm::length(box.high - box.low) + margin);
}

// How far a smooth operator may push the surface beyond the plain one.
float smoothMargin(const CsgNode& node)
{
    const float children = static_cast<float>(node.children.size());
    switch (describe(node.op).smoothing) {
    case CsgSmoothing::Exponential:
        return std::log(children) / node.parameter;
    case CsgSmoothing::Polynomial:
        return 0.25f * node.parameter * (children - 1.0f);
    case CsgSmoothing::Sharp:
        return 0.0f;
    }
    return 0.0f;
}

struct LocalBound {
    const Shape& shape;

    template <typename P, std::enable_if_t<kIsPrimitive<P>, int> = 0>
    ShapeBound operator()(const P& primitive) const
    {
        return Primitive<P>::bound(primitive);
    }
    ShapeBound operator()(const UserSdf& user) const
    {
        if (!user.boundingRadius)
            return {};
        return finiteBound(user.position, *user.boundingRadius);
    }
    ShapeBound operator()(const CsgNode& node) const
    {
        std::vector<ShapeBound> children;
        for (const Shape& child : node.children)
            children.push_back(boundShape(child));
        const CsgCombination combination = describe(node.op).combination;
        if (combination == CsgCombination::Difference)
            children.resize(1);
        if (combination == CsgCombination::Intersection) {
            // Any one finite child bounds an intersection; take the smallest.
            ShapeBound best;
            for (const ShapeBound& child : children)
                if (child.finite && (!best.finite || child.radius < best.radius))
                    best = child;
            if (best.finite)
                best.radius += smoothMargin(node);
            return best;
        }
        return enclose(children, smoothMargin(node));
    }
};

// A point on each infinite shape, so that the bounds reach it.
void addInfinitePoints(const Shape& shape, const glm::vec3& camera, Box3& box)
{
    auto toWorld = [&](const glm::vec3& local) {
        return shape.transform ? applyTransform(*shape.transform, local) : local;
    };
    if (const auto* polyhedron = std::get_if<Polyhedron>(&shape.geometry)) {
        glm::vec3 localCamera = camera;
        if (shape.transform)
            localCamera = glm::transpose(shape.transform->rotation) *
                          (camera - shape.transform->translation) / shape.transform->scale;
        for (const glm::vec4& plane : polyhedron->planes) {
            const glm::vec3 normal(plane);
            const float distance =
                (glm::dot(normal, localCamera) + plane.w) / glm::dot(normal, normal);
            box.add(toWorld(localCamera - distance * normal));
        }
    } else if (const auto* cone = std::get_if<Cone>(&shape.geometry)) {
        box.add(toWorld(cone->apex));
    } else if (const auto* node = std::get_if<CsgNode>(&shape.geometry)) {
        for (const Shape& child : node->children) {
            Shape placed = child;
            if (shape.transform)
                placed.transform = compose(*shape.transform, child.transform.value_or(Transform{}));
            addInfinitePoints(placed, camera, box);
        }
    } else if (const auto* user = std::get_if<UserSdf>(&shape.geometry)) {
        if (!user->boundingRadius)
            box.add(toWorld(user->position));
    }
}

}  // namespace

ShapeBound boundShape(const Shape& shape)
{
    ShapeBound local = std::visit(LocalBound{shape}, shape.geometry);
    if (!local.finite || !shape.transform)
        return local;
    const Transform& transform = *shape.transform;
    local.center = applyTransform(transform, local.center);
    local.radius *= transform.scale;
    return local;
}

float SceneBounds::minimumHitDistance() const
{
    return 1e-5f * std::max(radius, glm::length(center));
}

SceneBounds computeSceneBounds(const Scene& scene)
{
    Box3 box;
    box.add(scene.camera.eye);
    // The lights that have a place but are no object (the objects follow).
    for (const Light& light : sceneLights(scene))
        if (describe(light.kind).emitter == Emitter::DeltaPosition)
            box.add(light.position);
    for (const SceneObject& object : scene.objects) {
        const ShapeBound bound = boundShape(object.shape);
        if (bound.finite)
            box.add(bound.center, bound.radius);
        addInfinitePoints(object.shape, scene.camera.eye, box);
    }
    SceneBounds bounds;
    bounds.center = 0.5f * (box.low + box.high);
    bounds.radius = 0.5f * glm::length(box.high - box.low);
    if (!(bounds.radius > 0.0f) || !std::isfinite(bounds.radius))
        bounds.radius = std::max(1.0f, glm::length(bounds.center) * 1e-3f);
    return bounds;
}

namespace {

void addObjectBounds(const Shape& shape, const Transform& placement, ObjectBounds& bounds)
{
    if (const auto* polyhedron = std::get_if<Polyhedron>(&shape.geometry)) {
        std::vector<glm::vec4> planes;
        for (const glm::vec4& plane : polyhedron->planes) {
            const float length = glm::length(glm::vec3(plane));
            if (length > 0.0f)
                planes.push_back(applyTransformToPlane(placement, plane / length));
        }
        if (!planes.empty())
            bounds.halfSpaceUnions.push_back(std::move(planes));
        return;
    }
    if (const auto* node = std::get_if<CsgNode>(&shape.geometry)) {
        const CsgCombination combination = describe(node->op).combination;
        const ShapeBound whole = boundShape(Shape{shape.geometry, placement});
        if (combination != CsgCombination::Union && whole.finite) {
            bounds.spheres.push_back(whole);
            return;
        }
        // A union is its children; an intersection or a difference lies inside its first.
        // Smooth operators may push the surface out by their margin: a bound that is a
        // sphere carries it, exact half-spaces do not (too small to matter to the camera).
        for (const Shape& child : node->children) {
            addObjectBounds(child, compose(placement, child.transform.value_or(Transform{})),
                            bounds);
            if (combination != CsgCombination::Union)
                break;
        }
        return;
    }
    const ShapeBound bound = boundShape(Shape{shape.geometry, placement});
    if (bound.finite)
        bounds.spheres.push_back(bound);
}

}  // namespace

ObjectBounds objectBounds(const Scene& scene)
{
    ObjectBounds bounds;
    for (const SceneObject& object : scene.objects)
        addObjectBounds(object.shape, object.shape.transform.value_or(Transform{}), bounds);
    return bounds;
}

std::optional<float> nearestBoundHit(const ObjectBounds& bounds, const glm::vec3& origin,
                                     const glm::vec3& direction)
{
    std::optional<float> nearest;
    auto consider = [&](float distance) {
        if (!nearest || distance < *nearest)
            nearest = distance;
    };
    for (const ShapeBound& sphere : bounds.spheres) {
        const glm::vec3 offset = origin - sphere.center;
        const float c = glm::dot(offset, offset) - sphere.radius * sphere.radius;
        if (c <= 1e-4f * sphere.radius * sphere.radius)
            continue;  // the origin is in it (or on it)
        const float b = glm::dot(offset, direction);
        const float discriminant = b * b - c;
        if (b >= 0.0f || discriminant < 0.0f)
            continue;
        consider(-b - std::sqrt(discriminant));
    }
    for (const std::vector<glm::vec4>& planes : bounds.halfSpaceUnions) {
        // The union is entered where the ray first enters one of its half-spaces, unless
        // the origin is in one already.
        bool inside = false;
        std::optional<float> entry;
        for (const glm::vec4& plane : planes) {
            const float height = glm::dot(glm::vec3(plane), origin) + plane.w;
            const float tolerance = 1e-5f * std::max(1.0f, std::abs(plane.w));
            if (height <= tolerance) {
                inside = true;
                break;
            }
            const float approach = glm::dot(glm::vec3(plane), direction);
            if (approach < 0.0f) {
                const float distance = height / -approach;
                if (!entry || distance < *entry)
                    entry = distance;
            }
        }
        if (!inside && entry)
            consider(*entry);
    }
    return nearest;
}

}  // namespace scene
