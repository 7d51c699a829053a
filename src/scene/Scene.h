#pragma once
// The scene model: what a scene file means, in plain values. It knows nothing of OpenGL or
// of how the renderer lays the scene out for the GPU (see render/SceneUniforms).
#include "scene/CsgOperators.h"
#include "scene/Environments.h"
#include "scene/Materials.h"
#include "scene/Metals.h"
#include "scene/Pigments.h"
#include "scene/Primitives.h"
#include "scene/Transform.h"

#include <glm/glm.hpp>

#include <filesystem>
#include <optional>
#include <string>
#include <variant>
#include <vector>

namespace scene {

// A thin lens (the `lens` extension of the camera line): rays leave a disk of this radius
// around the eye, across the view, and meet again on the plane of focus, at this distance
// along the view direction. Without one the camera is a pinhole.
struct ThinLens {
    float apertureRadius = 0.0f;
    float focusDistance = 1.0f;
};

struct Camera {
    glm::vec3 eye{0.0f};
    glm::vec3 target{0.0f, 0.0f, -1.0f};
    glm::vec3 up{0.0f, 1.0f, 0.0f};
    float verticalFieldOfViewDegrees = 45.0f;
    std::optional<ThinLens> lens;
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

    // A finish written with a keyword (scene/Materials.h) instead of the seven numbers: its
    // material, whatever the numbers above say.
    std::optional<MaterialKind> keywordMaterial;
    // GGX roughness alpha of a microfacet finish (0 < alpha <= 1).
    float roughness = 0.0f;
    // A rough conductor's complex index of refraction; absent, Schlick's Fresnel with the
    // pigment as the reflectance at normal incidence (as the mirror has).
    std::optional<ComplexIor> conductorIor;

    // A keyword finish's material; otherwise the format's selection order: kt > 0, else
    // kr > 0, else alpha > 0, else Lambertian.
    MaterialKind material() const;
    bool isEmissive() const;
};

// --- geometry: the primitives (scene/Primitives.h), user SDFs and CSG (scene/CsgOperators.h)

// `float NAME(vec3 p, vec3 x)` from a GLSL file. The file may declare, in comment lines,
//   // @bound R        every point of the surface lies within R of the position x
//   // @lipschitz L    the function may overestimate the distance by up to a factor L
//   // @hull NX NY NZ D  every point of the surface lies where dot(N, p - x) <= D
// The first lets the renderer skip the function far from it; the second makes the sphere
// tracer take steps of distance / L, so a non-Lipschitz function does not tunnel; the third
// (one line per plane) lets rays that pass the bound's ball but not the hull's planes leave
// the function out of their marches.
struct UserSdf {
    std::string name;
    std::filesystem::path sourcePath;
    glm::vec3 position{0.0f};
    std::optional<float> boundingRadius;
    float lipschitz = 1.0f;
    // `// @hull` planes about the position: (N, W) with N of unit length, the surface where
    // dot(N, p - position) + W <= 0 (W = -D / |N| for the declared N and D).
    std::vector<glm::vec4> hullPlanes;
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
