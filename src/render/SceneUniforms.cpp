#include "render/SceneUniforms.h"

#include "gl/Shader.h"
#include "scene/Lights.h"

#include <glm/gtc/type_ptr.hpp>

#include <cmath>
#include <map>

namespace render {

using namespace scene;

namespace {

constexpr float kPi = 3.14159265358979f;

template <typename Vector>
void setArray(const gl::Program& program, const char* name, const std::vector<Vector>& values);

template <>
void setArray(const gl::Program& program, const char* name, const std::vector<glm::vec4>& values)
{
    const GLint location = program.uniformLocation(name);
    if (location >= 0 && !values.empty())
        glUniform4fv(location, static_cast<GLsizei>(values.size()), glm::value_ptr(values[0]));
}

template <>
void setArray(const gl::Program& program, const char* name, const std::vector<glm::ivec4>& values)
{
    const GLint location = program.uniformLocation(name);
    if (location >= 0 && !values.empty())
        glUniform4iv(location, static_cast<GLsizei>(values.size()), glm::value_ptr(values[0]));
}

void setFloat(const gl::Program& program, const char* name, float value)
{
    glUniform1f(program.uniformLocation(name), value);
}

void setInt(const gl::Program& program, const char* name, int value)
{
    glUniform1i(program.uniformLocation(name), value);
}

void setVec3(const gl::Program& program, const char* name, const glm::vec3& value)
{
    glUniform3fv(program.uniformLocation(name), 1, glm::value_ptr(value));
}

}  // namespace

bool SceneUniforms::operator==(const SceneUniforms& other) const
{
    return objects == other.objects && pigments == other.pigments &&
           finishes == other.finishes && conductors == other.conductors &&
           lights == other.lights && lens.apertureRadius == other.lens.apertureRadius &&
           lens.focusDistance == other.lens.focusDistance &&
           sphereLightPieces == other.sphereLightPieces &&
           textureLayers == other.textureLayers &&
           cameraFrame.right == other.cameraFrame.right &&
           cameraFrame.trueUp == other.cameraFrame.trueUp &&
           cameraFrame.forward == other.cameraFrame.forward && cameraEye == other.cameraEye &&
           tanHalfFovy == other.tanHalfFovy && bounds.center == other.bounds.center &&
           bounds.radius == other.bounds.radius && environment.kind == other.environment.kind &&
           environment.color == other.environment.color &&
           environment.mapPath == other.environment.mapPath &&
           environment.intensity == other.environment.intensity &&
           environment.rotationDegrees == other.environment.rotationDegrees;
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
        packed.pigments.emplace_back(static_cast<float>(describe(pigment.kind).code), pigment.size,
                                     layer, 0.0f);
        packed.pigments.emplace_back(pigment.color, 0.0f);
        packed.pigments.emplace_back(pigment.secondColor, 0.0f);
    }

    for (const Finish& finish : scene.finishes) {
        packed.finishes.emplace_back(finish.emission, finish.phongExponent);
        packed.finishes.emplace_back(static_cast<float>(describe(finish.material()).code),
                                     finish.ior, finish.roughness, 0.0f);
        // w = 1: the complex index below; 0: Schlick's Fresnel with the pigment as R0.
        const ComplexIor ior = finish.conductorIor.value_or(ComplexIor{});
        packed.conductors.emplace_back(ior.eta, finish.conductorIor ? 1.0f : 0.0f);
        packed.conductors.emplace_back(ior.k, 0.0f);
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
        const float probability =
            totalPower > 0.0 ? static_cast<float>(powers[i] / totalPower) : 0.0f;
        cumulativeProbability += totalPower > 0.0 ? powers[i] / totalPower : 0.0;
        // The last light closes the table exactly at 1 whatever the rounding.
        const float cdf =
            i + 1 == lights.size() ? 1.0f : static_cast<float>(cumulativeProbability);
        // A light that is an object takes the object's culling bit: rays leave it out of
        // their marches and meet it exactly (ray_queries_traced.glsl).
        std::uint32_t bit = 0u;
        if (light.object >= 0) {
            lightOfObject[light.object] = static_cast<int>(i);
            if (static_cast<std::size_t>(light.object) < code.objectCullingBits.size())
                bit = code.objectCullingBits[light.object];
            packed.sphereLightPieces |= bit;
        }
        packed.lights.emplace_back(light.position, light.radius);
        packed.lights.emplace_back(light.emission, probability);
        packed.lights.emplace_back(cdf, static_cast<float>(light.object),
                                   static_cast<float>(bit),
                                   static_cast<float>(describe(light.kind).code));
    }

