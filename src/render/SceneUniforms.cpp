#include "render/SceneUniforms.h"

#include "render/ProgramUniforms.h"
#include "scene/Lights.h"
#include "settings/SettingsTable.h"
#include "shadergen/ObjectHierarchy.h"
#include "shadergen/SceneRecords.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <optional>

namespace render {

using namespace scene;

namespace {

constexpr float kPi = 3.14159265358979f;

// A row of sceneValueUniforms(): the GLSL type follows from what `value` returns.
template <typename Value>
SceneValueUniform sceneValue(const char* name, const char* module,
                             Value (*value)(const UniformSources&), const char* guard = "")
{
    const std::string uniform = name;
    return {{settings::glslTypeOf<Value>(), uniform, "g" + uniform.substr(1), module, guard},
            [value](const UniformSources& sources) -> settings::UniformValue {
                return value(sources);
            }};
}

}  // namespace

const std::vector<SceneValueUniform>& sceneValueUniforms()
{
    using S = const UniformSources&;
    static const std::vector<SceneValueUniform> table = {
        // The scene's bounds: what a hit's distance and a ray's end are measured against.
        sceneValue<float>("uMinimumHitDistance", "sphere_tracing.glsl",
                          [](S s) { return s.scene.bounds.minimumHitDistance(); }),
        sceneValue<float>("uFarDistance", "sphere_tracing.glsl",
                          [](S s) { return s.scene.bounds.farDistance(); }),
        // The camera's orthonormal frame (camera.glsl).
        sceneValue<glm::vec3>("uCameraEye", "camera.glsl", [](S s) { return s.scene.cameraEye; }),
        sceneValue<glm::vec3>("uCameraRight", "camera.glsl",
                              [](S s) { return s.scene.cameraFrame.right; }),
        sceneValue<glm::vec3>("uCameraUp", "camera.glsl",
                              [](S s) { return s.scene.cameraFrame.trueUp; }),
        sceneValue<glm::vec3>("uCameraForward", "camera.glsl",
                              [](S s) { return s.scene.cameraFrame.forward; }),
        sceneValue<float>("uTanHalfFovy", "camera.glsl", [](S s) { return s.scene.tanHalfFovy; }),
        // A thin lens's aperture and plane of focus (camera.glsl), in scenes that have one.
        sceneValue<float>(
            "uLensRadius", "camera.glsl", [](S s) { return s.scene.lens.apertureRadius; },
            "HAS_THIN_LENS"),
        sceneValue<float>(
            "uFocusDistance", "camera.glsl", [](S s) { return s.scene.lens.focusDistance; },
            "HAS_THIN_LENS"),
        sceneValue<glm::vec2>("uImageSize", "camera.glsl",
                              [](S s) {
                                  return glm::vec2(static_cast<float>(s.width),
                                                   static_cast<float>(s.height));
                              }),
        sceneValue<float>("uPigmentTextureSize", "pigments.glsl",
                          [](S s) { return s.pigmentTextureSize; }),
        // The general shader, and the window's, read the environment's kind here (the panel
        // switches it off without a recompile); a specialised one builds it in.
        sceneValue<int>("uEnvironmentKind", "environment.glsl",
                        [](S s) {
                            return describe(s.settings.environmentLight ? s.scene.environment.kind
                                                                        : EnvironmentKind::None)
                                .code;
                        }),
        sceneValue<glm::vec3>("uEnvironmentColor", "environment.glsl",
                              [](S s) { return s.scene.environment.color; }),
        // An environment map's scale and its turn about +y, as (cos, sin) (environment.glsl).
        sceneValue<float>(
            "uEnvironmentIntensity", "environment.glsl",
            [](S s) { return s.scene.environment.intensity; }, "HAS_ENVIRONMENT_MAP"),
        sceneValue<glm::vec2>(
            "uEnvironmentRotation", "environment.glsl",
            [](S s) {
                const float angle = s.scene.environment.rotationDegrees * kPi / 180.0f;
                return glm::vec2(std::cos(angle), std::sin(angle));
            },
            "HAS_ENVIRONMENT_MAP"),
        // The culling bits of every light that is an object and has one: rays leave those out of their
        // marches and intersect the spheres exactly instead (ray_queries_traced.glsl).
        sceneValue<unsigned int>("uSphereLightPieces", "scene_data.glsl",
                                 [](S s) { return s.scene.sphereLightPieces; }),
    };
    return table;
}

std::vector<shadergen::UniformDeclaration> pathTracerUniformDeclarations()
{
    std::vector<shadergen::UniformDeclaration> declarations =
        shadergen::settingUniformDeclarations();
    for (const SceneValueUniform& row : sceneValueUniforms())
        declarations.push_back(row.declaration);
    return declarations;
}

bool SceneUniforms::operator==(const SceneUniforms& other) const
{
    return objects == other.objects && pigments == other.pigments && finishes == other.finishes &&
           conductors == other.conductors && lights == other.lights &&
           lens.apertureRadius == other.lens.apertureRadius &&
           lens.focusDistance == other.lens.focusDistance &&
           sphereLightPieces == other.sphereLightPieces && textureLayers == other.textureLayers &&
           cameraFrame.right == other.cameraFrame.right &&
           cameraFrame.trueUp == other.cameraFrame.trueUp &&
           cameraFrame.forward == other.cameraFrame.forward && cameraEye == other.cameraEye &&
           tanHalfFovy == other.tanHalfFovy && bounds.center == other.bounds.center &&
           bounds.radius == other.bounds.radius && environment.kind == other.environment.kind &&
           environment.color == other.environment.color &&
           environment.mapPath == other.environment.mapPath &&
           environment.intensity == other.environment.intensity &&
           environment.rotationDegrees == other.environment.rotationDegrees &&
           hierarchyBoxes == other.hierarchyBoxes && hierarchyLinks == other.hierarchyLinks;
}

namespace {

// The object's world-space box for the hierarchy: its bounding sphere's, widened by a little
// more than float rounding so that the slab test never loses a ray grazing the shape.
std::optional<shadergen::Box> hierarchyBox(const Shape& shape)
{
    const ShapeBound bound = boundShape(shape);
    if (!bound.finite)
        return std::nullopt;
    const float pad = 1e-4f * bound.radius + 1e-6f * glm::length(bound.center) + 1e-7f;
    shadergen::Box box;
    box.lower = bound.center - glm::vec3(bound.radius + pad);
    box.upper = bound.center + glm::vec3(bound.radius + pad);
    return box;
}

// Builds the hierarchy and lays it out for the buffer textures (shape_interpreter.glsl):
// the objects' list (unbounded objects first, as HIERARCHY_UNBOUNDED_COUNT counts them, then
// each leaf's; a marched object as -1 - its index) four a texel, then a texel (skip, first, count, holds marched) per node; and
// two box corners per node.
void packHierarchy(const Scene& scene, const shadergen::SceneShaderCode& code,
                   SceneUniforms& packed)
{
    const auto start = std::chrono::steady_clock::now();
    std::vector<shadergen::HierarchyObject> objects(scene.objects.size());
    for (std::size_t i = 0; i < scene.objects.size(); ++i) {
        objects[i].bounds = hierarchyBox(scene.objects[i].shape);
        objects[i].marched = i < code.objectMarched.size() && code.objectMarched[i];
    }
    const shadergen::ObjectHierarchy hierarchy =
        shadergen::buildObjectHierarchy(objects, setUpCheckpoint());
    std::vector<int> list = hierarchy.unbounded;
    const int leavesStart = static_cast<int>(list.size());
    list.insert(list.end(), hierarchy.leafObjects.begin(), hierarchy.leafObjects.end());
    // A marched object's entry is -1 - its index: the walks tell it from one met exactly
    // without reading its shape program (shape_interpreter.glsl).
    for (int& entry : list)
        if (objects[static_cast<std::size_t>(entry)].marched)
            entry = -1 - entry;
    list.resize(std::max<std::size_t>(4, (list.size() + 3) / 4 * 4), 0);
    for (std::size_t k = 0; k < list.size(); k += 4)
        packed.hierarchyLinks.emplace_back(list[k], list[k + 1], list[k + 2], list[k + 3]);
    for (const shadergen::HierarchyNode& node : hierarchy.nodes) {
        packed.hierarchyLinks.emplace_back(node.skip, leavesStart + node.first, node.count,
                                           node.holdsMarched ? 1 : 0);
        packed.hierarchyBoxes.emplace_back(node.bounds.lower, 0.0f);
        packed.hierarchyBoxes.emplace_back(node.bounds.upper, 0.0f);
    }
    packed.hierarchySeconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

std::function<void()>& checkpointSlot()
{
    static std::function<void()> checkpoint;
    return checkpoint;
}

}  // namespace

void setSetUpCheckpoint(std::function<void()> checkpoint)
{
    checkpointSlot() = std::move(checkpoint);
}

const std::function<void()>& setUpCheckpoint()
{
    return checkpointSlot();
}

SceneUniforms packSceneUniforms(const Scene& scene, const shadergen::SceneShaderCode& code,
                                const EnvironmentMap* environmentMap)
{
    SceneUniforms packed;

    std::map<std::filesystem::path, int> layers;
    for (const Pigment& pigment : scene.pigments) {
        float layer = 0.0f;
        if (pigment.kind == PigmentKind::Texture) {
            auto found = layers.find(pigment.texturePath);
            if (found == layers.end()) {
                found = layers.emplace(pigment.texturePath, static_cast<int>(layers.size())).first;
                packed.textureLayers.push_back(pigment.texturePath);
            }
            layer = static_cast<float>(found->second);
        }
        shadergen::PigmentRecord record;
        record.kind = describe(pigment.kind).code;
        record.size = pigment.size;
        record.textureLayer = layer;
        record.firstColor = pigment.color;
        record.secondColor = pigment.secondColor;
        shadergen::packRecord(shadergen::pigmentRecordLayout(), record, packed.pigments);
    }

    for (const Finish& finish : scene.finishes) {
        shadergen::FinishRecord record;
        record.emission = finish.emission;
        record.phongExponent = finish.phongExponent;
        record.material = describe(finish.material()).code;
        record.ior = finish.ior;
        record.roughness = finish.roughness;
        shadergen::packRecord(shadergen::finishRecordLayout(), record, packed.finishes);
        shadergen::ConductorRecord conductor;
        const ComplexIor ior = finish.conductorIor.value_or(ComplexIor{});
        conductor.eta = ior.eta;
        conductor.hasComplexIor = finish.conductorIor.has_value();
        conductor.k = ior.k;
        shadergen::packRecord(shadergen::conductorRecordLayout(), conductor, packed.conductors);
    }

    packed.bounds = computeSceneBounds(scene);
    LightPowerContext context;
    context.sceneRadius = packed.bounds.radius;
    if (environmentMap != nullptr)
        context.environmentIntegral = environmentMap->integral;
    const std::vector<Light> lights = sceneLights(scene);
    const std::vector<double> powers = lightPowers(lights, context);
    double totalPower = 0.0;
    for (double power : powers)
        totalPower += power;
    std::vector<int> lightOfObject(scene.objects.size(), -1);
    double cumulativeProbability = 0.0;
    for (std::size_t i = 0; i < lights.size(); ++i) {
        const Light& light = lights[i];
        shadergen::LightRecord record;
        record.selectionProbability =
            totalPower > 0.0 ? static_cast<float>(powers[i] / totalPower) : 0.0f;
        cumulativeProbability += totalPower > 0.0 ? powers[i] / totalPower : 0.0;
        // The last light closes the table exactly at 1 whatever the rounding.
        record.cumulativeProbability =
            i + 1 == lights.size() ? 1.0f : static_cast<float>(cumulativeProbability);
        record.position = light.position;
        record.radius = light.radius;
        record.emission = light.emission;
        record.object = light.object;
        record.kind = describe(light.kind).code;
        // A light that is an object takes the object's culling bit: rays leave it out of
        // their marches and meet it exactly (ray_queries_traced.glsl).
        if (light.object >= 0) {
            lightOfObject[light.object] = static_cast<int>(i);
            if (static_cast<std::size_t>(light.object) < code.objectCullingBits.size())
                record.cullingBit = code.objectCullingBits[light.object];
            packed.sphereLightPieces |= record.cullingBit;
        }
        shadergen::packRecord(shadergen::lightRecordLayout(), record, packed.lights);
    }

    for (std::size_t i = 0; i < scene.objects.size(); ++i) {
        const SceneObject& object = scene.objects[i];
        shadergen::ObjectRecord record;
        record.pigment = object.pigment;
        record.finish = object.finish;
        record.sphereLight = lightOfObject[i];
        record.shapeProgramStart =
            i < code.objectProgramStart.size() ? code.objectProgramStart[i] : 0;
        shadergen::packRecord(shadergen::objectRecordLayout(), record, packed.objects);
    }

    packed.cameraFrame = cameraFrame(scene.camera);
    packed.cameraEye = scene.camera.eye;
    packed.tanHalfFovy = std::tan(0.5f * scene.camera.verticalFieldOfViewDegrees * kPi / 180.0f);
    packed.lens = scene.camera.lens.value_or(ThinLens{});
    packed.environment = scene.environment;
    if (!shadergen::specializesShapes(code.variant))
        packHierarchy(scene, code, packed);
    return packed;
}

void uploadUniforms(ProgramUniforms& program, const UniformSources& sources,
                    const shadergen::SceneShaderCode& code)
{
    // The general shader reads these from buffer textures instead (render/SceneDataBuffers.h).
    if (shadergen::specializesShapes(code.variant)) {
        program.setArray("uShapeParameters", code.shapeParameters);
        program.setArray(shadergen::objectRecordLayout().uniform, sources.scene.objects);
    }
    program.setArray(shadergen::pigmentRecordLayout().uniform, sources.scene.pigments);
    program.setArray(shadergen::finishRecordLayout().uniform, sources.scene.finishes);
    program.setArray(shadergen::conductorRecordLayout().uniform, sources.scene.conductors);
    program.setArray(shadergen::lightRecordLayout().uniform, sources.scene.lights);

    // The values, where the shader has the module that reads them.
    for (const settings::SettingRow& row : settings::settingRows()) {
        const std::string name = settings::uniformName(row.field);
        if (row.isUniform() && program.declares(name))
            program.set(name, row.uniform(sources.settings));
    }
    for (const SceneValueUniform& row : sceneValueUniforms())
        if (program.declares(row.declaration.name))
            program.set(row.declaration.name, row.value(sources));
}

}  // namespace render
