#include "shadergen/SpecializedSceneCode.h"

#include <sstream>

namespace shadergen {

namespace {

std::string boundTest(int boundSlot)
{
    return "sdSphere(p - " + parameterSlot(boundSlot) + ".xyz, " + parameterSlot(boundSlot) +
           ".w) < d";
}

// An object's bit test in the culled functions; empty for an object never culled.
std::string objectBit(const ObjectPlan& object)
{
    if (!object.culling)
        return {};
    return "(mask & " + std::to_string(object.culling->bit) + "u) != 0u";
}

std::string call(const ObjectPlan& object)
{
    return object.function + "(p)";
}

// The condition under which a bounded object is evaluated, with the object's culling bit
// tested in the culled forms.
std::string boundedCondition(const ObjectPlan& object, bool culled)
{
    const std::string bit = culled ? objectBit(object) : "";
    return (bit.empty() ? "" : bit + " && ") + boundTest(object.boundSlot);
}

// The first crossing of each object met exactly, in object order.
std::string exactSurfaces(const ScenePlan& plan)
{
    std::ostringstream out;
    for (const ObjectPlan& object : plan.objects)
        if (object.exact)
            out << "    if (only < 0 || only == " << object.object << ") {\n"
                << object.exactIntersection << "    }\n";
    return out.str();
}

}  // namespace

std::string specializedSceneFunctions(const ScenePlan& plan, const std::string& shapeFunctions)
{
    // Cheap objects first, so that bounded expensive ones are skipped as often as possible.
    std::vector<const ObjectPlan*> cheap;
    std::vector<const ObjectPlan*> bounded;
    for (const ObjectPlan& object : plan.objects)
        (object.boundSlot >= 0 ? bounded : cheap).push_back(&object);

    std::ostringstream out;
    out << shapeFunctions;
    out << "// The scene: the union of its objects. Cheap objects first, so that bounded "
           "expensive\n// ones are skipped as often as possible. The culled forms, which rays "
           "march, leave out\n// the pieces a ray's mask clears (ray_culling.glsl) and the "
           "objects rays meet\n// exactly (exactSurfacesIntersect).\n\n";
    for (const bool culled : {false, true}) {
        const std::string suffix = culled ? "Culled" : "";
        const std::string maskParameter = culled ? ", uint mask" : "";
        out << "float sceneDistance" << suffix << "(vec3 p" << maskParameter
            << ")\n{\n    float d = FLOAT_MAX;\n";
        // A culled object is skipped by a branch, not a select: where every lane of a SIMD
        // group has its bit clear (a sphere light, which rays meet exactly), no lane pays for
        // its distance.
        for (const ObjectPlan* object : cheap) {
            if (culled && object->exact)
                continue;
            const std::string bit = culled ? objectBit(*object) : "";
            out << (bit.empty() ? "" : "    if (" + bit + ")\n    ") << "    d = min(d, "
                << call(*object) << ");\n";
        }
        for (const ObjectPlan* object : bounded)
            out << "    if (" << boundedCondition(*object, culled) << ")\n        d = min(d, "
                << call(*object) << ");\n";
        out << "    return d;\n}\n\n";

        out << "float sceneDistanceAndObject" << suffix << "(vec3 p" << maskParameter
            << ", out int nearest)\n{\n";
        out << "    float d = FLOAT_MAX;\n    nearest = -1;\n    float candidate;\n";
        for (const ObjectPlan* object : cheap) {
            if (culled && object->exact)
                continue;
            const std::string bit = culled ? objectBit(*object) : "";
            if (bit.empty())
                out << "    candidate = " << call(*object) << ";\n"
                    << "    if (candidate < d) { d = candidate; nearest = " << object->object
                    << "; }\n";
            else
                out << "    if (" << bit << ") {\n        candidate = " << call(*object)
                    << ";\n        if (candidate < d) { d = candidate; nearest = " << object->object
                    << "; }\n    }\n";
        }
        for (const ObjectPlan* object : bounded)
            out << "    if (" << boundedCondition(*object, culled) << ") {\n"
                << "        candidate = " << call(*object) << ";\n"
                << "        if (candidate < d) { d = candidate; nearest = " << object->object
                << "; }\n    }\n";
        out << "    return d;\n}\n\n";
    }

    out << "// The first crossing in (tMin, hit.t) of every object met exactly (exact_shapes.glsl);\n"
           "// of object `only` alone where it is not -1.\n"
           "void exactSurfacesIntersect(vec3 origin, vec3 direction, float tMin, int only,\n"
           "                            inout ExactHit hit)\n{\n"
        << exactSurfaces(plan) << "}\n\n";

    out << "RayCulling sceneRayCulling(vec3 origin, vec3 direction, float tolerance0,\n"
           "                           float toleranceGrowth)\n{\n"
           "    if (!gRayCulling || !(toleranceGrowth < kMaxCullableToleranceGrowth))\n"
           "        return noRayCulling();\n"
           "    RayCulling culling = RayCulling(0u, 0.0, FLOAT_MAX);\n";
    for (const std::vector<const ObjectPlan*>* objects : {&cheap, &bounded})
        for (const ObjectPlan* object : *objects)
            if (object->culling && object->culling->hullPlanes > 0) {
                const CullingPiece& piece = *object->culling;
                out << "    {\n        BallChord chord = ballChord(" << parameterSlot(piece.slot)
                    << ", origin, direction, tolerance0, toleranceGrowth);\n";
                for (int k = 0; k < piece.hullPlanes; ++k)
                    out << "        clipChord(chord, " << parameterSlot(piece.hullSlot + k)
                        << ", origin, direction);\n";
                out << "        approachChord(culling, " << piece.bit << "u, chord);\n    }\n";
            } else if (object->culling)
                out << "    cullByBall(culling, " << object->culling->bit << "u, "
                    << parameterSlot(object->culling->slot)
                    << ", origin, direction, tolerance0, toleranceGrowth);\n";
    if (!plan.everyObjectCulled)
        out << "    // Some objects have no bound to cull by: the ray may meet them anywhere.\n"
               "    culling.escapeDistance = FLOAT_MAX;\n"
               "    culling.entryDistance = 0.0;\n";
    out << "    return culling;\n}\n";
    return out.str();
}

}  // namespace shadergen
