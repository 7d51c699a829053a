#include "render/SceneShaderGenerator.h"

#include "render/ExactSceneIntersection.h"
#include "render/ShaderCodes.h"
#include "scene/PrimitiveKinds.h"
#include "scene/SceneBounds.h"

#include <algorithm>
#include <cstdint>
#include <map>
#include <optional>
#include <sstream>

namespace render {

using namespace scene;

namespace {

int instruction(Opcode opcode)
{
    return static_cast<int>(opcode);
}

std::string slot(int index)
{
    return "uShapeParameters[" + std::to_string(index) + "]";
}

// Walks shapes once, laying their numbers out in the parameter array and producing either
// generated GLSL (specialised) or a program for the interpreter (general).
class ShapeCompiler {
public:
    explicit ShapeCompiler(SceneShaderCode& code) : code_(code) {}

    // --- specialised: one GLSL function per shape node, returns its name -------------------

    std::string emitFunction(const Shape& shape)
    {
        const std::string name = "shape" + std::to_string(nextFunction_++);
        std::string body;
        if (shape.transform) {
            const int frame = allocateTransform(*shape.transform);
            const std::string inner = emitGeometry(shape.geometry);
            body = "    return toWorldDistance(" + inner + "(toLocalPoint(p, " +
                   std::to_string(frame) + ")), " + std::to_string(frame) + ");\n";
        } else {
            body = emitGeometryBody(shape.geometry);
        }
        functions_ << "float " << name << "(vec3 p)\n{\n" << body << "}\n\n";
        return name;
    }

    int allocateValue(const glm::vec4& value) { return allocate({value}); }

    // --- general: instructions for shape_interpreter.glsl ---------------------------------

    void emitProgram(const Shape& shape, int depth)
    {
        maxDepth_ = std::max(maxDepth_, depth + 1);
        if (shape.transform) {
            const int frame = allocateTransform(*shape.transform);
            code_.shapeProgram.emplace_back(instruction(Opcode::PushFrame), frame, 0, 0);
            emitGeometryProgram(shape.geometry, depth + 1);
            code_.shapeProgram.emplace_back(instruction(Opcode::PopFrame), frame, 0, 0);
        } else {
            emitGeometryProgram(shape.geometry, depth);
        }
    }

    std::string functions() const { return functions_.str(); }

    int allocateBound(const ShapeBound& bound)
    {
        return allocate({glm::vec4(bound.center, bound.radius)});
    }
    int maxStackDepth() const { return maxDepth_; }
    const std::map<std::string, int>& userSdfIds() const { return userIds_; }

private:
    int allocate(std::initializer_list<glm::vec4> values)
    {
        return allocate(std::vector<glm::vec4>(values));
    }
    int allocate(const std::vector<glm::vec4>& values)
    {
        const int first = static_cast<int>(code_.shapeParameters.size());
        code_.shapeParameters.insert(code_.shapeParameters.end(), values.begin(), values.end());
        return first;
    }

    int allocateTransform(const Transform& transform)
    {
        return allocate({glm::vec4(transform.rotation[0], 0.0f),
                         glm::vec4(transform.rotation[1], 0.0f),
                         glm::vec4(transform.rotation[2], 0.0f),
                         glm::vec4(transform.translation, transform.scale)});
    }

    int userSdfId(const std::string& name)
    {
        const auto found = userIds_.find(name);
        if (found != userIds_.end())
            return found->second;
        const int id = static_cast<int>(userIds_.size());
        userIds_[name] = id;
        return id;
    }

    struct Primitive {
        int kind;
        int first;
        int extra;
        std::string expression;  // specialised code, in terms of p
    };

