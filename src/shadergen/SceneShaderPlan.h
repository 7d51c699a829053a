#pragma once
// The specialised shader's plan for a scene, computed before any of the scene's union is
// written (shadergen/SpecializedSceneCode.h writes it): for each object, its distance function,
// whether rays meet it exactly instead of marching it, the bounding sphere it is skipped
// by, and the piece of the ray's culling mask that stands for it, each with the parameter
// slots it reads. Tests assert on the plan rather than on the GLSL text.
#include "scene/Scene.h"
#include "shadergen/ShapeCompiler.h"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace shadergen {

// A part of the scene's union that a ray is tested against before it is marched
// (shaders/modules/ray_culling.glsl): a bounding ball in uShapeParameters, and the bit that
// stands for it in the ray's mask. (Shapes without a bound that have a closed form, planes
// and cones, are met exactly and never marched.)
// A user SDF that declares `// @hull` planes is culled by them too: a ray that passes
// the ball but not the planes leaves the piece out as well.
struct CullingPiece {
    int slot = -1;
    std::uint32_t bit = 0;
    int hullSlot = -1;   // the first of the hull's planes in world space, (N, W): inside where
                         // dot(N, p) + W <= 0
    int hullPlanes = 0;  // how many; 0: the ball alone
};

// The ray's mask has this many bits; objects beyond them are never culled.
constexpr int kCullingBits = 32;

struct ObjectPlan {
    std::size_t object = 0;  // in the scene the shader is built for
    int line = 0;            // where the object starts in its scene file
    std::string function;    // its generated distance function
    // Met by exact intersection (exactSurfacesIntersect): a top-level shape with a closed
    // form (shadergen/ExactSceneIntersection.h) that is not a culled light. In the
    // full distance forms, which every point query uses; left out of the culled forms, which
    // rays march.
    bool exact = false;
    std::string exactIntersection;  // the statements that meet it (exactIntersectionStatements)
    std::vector<int> exactSlots;    // the parameter slots they read, in the order allocated
    // An expensive object with a bounding sphere: evaluated only where that sphere is nearer
    // than what is already known, after every cheap object. -1: evaluated everywhere.
    int boundSlot = -1;
    std::optional<CullingPiece> culling;  // none: never left out of a march
};

struct ScenePlan {
    std::vector<ObjectPlan> objects;  // in object order
    // Every marched object has a culling piece, so a ray that misses them all escapes.
    bool everyObjectCulled = true;
    // Some ray marches some object (false where every object is met exactly).
    bool marchesAnything = true;
    // Objects in the marched union whose surfaces outside rays meet by marching: those not
    // met exactly, lights with a culling bit excepted unless a ray can enter them. With
    // fewer than two, no normal's stencil can reach another object's hidden face.
    int marchedSurfaceCount = 0;
    // Per object: its culling bit, or 0.
    std::vector<std::uint32_t> objectCullingBits;
};

// Objects whose distance is expensive (user SDFs, CSG solids) and that have a bounding
// sphere are evaluated only where that sphere is nearer than everything known so far: the
// exact distance is never below the sphere's, so the skipped evaluation could not have been
// the minimum. Nothing is approximated. (Both shaders.)
bool worthBounding(const scene::SceneObject& object);

// Plans the scene's objects, emitting their distance functions into `compiler` and laying
// out every value the plan names in its parameter array. `marchBoxesCylindersAndDisks`:
// see ShaderBuild.
ScenePlan planScene(const scene::Scene& scene, ShapeCompiler& compiler,
                    bool marchBoxesCylindersAndDisks = false);

}  // namespace shadergen
