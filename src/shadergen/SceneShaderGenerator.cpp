#include "shadergen/SceneShaderGenerator.h"

#include "scene/PrimitiveKinds.h"
#include "scene/SceneBounds.h"
#include "shadergen/ExactSceneIntersection.h"
#include "shadergen/InterpretedSceneCode.h"
#include "shadergen/ShaderCodes.h"
#include "shadergen/SpecializedSceneCode.h"

#include <algorithm>
#include <sstream>

namespace shadergen {

using namespace scene;

namespace {

void define(std::ostringstream& out, const std::string& name, int value)
{
    out << "#define " << name << " " << value << "\n";
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

namespace {

std::size_t weightOf(const Shape& shape)
{
    std::size_t weight = shape.transform ? 2 : 1;
    if (const auto* node = std::get_if<CsgNode>(&shape.geometry))
        for (const Shape& child : node->children)
            weight += weightOf(child);
    return weight;
}

// Whether the interpreter meets `object` exactly (isExactObject, shape_interpreter.glsl): a
// program of one primitive (a transform the compiler folds into the parameters of a kind it
// maps to itself leaves none), of a kind with a closed form that this shape of it trusts,
// and no sphere light. Anything else is marched. The same rule as the shader's, which reads
// this answer from the hierarchy's list of objects.
bool interpreterMeetsExactly(const SceneObject& object, const std::vector<glm::ivec4>& program,
                             int start, bool sphereLight, bool marchBoxesCylindersAndDisks)
{
    const auto at = static_cast<std::size_t>(start);
    const bool single = at + 1 < program.size() &&
                        program[at].x == static_cast<int>(Opcode::Primitive) &&
                        program[at + 1].x == static_cast<int>(Opcode::End);
    const PrimitiveKind* kind = primitiveKindOf(object.shape.geometry);
    return single && kind != nullptr && kind->exact != nullptr &&
           kind->metExactly(object.shape.geometry) &&
           !(kind->marchedOnRequest && marchBoxesCylindersAndDisks) &&
           !(sphereLight && std::holds_alternative<Sphere>(object.shape.geometry));
}

}  // namespace

std::size_t shapeCodeWeight(const Scene& scene)
{
    std::size_t weight = 0;
    for (const SceneObject& object : scene.objects)
        weight += weightOf(object.shape);
    return weight;
}

ShaderVariant variantForScene(const Scene& scene, ShaderVariant asked)
{
    if (!specializesShapes(asked) || shapeCodeWeight(scene) <= kMostShapeCodeWeight)
        return asked;
    return asked == ShaderVariant::Specialized ? ShaderVariant::FeaturesOnly
                                               : ShaderVariant::General;
}

ShaderBuild shaderBuild(const settings::RenderSettings& settings)
{
    ShaderBuild build;
    build.variant = settings.variant;
    build.environment = settings.switchableEnvironment ? EnvironmentBinding::FromUniform
                                                       : EnvironmentBinding::BuiltIn;
    build.exactGeometry = settings.exactGeometry;
    build.profileCounters = settings.profileCounters;
    build.marchBoxesCylindersAndDisks = settings.marchBoxesCylindersAndDisks;
    build.featureBuffers = settings.featureBuffers;
    return build;
}

SceneShaderCode generateSceneShaderCode(const Scene& scene, const ShaderBuild& build)
{
    const ShaderVariant variant =
        build.shapesByWeight ? variantForScene(scene, build.variant) : build.variant;
    const EnvironmentBinding environment = build.environment;
    SceneShaderCode code;
    code.variant = variant;
    code.exactGeometry = build.exactGeometry;
    code.profileCounters = build.profileCounters;
    const bool specialized = specializesShapes(variant);
    code.features =
        specializesFeatures(variant) ? analyseFeatures(scene) : SceneFeatures::everything(scene);
    if (!specialized)
        // The interpreter reads transforms whether or not this scene has any.
        code.features.transforms = true;
    for (const auto& [name, path] : code.features.userSdfs)
        code.userSdfFiles.push_back(path);

    ShapeCompiler compiler(code.shapeParameters, code.shapeProgram);
    if (specialized) {
        code.plan = planScene(scene, compiler, build.marchBoxesCylindersAndDisks);
        code.objectCullingBits = code.plan.objectCullingBits;
        code.marchesAnything = code.plan.marchesAnything;
        code.marchedUnion = code.plan.marchedSurfaceCount >= 2;
        code.sceneFunctions = specializedSceneFunctions(code.plan, compiler.functions());
    } else {
        InterpretedScene interpreted =
            interpretedScene(scene, compiler, specializesFeatures(variant));
        code.objectProgramStart = std::move(interpreted.objectProgramStart);
        code.objectBounds = std::move(interpreted.objectBounds);
        code.sceneFunctions = std::move(interpreted.functions);
        // The interpreter's culled forms leave out object k < 32 where mask bit k is clear.
        for (std::size_t i = 0; i < scene.objects.size(); ++i)
            code.objectCullingBits.push_back(i < kCullingBits ? 1u << i : 0u);
        std::vector<bool> sphereLight(scene.objects.size(), false);
        // Sphere lights with a culling bit that no ray can be inside (no dielectric, the
        // camera outside) are met exactly by every ray and never marched: as planScene.
        std::vector<bool> neverMarched(scene.objects.size(), false);
        for (const SphereLight& light : sphereLights(scene)) {
            const auto object = static_cast<std::size_t>(light.object);
            sphereLight[object] = true;
            const bool enterable = scene.finishes[scene.objects[object].finish].material() ==
                                       MaterialKind::Dielectric ||
                                   glm::length(scene.camera.eye - light.center) < light.radius;
            neverMarched[object] = object < static_cast<std::size_t>(kCullingBits) && !enterable;
        }
        code.marchesAnything = false;
        for (std::size_t i = 0; i < scene.objects.size(); ++i) {
            const bool marched = !interpreterMeetsExactly(
                scene.objects[i], code.shapeProgram, code.objectProgramStart[i], sphereLight[i],
                build.marchBoxesCylindersAndDisks);
            code.objectMarched.push_back(marched);
            code.marchesAnything = code.marchesAnything || (marched && !neverMarched[i]);
            // A marched object is marched only where rays come near its bounding sphere
            // (shape_interpreter.glsl, marchedObjectStretch): every one with a finite bound
            // gets one, not only the expensive shapes the distance walk skips by it.
            if (marched && code.objectBounds[i].w < 0.0f) {
                const ShapeBound bound = boundShape(scene.objects[i].shape);
                if (bound.finite)
                    code.objectBounds[i] = glm::vec4(bound.center, bound.radius);
            }
        }
    }
    if (build.exactGeometry) {
        code.exactFunctions = generateExactSceneIntersection(scene, code.shapeParameters);
    }

    const SceneFeatures& f = code.features;
    const std::vector<Light> lights = sceneLights(scene);
    const int lightCount = static_cast<int>(lights.size());
    int environmentLight = -1;
    for (std::size_t i = 0; i < lights.size(); ++i)
        if (lights[i].kind == LightKind::Environment)
            environmentLight = static_cast<int>(i);
    std::ostringstream out;
    if (!specialized) {
        // The general shader reads its objects from buffer textures and finds them through a
        // hierarchy (shape_interpreter.glsl); the objects without a finite bound come first
        // in its list of objects, and every query tests them.
        int unbounded = 0;
        for (const SceneObject& object : scene.objects)
            unbounded += boundShape(object.shape).finite ? 0 : 1;
        define(out, "HIERARCHY_UNBOUNDED_COUNT", unbounded);
        define(out, "HIERARCHY_HAS_NODES", unbounded < static_cast<int>(scene.objects.size()));
    }
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
    define(out, "HAS_MICROFACET", f.microfacets ? 1 : 0);
    define(out, "HAS_NULL_INTERFACES", f.nullInterfaces ? 1 : 0);
    define(out, "HAS_THIN_LENS", f.thinLens ? 1 : 0);
    for (const PigmentDescription& pigment : pigmentDescriptions())
        if (pigment.featureSwitch != nullptr)
            define(out, pigment.featureSwitch, f.has(pigment.kind) ? 1 : 0);
    for (const LightDescription& light : lightDescriptions())
        define(out, light.featureSwitch, f.has(light.kind) ? 1 : 0);
    // Where the environment's light record is (integrator.glsl weighs escaping rays by it).
    define(out, "ENVIRONMENT_LIGHT_INDEX", environmentLight);
    for (const EnvironmentDescription& kind : environmentDescriptions())
        if (kind.featureSwitch != nullptr)
            define(out, kind.featureSwitch, f.has(kind.kind) ? 1 : 0);
    out << "#define ENVIRONMENT_KIND_FROM_UNIFORM (-1)\n";
    if (specializesFeatures(variant) && environment == EnvironmentBinding::BuiltIn)
        define(out, "ENVIRONMENT_KIND", describe(f.environment).code);
    else
        out << "#define ENVIRONMENT_KIND ENVIRONMENT_KIND_FROM_UNIFORM\n";
    define(out, "PROFILE_COUNTERS", build.profileCounters ? 1 : 0);
    define(out, "FEATURE_BUFFERS", build.featureBuffers ? 1 : 0);
    define(out, "EXACT_BOXES_CYLINDERS_AND_DISKS", build.marchBoxesCylindersAndDisks ? 0 : 1);
    out << "#define THINNEST_EXACT_TORUS " << Primitive<Torus>::kThinnestExact << "\n";
    // Where every object is met exactly (polyhedra, spheres, lights), no ray marches: the
    // sphere tracer's loops are left out, which llvmpipe would otherwise run once per ray
    // with no pixel in them.
    define(out, "HAS_MARCHED_OBJECTS", code.marchesAnything ? 1 : 0);
    // One marched object: its gradient is never tilted by another's, and a gradient whose
    // length is not 1 is its own field's (a user SDF that is no exact distance), which
    // backing off would not change: llvmpipe would pay a second gradient at every hit.
    define(out, "HAS_MARCHED_UNION", code.marchedUnion ? 1 : 0);
    // The generated shape code reads the shape parameters at constant indices: they are read
    // once per pixel, before any branch (scene_data.glsl). The interpreter's indices vary.
    define(out, "SHAPE_PARAMETERS_READ_ONCE",
           specializesShapes(variant) && code.shapeParameters.size() <= kMostShapeParametersReadOnce
               ? 1
               : 0);
    out << shaderCodeDefines();
    code.defines = out.str();
    return code;
}

}  // namespace shadergen