    // Lays out a primitive's parameters (the same layout for both variants).
    Primitive layoutPrimitive(const Geometry& geometry)
    {
        if (const PrimitiveKind* kind = primitiveKindOf(geometry)) {
            const std::vector<glm::vec4> values = primitiveParameters(geometry);
            const int first = allocate(values);
            if (!kind->unionOfTerms)
                return {kind->code, first, 0,
                        distanceOverSlots(*kind, [&](int k) { return slot(first + k); })};
            std::string expression;
            for (int i = 0; i < static_cast<int>(values.size()); ++i) {
                const std::string term =
                    distanceOverSlots(*kind, [&](int) { return slot(first + i); });
                expression = i == 0 ? term : "min(" + expression + ", " + term + ")";
            }
            return {kind->code, first, static_cast<int>(values.size()), expression};
        }
        const auto& user = std::get<UserSdf>(geometry);
        // A function that may overestimate by a factor L is stepped by distance / L.
        const int s = allocate({glm::vec4(user.position, 1.0f / user.lipschitz)});
        return {userSdfCode(), s, userSdfId(user.name),
                user.name + "(p, " + slot(s) + ".xyz) * " + slot(s) + ".w"};
    }

    std::string emitGeometry(const Geometry& geometry)
    {
        const std::string name = "shape" + std::to_string(nextFunction_++);
        const std::string body = emitGeometryBody(geometry);
        functions_ << "float " << name << "(vec3 p)\n{\n" << body << "}\n\n";
        return name;
    }

    std::string emitGeometryBody(const Geometry& geometry)
    {
        if (const auto* node = std::get_if<CsgNode>(&geometry)) {
            std::vector<std::string> children;
            for (const Shape& child : node->children)
                children.push_back(emitFunction(child));
            const CsgOperatorDescription& op = describe(node->op);
            std::string parameter;
            if (op.hasParameter())
                parameter =
                    ", " + slot(allocate({glm::vec4(node->parameter, 0.0f, 0.0f, 0.0f)})) + ".x";
            std::string body = "    float d = " + children[0] + "(p);\n";
            for (std::size_t i = 1; i < children.size(); ++i)
                body += "    d = " + std::string(op.function) + "(d, " + children[i] +
                        "(p)" + parameter + ");\n";
            return body + "    return d;\n";
        }
        return "    return " + layoutPrimitive(geometry).expression + ";\n";
    }

    void emitGeometryProgram(const Geometry& geometry, int depth)
    {
        if (const auto* node = std::get_if<CsgNode>(&geometry)) {
            for (std::size_t i = 0; i < node->children.size(); ++i)
                emitProgram(node->children[i], depth + static_cast<int>(i));
            const CsgOperatorDescription& op = describe(node->op);
            const int parameter =
                op.hasParameter() ? allocate({glm::vec4(node->parameter, 0.0f, 0.0f, 0.0f)}) : 0;
            code_.shapeProgram.emplace_back(instruction(Opcode::Combine), op.code,
                                            static_cast<int>(node->children.size()), parameter);
            return;
        }
        const Primitive primitive = layoutPrimitive(geometry);
        code_.shapeProgram.emplace_back(instruction(Opcode::Primitive), primitive.kind, primitive.first,
                                        primitive.extra);
    }

