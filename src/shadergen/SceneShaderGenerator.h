#pragma once
#include "scene/Scene.h"
#include "scene/SceneFeatures.h"
#include "settings/RenderSettings.h"
#include "shadergen/SceneShaderPlan.h"

#include <glm/glm.hpp>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace shadergen {

using settings::ShaderVariant;

bool specializesFeatures(ShaderVariant variant);
bool specializesShapes(ShaderVariant variant);

// The most shape parameters (vec4s) the specialised shader reads into its own variables once
// per pixel (scene_data.glsl says why); a larger scene reads them where they are used.
constexpr std::size_t kMostShapeParametersReadOnce = 256;

// What a scene's shapes weigh in the specialised shader's code: a unit per primitive,
// transform and CSG operator. The specialised shader's code, and the time its compile takes,
// grow with it; the general shader's do not.
std::size_t shapeCodeWeight(const scene::Scene& scene);

// Scenes whose shapes weigh more than this are given the general shader's shapes (with their
// features still specialised: ShaderVariant::FeaturesOnly), which finds surfaces through a
// hierarchy over the objects (shadergen/ObjectHierarchy.h) and compiles in the same time
// whatever the scene. Chosen by measurement (docs/PERFORMANCE.md, "Scenes of many objects"):
// spheres on a plane at 160x120 on llvmpipe, the specialised shader renders faster up to
// about 30 spheres, and the two cross between 30 and 35 (at 30: 0.35 against 0.32 Mpaths/s,
// the same wall time; at 35: 0.28 against 0.30, 1.5 s against 1.3 s); beyond, its code and
// its compile keep growing. Every scene the project ships weighs 23 or less.
constexpr std::size_t kMostShapeCodeWeight = 32;

// The variant a scene is given for the one asked: `asked`, but with the general shader's
// shapes where the scene weighs more than kMostShapeCodeWeight.
ShaderVariant variantForScene(const scene::Scene& scene, ShaderVariant asked);

// Where the shader takes the environment's kind from. A specialised shader builds it in;
// the window reads it from a uniform so that its panel can switch the environment off
// without a recompile (the general shader always does).
enum class EnvironmentBinding { BuiltIn, FromUniform };

// The scene-dependent part of the path-tracing shader: the #defines that switch modules on
// and size the uniform arrays, the distance functions of the scene, and the shape
// parameters they read. Only structure (which shapes, which CSG tree, which features)
// reaches the code; every number lands in `shapeParameters`, so editing a value gives the
// same code and only new uniforms.
struct SceneShaderCode {
    ShaderVariant variant = ShaderVariant::Specialized;
    scene::SceneFeatures features;  // what the shader is built for
    std::string defines;            // lines for the preamble, after #version
    std::vector<std::filesystem::path> userSdfFiles;
    // The specialised shader's decisions for each object, from which its scene functions
    // are written (empty for the interpreted shapes).
    ScenePlan plan;
    // The scene's distance functions (each with a comment naming its object and scene-file
    // line), sceneDistance, sceneDistanceAndObject and their culled forms.
    std::string sceneFunctions;
    // --exact-geometry: rays find surfaces by exact intersection (exactSceneIntersect,
    // below) instead of sphere tracing.
    bool exactGeometry = false;
    std::string exactFunctions;
    bool profileCounters = false;
    // Some ray marches some object (false where every object is met exactly).
    bool marchesAnything = true;
    // Two or more objects are marched, so a normal's stencil may reach where one object's
    // distance measures another's hidden face (sceneNormal backs off there).
    bool marchedUnion = true;

    std::vector<glm::vec4> shapeParameters;
    std::vector<glm::ivec4> shapeProgram;  // General only
    std::vector<int> objectProgramStart;   // General only: per object
    // General only: per object, radius < 0 for none (every marched object with a finite
    // bound has one: rays march it only where they come near it, shape_interpreter.glsl).
    std::vector<glm::vec4> objectBounds;
    // General only: per object, whether rays march it (the interpreter meets the others
    // exactly: isExactObject, shape_interpreter.glsl); the walk that finds a ray's marched
    // objects (nextMarchedObject) skips nodes that hold none.
    std::vector<bool> objectMarched;
    // Per object: the culling-mask bit that leaves the whole object out of a culled distance
    // (ray_culling.glsl), or 0 where none does.
    std::vector<std::uint32_t> objectCullingBits;
};

// Everything but the scene that shapes the shader's code.
struct ShaderBuild {
    ShaderVariant variant = ShaderVariant::Specialized;
    EnvironmentBinding environment = EnvironmentBinding::BuiltIn;
    // Rays find surfaces by exact intersection instead of sphere tracing (--exact-geometry).
    bool exactGeometry = false;
    // The shader counts its work per path (march steps by kind of ray, shadow rays, path
    // segments) and accumulates those counts instead of radiance: bench_throughput reads
    // them.
    bool profileCounters = false;
    // Boxes, capped cylinders and disks are marched instead of met exactly, as before the
    // renderer met them exactly: only so that the sphere tracer's handling of silhouettes,
    // edges and contacts can still be judged against exact intersection on shapes that
    // have one (tests/render/EdgeBiasTest.cpp), and what meeting them exactly saves measured.
    bool marchBoxesCylindersAndDisks = false;
    // Each pixel also accumulates its first-hit albedo, normal and depth (FEATURE_BUFFERS,
    // path_tracer_main.glsl; --feature-buffers).
    bool featureBuffers = false;
    // Scenes that weigh more than kMostShapeCodeWeight get the general shader's shapes
    // (variantForScene); false: the variant asked whatever the scene (tests of the
    // specialised plan on scenes of many objects).
    bool shapesByWeight = true;
};

// What of the settings shapes the shader's code (the rest are uniforms).
ShaderBuild shaderBuild(const settings::RenderSettings& settings);

SceneShaderCode generateSceneShaderCode(const scene::Scene& scene, const ShaderBuild& build = {});

}  // namespace shadergen
