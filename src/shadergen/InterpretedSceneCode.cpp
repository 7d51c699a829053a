#include "shadergen/InterpretedSceneCode.h"

#include "scene/PrimitiveKinds.h"
#include "scene/SceneBounds.h"
#include "shadergen/SceneShaderPlan.h"
#include "shadergen/ShaderCodes.h"

#include <algorithm>
#include <map>
#include <set>
#include <sstream>

namespace shadergen {

using namespace scene;

namespace {

// The general shader's distance to one primitive: a branch per kind, the kinds that read
// fewer parameter vec4s first so that each vec4 is fetched once and only where needed.
std::string primitiveInterpreter(const std::set<int>* usedKinds)
{
    const char* const names = "abcdefgh";
    std::vector<const PrimitiveKind*> kinds;
    for (const PrimitiveKind& kind : primitiveKinds())
        if (usedKinds == nullptr || usedKinds->count(kind.code) != 0)
            kinds.push_back(&kind);
    std::stable_sort(kinds.begin(), kinds.end(),
                     [](const PrimitiveKind* a, const PrimitiveKind* b) {
                         return a->parameterCount < b->parameterCount;
                     });
    std::ostringstream out;
    out << "// Primitive `kind` with its parameters from uShapeParameters[first]; `extra` counts a\n"
           "// union's terms (a polyhedron's planes) or names the user SDF (scene/Primitives.h).\n"
           "float primitiveDistance(int kind, int first, int extra, vec3 p)\n{\n";
    int fetched = 0;
    auto fetch = [&](int count) {
        for (; fetched < count; ++fetched)
            out << "    vec4 " << names[fetched] << " = SHAPE_PARAMETER(first"
                << (fetched == 0 ? "" : " + " + std::to_string(fetched)) << ");\n";
    };
    fetch(1);  // the user SDF's
    for (const PrimitiveKind* kind : kinds) {
        const std::string code = primitiveCodeName(*kind);
        if (kind->unionOfTerms) {
            out << "    if (kind == " << code << ") {\n        float d = FLOAT_MAX;\n"
                << "        for (int term = 0; term < extra && loopIterationAllowed(); ++term)\n"
                << "            d = min(d, "
                << distanceOverSlots(*kind, [](int) { return "SHAPE_PARAMETER(first + term)"; })
                << ");\n        return d;\n    }\n";
            continue;
        }
        fetch(kind->parameterCount);
        out << "    if (kind == " << code << ")\n        return "
            << distanceOverSlots(*kind, [&](int k) { return std::string(1, names[k]); }) << ";\n";
    }
    out << "    return callUserSdf(extra, p, a.xyz) * a.w;\n}\n";
    return out.str();
}

// The general shader's exact intersections (shape_interpreter.glsl meets a single
// untransformed primitive exactly where its kind has a closed form): a branch per kind, in
// world space, from the same descriptions the specialised shader's calls are written from.
std::string exactPrimitiveInterpreter(const std::set<int>* usedKinds)
{
    const char* const names = "abcdefgh";
    std::vector<const PrimitiveKind*> kinds;
    for (const PrimitiveKind& kind : primitiveKinds())
        if (kind.exact != nullptr && (usedKinds == nullptr || usedKinds->count(kind.code) != 0))
            kinds.push_back(&kind);
    std::stable_sort(kinds.begin(), kinds.end(),
                     [](const PrimitiveKind* a, const PrimitiveKind* b) {
                         return a->parameterCount < b->parameterCount;
                     });
    auto slot = [](int k) {
        return k == 0 ? "SHAPE_PARAMETER(first)"
                      : "SHAPE_PARAMETER(first + " + std::to_string(k) + ")";
    };
    std::ostringstream out;
    out << "// Whether rays meet primitive `kind`, its parameters from SHAPE_PARAMETER(first), by "
           "exact\n// intersection (scene/Primitives.h).\n"
           "bool primitiveMetExactly(int kind, int first)\n{\n    return ";
    if (kinds.empty())
        out << "false";
    for (std::size_t i = 0; i < kinds.size(); ++i) {
        const PrimitiveKind& kind = *kinds[i];
        std::string test = "kind == " + primitiveCodeName(kind);
        if (kind.metExactlyGlsl != nullptr)
            test += " && " + overSlots(kind.metExactlyGlsl, slot);
        if (kind.marchedOnRequest)
            test += " && EXACT_BOXES_CYLINDERS_AND_DISKS != 0";
        const bool compound = test.find("&&") != std::string::npos;
        out << (i == 0 ? "" : " ||\n           ") << (compound ? "(" + test + ")" : test);
    }
    out << ";\n}\n\n";

    out << "// The first crossing in (tMin, hit.t) of primitive `kind` by the ray (o, d), its\n"
           "// parameters from SHAPE_PARAMETER(first) (`terms` of them for a union of terms).\n"
           "void exactPrimitiveIntersect(int kind, int first, int terms, vec3 o, vec3 d, "
           "float tMin,\n                             int object, inout ExactHit hit)\n{\n";
    int fetched = 0;
    for (const PrimitiveKind* kind : kinds) {
        const std::string code = primitiveCodeName(*kind);
        const std::string tail = "tMin, object, hit);\n";
        if (kind->unionOfTerms) {
            out << "    if (kind == " << code << ") {\n        " << kind->exactSetup << "\n"
                << "        for (int term = 0; term < terms && loopIterationAllowed(); ++term)\n"
                << "            "
                << overSlots(kind->exactTerm, [](int) { return "SHAPE_PARAMETER(first + term)"; })
                << "\n        " << kind->exact << tail << "        return;\n    }\n";
            continue;
        }
        for (; fetched < kind->parameterCount; ++fetched)
            out << "    vec4 " << names[fetched] << " = " << slot(fetched) << ";\n";
        out << "    if (kind == " << code << ") {\n        "
            << overSlots(kind->exact, [&](int k) { return std::string(1, names[k]); }) << tail
            << "        return;\n    }\n";
    }
    out << "}\n";
    return out.str();
}

// The general shader's CSG operators: a branch per operator, in code order, the last one
// taken for any code the others are not.
std::string csgInterpreter()
{
    const std::vector<CsgOperatorDescription>& operators = csgOperatorDescriptions();
    std::ostringstream out;
    out << "// CSG operator `op` on two distances; `parameter` for the smooth ones "
           "(scene/CsgOperators.h).\n"
           "float combine(int op, float a, float b, float parameter)\n{\n";
    for (std::size_t i = 0; i < operators.size(); ++i) {
        const CsgOperatorDescription& op = operators[i];
        const std::string call =
            std::string(op.function) + "(a, b" + (op.hasParameter() ? ", parameter" : "") + ")";
        if (i + 1 < operators.size())
            out << "    if (op == " << codeName(op) << ")\n        return " << call << ";\n";
        else
            out << "    return " << call << ";\n";
    }
    out << "}\n";
    return out.str();
}

std::string userSdfDispatcher(const std::map<std::string, int>& ids)
{
    std::ostringstream out;
    out << "// The general shader reaches user SDFs by number.\n";
    out << "float callUserSdf(int id, vec3 p, vec3 x)\n{\n";
    for (const auto& [name, id] : ids)
        out << "    if (id == " << id << ") return " << name << "(p, x);\n";
    out << "    return FLOAT_MAX;\n}\n";
    return out.str();
}

}  // namespace

namespace {

void collectKinds(const Shape& shape, std::set<int>& kinds)
{
    if (const auto* node = std::get_if<CsgNode>(&shape.geometry)) {
        for (const Shape& child : node->children)
            collectKinds(child, kinds);
    } else if (const PrimitiveKind* kind = primitiveKindOf(shape.geometry)) {
        kinds.insert(kind->code);
    }
}

}  // namespace

InterpretedScene interpretedScene(const Scene& scene, ShapeCompiler& compiler, bool onlyKindsUsed)
{
    std::set<int> usedKinds;
    for (const SceneObject& object : scene.objects)
        collectKinds(object.shape, usedKinds);
    const std::set<int>* kinds = onlyKindsUsed ? &usedKinds : nullptr;
    InterpretedScene interpreted;
    for (const SceneObject& object : scene.objects) {
        interpreted.objectProgramStart.push_back(compiler.programSize());
        compiler.emitProgram(object.shape, 0);
        compiler.endProgram();
        const ShapeBound bound = boundShape(object.shape);
        interpreted.objectBounds.push_back(worthBounding(object) && bound.finite
                                               ? glm::vec4(bound.center, bound.radius)
                                               : glm::vec4(0.0f, 0.0f, 0.0f, -1.0f));
    }
    // Declared before the interpreter module, which calls them.
    interpreted.functions = userSdfDispatcher(compiler.userSdfIds()) + "\n" +
                            primitiveInterpreter(kinds) + "\n" + csgInterpreter() + "\n" +
                            exactPrimitiveInterpreter(kinds);
    return interpreted;
}

}  // namespace shadergen
