#pragma once
// The scene model: what a scene file means, in plain values. It knows nothing of OpenGL or
// of how the renderer lays the scene out for the GPU (see render/SceneUniforms).
#include "scene/CsgOperators.h"
#include "scene/Environments.h"
#include "scene/Materials.h"
#include "scene/Pigments.h"
#include "scene/Primitives.h"

#include <glm/glm.hpp>

#include <filesystem>
#include <optional>
#include <string>
#include <variant>
#include <vector>

namespace scene {

struct Camera {
    glm::vec3 eye{0.0f};
    glm::vec3 target{0.0f, 0.0f, -1.0f};
    glm::vec3 up{0.0f, 1.0f, 0.0f};
    float verticalFieldOfViewDegrees = 45.0f;
};

// Orthonormal camera frame as the format defines it: forward = normalize(target - eye),
// right = normalize(cross(forward, up)), trueUp = cross(right, forward).
struct CameraFrame {
    glm::vec3 right;
    glm::vec3 trueUp;
    glm::vec3 forward;
};
CameraFrame cameraFrame(const Camera& camera);

// Two cameras that give the same view.
bool sameCamera(const Camera& a, const Camera& b);

struct PointLight {
    glm::vec3 position{0.0f};
    glm::vec3 intensity{0.0f};  // radiant intensity I, W/sr per channel
};

struct Finish {
    glm::vec3 emission{0.0f};  // emitted radiance; only spheres may emit
    float phongExponent = 0.0f;
    float reflection = 0.0f;    // kr: a switch, only > 0 matters
    float transmission = 0.0f;  // kt: a switch, only > 0 matters
    float ior = 1.0f;

    // The format's selection order: kt > 0, else kr > 0, else alpha > 0, else Lambertian.
    MaterialKind material() const;
    bool isEmissive() const;
};

// --- geometry: the primitives (scene/Primitives.h), user SDFs and CSG (scene/CsgOperators.h)

// `float NAME(vec3 p, vec3 x)` from a GLSL file. The file may declare, in comment lines,
//   // @bound R        every point of the surface lies within R of the position x
//   // @lipschitz L    the function may overestimate the distance by up to a factor L
// The first lets the renderer skip the function far from it; the second makes the sphere
// tracer take steps of distance / L, so a non-Lipschitz function does not tunnel.
struct UserSdf {
    std::string name;
    std::filesystem::path sourcePath;
    glm::vec3 position{0.0f};
    std::optional<float> boundingRadius;
    float lipschitz = 1.0f;
    // `// @intersect FUNCTION`: the file's closed-form intersection of the shape, which rays
    // use instead of marching it (docs/SCENE_FORMAT.md).
    std::optional<std::string> intersectFunction;
};

struct Shape;

struct CsgNode {
    CsgOperator op = CsgOperator::Union;
    float parameter = 0.0f;
    std::vector<Shape> children;  // two or more; difference subtracts all others from the first
};

// A similarity transform: world = rotation * (scale * local) + translation.
struct Transform {
    glm::mat3 rotation{1.0f};
    glm::vec3 translation{0.0f};
    float scale = 1.0f;
};

// The transform that applies `inner` first, then `outer`.
Transform compose(const Transform& outer, const Transform& inner);
glm::vec3 applyTransform(const Transform& transform, const glm::vec3& local);
// A plane dot(n, x) + w = 0 (unit n) of a shape's local space, in world space: n' = R n,
// w' = s w - dot(n', T).
glm::vec4 applyTransformToPlane(const Transform& transform, const glm::vec4& localPlane);

template <typename List, typename... More>
struct VariantOf;
template <typename... Listed, typename... More>
struct VariantOf<TypeList<Listed...>, More...> {
    using type = std::variant<Listed..., More...>;
};

// The primitives first: a primitive's code is its index here (scene/PrimitiveKinds.h).
using Geometry = VariantOf<PrimitiveTypes, UserSdf, CsgNode>::type;

struct Shape {
    Geometry geometry;
    std::optional<Transform> transform;
};

struct SceneObject {
    int pigment = 0;
    int finish = 0;
    Shape shape;
    int line = 0;  // where the object starts in its file, for messages
};

struct Scene {
    std::filesystem::path sourcePath;
    Camera camera;
    std::vector<PointLight> pointLights;
    std::vector<Pigment> pigments;
    std::vector<Finish> finishes;
    std::vector<SceneObject> objects;
    Environment environment;
};

// A sphere whose finish emits: a spherical area light.
struct SphereLight {
    int object = 0;
    glm::vec3 center{0.0f};
    float radius = 0.0f;
    glm::vec3 radiance{0.0f};
};

// Every emissive top-level sphere, in object order (with any transform applied).
std::vector<SphereLight> sphereLights(const Scene& scene);

}  // namespace scene