    for (std::size_t i = 0; i < scene.objects.size(); ++i) {
        const SceneObject& object = scene.objects[i];
        const int programStart = i < code.objectProgramStart.size() ? code.objectProgramStart[i] : 0;
        packed.objects.emplace_back(object.pigment, object.finish, lightOfObject[i], programStart);
    }

    packed.cameraFrame = cameraFrame(scene.camera);
    packed.cameraEye = scene.camera.eye;
    packed.tanHalfFovy =
        std::tan(0.5f * scene.camera.verticalFieldOfViewDegrees * kPi / 180.0f);
    packed.lens = scene.camera.lens.value_or(ThinLens{});
    packed.environment = scene.environment;
    return packed;
}

void uploadUniforms(const gl::Program& program, const SceneUniforms& uniforms,
                    const shadergen::SceneShaderCode& code, const settings::RenderSettings& settings, int width,
                    int height)
{
    setArray(program, "uShapeParameters", code.shapeParameters);
    setArray(program, "uShapeProgram", code.shapeProgram);
    setArray(program, "uObjectBounds", code.objectBounds);
    setArray(program, "uObjects", uniforms.objects);
    setArray(program, "uPigments", uniforms.pigments);
    setArray(program, "uFinishes", uniforms.finishes);
    setArray(program, "uFinishConductors", uniforms.conductors);
    setArray(program, "uLights", uniforms.lights);

    setVec3(program, "uCameraEye", uniforms.cameraEye);
    setVec3(program, "uCameraRight", uniforms.cameraFrame.right);
    setVec3(program, "uCameraUp", uniforms.cameraFrame.trueUp);
    setVec3(program, "uCameraForward", uniforms.cameraFrame.forward);
    setFloat(program, "uTanHalfFovy", uniforms.tanHalfFovy);
    setFloat(program, "uLensRadius", uniforms.lens.apertureRadius);
    setFloat(program, "uFocusDistance", uniforms.lens.focusDistance);
    glUniform2f(program.uniformLocation("uImageSize"), static_cast<float>(width),
                static_cast<float>(height));

    setInt(program, "uEnvironmentKind",
           describe(settings.environmentLight ? uniforms.environment.kind : EnvironmentKind::None)
               .code);
    setVec3(program, "uEnvironmentColor", uniforms.environment.color);
    if (uniforms.environment.kind == EnvironmentKind::Map) {
        const float angle = uniforms.environment.rotationDegrees * kPi / 180.0f;
        setFloat(program, "uEnvironmentIntensity", uniforms.environment.intensity);
        glUniform2f(program.uniformLocation("uEnvironmentRotation"), std::cos(angle),
                    std::sin(angle));
    }

    setFloat(program, "uMinimumHitDistance", uniforms.bounds.minimumHitDistance());
    setFloat(program, "uFarDistance", uniforms.bounds.farDistance());
    setFloat(program, "uHitTolerance", settings.hitTolerance);
    setInt(program, "uMaxMarchSteps", settings.maxMarchSteps);
    setFloat(program, "uOverRelaxation", settings.overRelaxation);
    setFloat(program, "uStepScale", settings.stepScale);
    setInt(program, "uMaxBounces", settings.maxBounces);
    setInt(program, "uRussianRouletteDepth", settings.russianRouletteDepth);
    setInt(program, "uUseMis", settings.multipleImportanceSampling ? 1 : 0);
    setInt(program, "uRayCulling", settings.rayCulling ? 1 : 0);
    setInt(program, "uExactFresnel", settings.dielectricFresnel == settings::FresnelModel::Exact ? 1 : 0);
    setInt(program, "uEnergyCompensation", settings.energyCompensation ? 1 : 0);
    setInt(program, "uSeparableMasking",
           settings.masking == settings::MaskingModel::Separable ? 1 : 0);
    setInt(program, "uSampler", settings.sampler == settings::SamplerKind::Sobol ? 1 : 0);
    glUniform1ui(program.uniformLocation("uSphereLightPieces"), uniforms.sphereLightPieces);
    glUniform2ui(program.uniformLocation("uSeed"), static_cast<GLuint>(settings.seed),
                 static_cast<GLuint>(settings.seed >> 32));
}

}  // namespace render