    SceneShaderCode& code_;
    std::ostringstream functions_;
    int nextFunction_ = 0;
    int maxDepth_ = 1;
    std::map<std::string, int> userIds_;
};

void define(std::ostringstream& out, const std::string& name, int value)
{
    out << "#define " << name << " " << value << "\n";
}

// Objects whose distance is expensive (user SDFs, CSG solids) and that have a bounding
// sphere are evaluated only where that sphere is nearer than everything known so far: the
// exact distance is never below the sphere's, so the skipped evaluation could not have been
// the minimum. Nothing is approximated.
bool worthBounding(const SceneObject& object)
{
    return std::holds_alternative<UserSdf>(object.shape.geometry) ||
           std::holds_alternative<CsgNode>(object.shape.geometry);
}

// A part of the scene's union that a ray is tested against before it is marched
// (shaders/modules/ray_culling.glsl): a bounding half-space or ball in uShapeParameters, and
// the bit that stands for it in the ray's mask.
struct CullingPiece {
    bool halfSpace;
    int slot;
    std::uint32_t bit;
};

constexpr int kCullingBits = 32;

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

// The scene's distance functions. Top-level polyhedra (unions of half-spaces: floors,
// walls, rooms) and spheres are in the full forms, which every point query uses, but not in
// the culled forms that rays march: rays meet them by exact intersection instead (the
// generated exactSurfacesIntersect), so a march ends at their exact crossing and never
// creeps along a wall or a floor seen at grazing angles, never stops short of one at a
// concave edge, and spends no steps on them.
std::string specializedSceneFunctions(const Scene& scene, ShapeCompiler& compiler,
                                      std::vector<std::uint32_t>& objectCullingBits,
                                      bool& marchesAnything)
{
    struct Entry {
        std::size_t index;
        std::string function;
        bool exact;      // met by exact intersection: absent from culled forms
        int boundSlot;   // -1: evaluated everywhere
        std::vector<CullingPiece> pieces;  // empty: never culled
    };
    std::vector<Entry> cheap;
    std::vector<Entry> bounded;
    std::ostringstream exactSurfaces;
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
    objectCullingBits.assign(scene.objects.size(), 0u);
    bool everyObjectCulled = true;
    // Whether any ray ever marches: a light with a bit is marched only by rays inside it,
    // which need a way in (a dielectric finish) or a camera inside it.
    marchesAnything = false;
    for (const SphereLight& light : sphereLights(scene)) {
        const bool enterable =
            scene.finishes[scene.objects[light.object].finish].material() == MaterialKind::Dielectric ||
            glm::length(scene.camera.eye - light.center) < light.radius;
        if (enterable || lightBits.count(static_cast<std::size_t>(light.object)) == 0)
            marchesAnything = true;
    }
    for (std::size_t i = 0; i < scene.objects.size(); ++i) {
        const SceneObject& object = scene.objects[i];
        const Shape& shape = object.shape;
        const ShapeBound bound = boundShape(shape);
        const int boundSlot = bound.finite ? compiler.allocateBound(bound) : -1;
        Entry entry{i, compiler.emitFunction(shape), false, -1, {}};
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
            exactSurfaces << "    if (only < 0 || only == " << i << ")\n        exactSphere(origin, direction, "
                      << slot(compiler.allocateValue(glm::vec4(center, radius))) << ", tMin, " << i
                      << ", hit);\n";
            cheap.push_back(entry);
            continue;
        }
        if (const auto* polyhedron = std::get_if<Polyhedron>(&shape.geometry)) {
            entry.exact = true;
            exactSurfaces << "    if (only < 0 || only == " << i << ") {\n        ConvexInterval outside = wholeRay();\n";
            for (const glm::vec4& plane : polyhedron->planes) {
                const glm::vec4 unit = plane / glm::length(glm::vec3(plane));
                exactSurfaces << "        clipOutsideHalfSpace(outside, origin, direction, "
                          << slot(compiler.allocateValue(worldPlane(unit, shape.transform)))
                          << ");\n";
            }
            exactSurfaces << "        exactHalfSpaceUnion(outside, tMin, " << i << ", hit);\n    }\n";
            cheap.push_back(entry);
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
        if (lightBits.count(i) == 0)
            marchesAnything = true;
        if (piece) {
            const auto reserved = lightBits.find(i);
            const std::optional<std::uint32_t> bit =
                reserved != lightBits.end() ? std::optional<std::uint32_t>(reserved->second)
                                            : takeBit();
            if (bit) {
                piece->bit = *bit;
                entry.pieces.push_back(*piece);
                objectCullingBits[i] = *bit;
            }
        }
        if (entry.pieces.empty())
            everyObjectCulled = false;
        if (worthBounding(object) && bound.finite) {
            entry.boundSlot = boundSlot;
            bounded.push_back(entry);
        } else {
            cheap.push_back(entry);
        }
    }
    auto boundTest = [](int boundSlot) {
        return "sdSphere(p - " + slot(boundSlot) + ".xyz, " + slot(boundSlot) + ".w) < d";
    };
    // An object's bit test in the culled functions.
    auto objectBit = [](const Entry& entry) -> std::string {
        if (entry.pieces.empty())
            return {};
        return "(mask & " + std::to_string(entry.pieces[0].bit) + "u) != 0u";
    };
    auto call = [](const Entry& entry) { return entry.function + "(p)"; };

    std::ostringstream out;
    out << compiler.functions();
    out << "// The scene: the union of its objects. Cheap objects first, so that bounded "
           "expensive\n// ones are skipped as often as possible. The culled forms, which rays "
           "march, leave out\n// the pieces a ray's mask clears (ray_culling.glsl) and the "
           "polyhedra and spheres,\n// which rays meet exactly (exactSurfacesIntersect).\n\n";
    // The condition under which a bounded object is evaluated, with the object's culling bit
    // tested in the culled forms.
    auto boundedCondition = [&](const Entry& entry, bool culled) {
        const std::string bit = culled ? objectBit(entry) : "";
        return (bit.empty() ? "" : bit + " && ") + boundTest(entry.boundSlot);
    };
    for (const bool culled : {false, true}) {
        const std::string suffix = culled ? "Culled" : "";
        const std::string maskParameter = culled ? ", uint mask" : "";
        out << "float sceneDistance" << suffix << "(vec3 p" << maskParameter
            << ")\n{\n    float d = FLOAT_MAX;\n";
        // A culled object is skipped by a branch, not a select: where every lane of a SIMD
        // group has its bit clear (a sphere light, which rays meet exactly), no lane pays for
        // its distance.
        for (const Entry& entry : cheap) {
            if (culled && entry.exact)
                continue;
            const std::string bit = culled ? objectBit(entry) : "";
            out << (bit.empty() ? "" : "    if (" + bit + ")\n    ") << "    d = min(d, "
                << call(entry) << ");\n";
        }
        for (const Entry& entry : bounded)
            out << "    if (" << boundedCondition(entry, culled) << ")\n        d = min(d, "
                << call(entry) << ");\n";
        out << "    return d;\n}\n\n";

        out << "float sceneDistanceAndObject" << suffix << "(vec3 p" << maskParameter
            << ", out int nearest)\n{\n";
        out << "    float d = FLOAT_MAX;\n    nearest = -1;\n    float candidate;\n";
        for (const Entry& entry : cheap) {
            if (culled && entry.exact)
                continue;
            const std::string bit = culled ? objectBit(entry) : "";
            if (bit.empty())
                out << "    candidate = " << call(entry) << ";\n"
                    << "    if (candidate < d) { d = candidate; nearest = " << entry.index
                    << "; }\n";
            else
                out << "    if (" << bit << ") {\n        candidate = " << call(entry)
                    << ";\n        if (candidate < d) { d = candidate; nearest = "
                    << entry.index << "; }\n    }\n";
        }
        for (const Entry& entry : bounded)
            out << "    if (" << boundedCondition(entry, culled) << ") {\n"
                << "        candidate = " << call(entry) << ";\n"
                << "        if (candidate < d) { d = candidate; nearest = " << entry.index
                << "; }\n    }\n";
        out << "    return d;\n}\n\n";
    }

    out << "// The first crossing in (tMin, hit.t) of every top-level polyhedron and sphere, exactly\n"
           "// (exact_shapes.glsl); of object `only` alone where it is not -1.\n"
           "void exactSurfacesIntersect(vec3 origin, vec3 direction, float tMin, int only,\n"
           "                            inout ExactHit hit)\n{\n"
        << exactSurfaces.str() << "}\n\n";

    out << "RayCulling sceneRayCulling(vec3 origin, vec3 direction, float tolerance0,\n"
           "                           float toleranceGrowth)\n{\n"
           "    if (uRayCulling == 0 || !(toleranceGrowth < kMaxCullableToleranceGrowth))\n"
           "        return noRayCulling();\n"
           "    RayCulling culling = RayCulling(0u, 0.0);\n";
    for (const std::vector<Entry>* entries : {&cheap, &bounded})
        for (const Entry& entry : *entries)
            for (const CullingPiece& piece : entry.pieces)
                out << "    " << (piece.halfSpace ? "cullByHalfSpace" : "cullByBall")
                    << "(culling, " << piece.bit << "u, " << slot(piece.slot)
                    << ", origin, direction, tolerance0, toleranceGrowth);\n";
    if (!everyObjectCulled)
        out << "    // Some objects have no bound to cull by: the ray may meet them anywhere.\n"
               "    culling.escapeDistance = FLOAT_MAX;\n";
    out << "    return culling;\n}\n";
    return out.str();
}

// The general shader's distance to one primitive: a branch per kind, the kinds that read
// fewer parameter vec4s first so that each vec4 is fetched once and only where needed.
std::string primitiveInterpreter()
{
    const char* const names = "abcdefgh";
    std::vector<const PrimitiveKind*> kinds;
    for (const PrimitiveKind& kind : primitiveKinds())
        kinds.push_back(&kind);
    std::stable_sort(kinds.begin(), kinds.end(), [](const PrimitiveKind* a, const PrimitiveKind* b) {
        return a->parameterCount < b->parameterCount;
    });
    std::ostringstream out;
    out << "// Primitive `kind` with its parameters from uShapeParameters[first]; `extra` counts a\n"
           "// union's terms (a polyhedron's planes) or names the user SDF (scene/Primitives.h).\n"
           "float primitiveDistance(int kind, int first, int extra, vec3 p)\n{\n";
    int fetched = 0;
    auto fetch = [&](int count) {
        for (; fetched < count; ++fetched)
            out << "    vec4 " << names[fetched] << " = uShapeParameters[first"
                << (fetched == 0 ? "" : " + " + std::to_string(fetched)) << "];\n";
    };
    fetch(1);  // the user SDF's
    for (const PrimitiveKind* kind : kinds) {
        const std::string code = primitiveCodeName(*kind);
        if (kind->unionOfTerms) {
            out << "    if (kind == " << code << ") {\n        float d = FLOAT_MAX;\n"
                << "        for (int term = 0; term < extra && loopIterationAllowed(); ++term)\n"
                << "            d = min(d, "
                << distanceOverSlots(*kind, [](int) { return "uShapeParameters[first + term]"; })
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
        const std::string call = std::string(op.function) + "(a, b" +
                                 (op.hasParameter() ? ", parameter" : "") + ")";
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

bool specializesFeatures(ShaderVariant variant)
{
    return variant == ShaderVariant::Specialized || variant == ShaderVariant::FeaturesOnly;
}

bool specializesShapes(ShaderVariant variant)
{
    return variant == ShaderVariant::Specialized || variant == ShaderVariant::ShapesOnly;
}

SceneShaderCode generateSceneShaderCode(const Scene& scene, const ShaderBuild& build)
{
    const ShaderVariant variant = build.variant;
    const EnvironmentBinding environment = build.environment;
    SceneShaderCode code;
    code.variant = variant;
    code.exactGeometry = build.exactGeometry;
    code.profileCounters = build.profileCounters;
    const bool specialized = specializesShapes(variant);
    code.features = specializesFeatures(variant) ? analyseFeatures(scene)
                                                 : SceneFeatures::everything(scene);
    if (!specialized)
        // The interpreter reads transforms whether or not this scene has any.
        code.features.transforms = true;
    for (const auto& [name, path] : code.features.userSdfs)
        code.userSdfFiles.push_back(path);

    ShapeCompiler compiler(code);
    if (specialized) {
        code.sceneFunctions = specializedSceneFunctions(scene, compiler, code.objectCullingBits,
                                                        code.marchesAnything);
    } else {
        for (const SceneObject& object : scene.objects) {
            code.objectProgramStart.push_back(static_cast<int>(code.shapeProgram.size()));
            compiler.emitProgram(object.shape, 0);
            code.shapeProgram.emplace_back(instruction(Opcode::End), 0, 0, 0);
            const ShapeBound bound = boundShape(object.shape);
            code.objectBounds.push_back(worthBounding(object) && bound.finite
                                            ? glm::vec4(bound.center, bound.radius)
                                            : glm::vec4(0.0f, 0.0f, 0.0f, -1.0f));
        }
        // Declared before the interpreter module, which calls it.
        code.sceneFunctions = userSdfDispatcher(compiler.userSdfIds()) + "\n" +
                              primitiveInterpreter() + "\n" + csgInterpreter();
        // The interpreter's culled forms leave out object k < 32 where mask bit k is clear.
        for (std::size_t i = 0; i < scene.objects.size(); ++i)
            code.objectCullingBits.push_back(i < 32 ? 1u << i : 0u);
    }
    if (build.exactGeometry) {
        code.exactFunctions = generateExactSceneIntersection(scene, code.shapeParameters);
    }

    const SceneFeatures& f = code.features;
    const int lightCount =
        static_cast<int>(scene.pointLights.size() + sphereLights(scene).size());
    std::ostringstream out;
    define(out, "OBJECT_COUNT", static_cast<int>(scene.objects.size()));
    define(out, "OBJECT_ARRAY_SIZE", std::max<int>(1, scene.objects.size()));
    define(out, "SHAPE_PARAMETER_ARRAY_SIZE", std::max<int>(1, code.shapeParameters.size()));
    define(out, "SHAPE_PROGRAM_ARRAY_SIZE", std::max<int>(1, code.shapeProgram.size()));
    define(out, "SHAPE_STACK_DEPTH", compiler.maxStackDepth() + 1);
    define(out, "PIGMENT_ARRAY_SIZE", std::max<int>(1, scene.pigments.size()));
    define(out, "FINISH_ARRAY_SIZE", std::max<int>(1, scene.finishes.size()));
    define(out, "LIGHT_COUNT", lightCount);
    define(out, "LIGHT_ARRAY_SIZE", std::max(1, lightCount));
    for (const MaterialDescription& material : materialDescriptions())
        if (material.featureSwitch != nullptr)
            define(out, material.featureSwitch, f.has(material.kind) ? 1 : 0);
    define(out, "HAS_NULL_INTERFACES", f.nullInterfaces ? 1 : 0);
    for (const PigmentDescription& pigment : pigmentDescriptions())
        if (pigment.featureSwitch != nullptr)
            define(out, pigment.featureSwitch, f.has(pigment.kind) ? 1 : 0);
    define(out, "HAS_POINT_LIGHTS", f.pointLights ? 1 : 0);
    define(out, "HAS_SPHERE_LIGHTS", f.sphereLights ? 1 : 0);
    out << "#define ENVIRONMENT_KIND_FROM_UNIFORM (-1)\n";
    if (specializesFeatures(variant) && environment == EnvironmentBinding::BuiltIn)
        define(out, "ENVIRONMENT_KIND", describe(f.environment).code);
    else
        out << "#define ENVIRONMENT_KIND ENVIRONMENT_KIND_FROM_UNIFORM\n";
    define(out, "PROFILE_COUNTERS", build.profileCounters ? 1 : 0);
    // Where every object is met exactly (polyhedra, spheres, lights), no ray marches: the
    // sphere tracer's loops are left out, which llvmpipe would otherwise run once per ray
    // with no pixel in them.
    define(out, "HAS_MARCHED_OBJECTS", code.marchesAnything ? 1 : 0);
    out << shaderCodeDefines();
    code.defines = out.str();
    return code;
}

}  // namespace render
