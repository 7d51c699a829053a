#include "render/SceneUniforms.h"

#include "gl/Shader.h"

#include <glm/gtc/type_ptr.hpp>

#include <cmath>
#include <map>

namespace render {

using namespace scene;

namespace {

constexpr float kPi = 3.14159265358979f;

double average(const glm::dvec3& v)
{
    return (v.x + v.y + v.z) / 3.0;
}

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

// In double: the power of a bright, large sphere light (radiance near the float maximum)
// overflows float, and one infinite power would make every selection probability NaN.
std::vector<double> lightPowers(const Scene& scene)
{
    constexpr double kPiDouble = 3.14159265358979323846;
    std::vector<double> powers;
    for (const PointLight& light : scene.pointLights)
        powers.push_back(4.0 * kPiDouble * average(glm::dvec3(light.intensity)));
    for (const SphereLight& light : sphereLights(scene)) {
        const double radius = light.radius;
        powers.push_back(4.0 * kPiDouble * kPiDouble * radius * radius *
                         average(glm::dvec3(light.radiance)));
    }
    return powers;
}

bool SceneUniforms::operator==(const SceneUniforms& other) const
{
    return objects == other.objects && pigments == other.pigments &&
           finishes == other.finishes && lights == other.lights &&
           sphereLightPieces == other.sphereLightPieces &&
           textureLayers == other.textureLayers &&
           cameraFrame.right == other.cameraFrame.right &&
           cameraFrame.trueUp == other.cameraFrame.trueUp &&
           cameraFrame.forward == other.cameraFrame.forward && cameraEye == other.cameraEye &&
           tanHalfFovy == other.tanHalfFovy && bounds.center == other.bounds.center &&
           bounds.radius == other.bounds.radius && environment.kind == other.environment.kind &&
           environment.color == other.environment.color;
}

SceneUniforms packSceneUniforms(const Scene& scene, const shadergen::SceneShaderCode& code)
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
                                     finish.ior, 0.0f, 0.0f);
    }

    const std::vector<SphereLight> spheres = sphereLights(scene);
    const std::vector<double> powers = lightPowers(scene);
    double totalPower = 0.0;
    for (double power : powers)
        totalPower += power;
    std::vector<int> lightOfObject(scene.objects.size(), -1);
    double cumulativeProbability = 0.0;
    for (std::size_t i = 0; i < powers.size(); ++i) {
        const float probability =
            totalPower > 0.0 ? static_cast<float>(powers[i] / totalPower) : 0.0f;
        cumulativeProbability += totalPower > 0.0 ? powers[i] / totalPower : 0.0;
        // The last light closes the table exactly at 1 whatever the rounding.
        const float cdf =
            i + 1 == powers.size() ? 1.0f : static_cast<float>(cumulativeProbability);
        if (i < scene.pointLights.size()) {
            const PointLight& light = scene.pointLights[i];
            packed.lights.emplace_back(light.position, 0.0f);
            packed.lights.emplace_back(light.intensity, probability);
            packed.lights.emplace_back(cdf, -1.0f, 0.0f, 0.0f);
        } else {
            const SphereLight& light = spheres[i - scene.pointLights.size()];
            lightOfObject[light.object] = static_cast<int>(i);
            packed.lights.emplace_back(light.center, light.radius);
            packed.lights.emplace_back(light.radiance, probability);
            const std::uint32_t bit = static_cast<std::size_t>(light.object) <
                                              code.objectCullingBits.size()
                                          ? code.objectCullingBits[light.object]
                                          : 0u;
            packed.lights.emplace_back(cdf, static_cast<float>(light.object),
                                       static_cast<float>(bit), 0.0f);
            packed.sphereLightPieces |= bit;
        }
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
    packed.bounds = computeSceneBounds(scene);
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
    setArray(program, "uLights", uniforms.lights);

    setVec3(program, "uCameraEye", uniforms.cameraEye);
    setVec3(program, "uCameraRight", uniforms.cameraFrame.right);
    setVec3(program, "uCameraUp", uniforms.cameraFrame.trueUp);
    setVec3(program, "uCameraForward", uniforms.cameraFrame.forward);
    setFloat(program, "uTanHalfFovy", uniforms.tanHalfFovy);
    glUniform2f(program.uniformLocation("uImageSize"), static_cast<float>(width),
                static_cast<float>(height));

    setInt(program, "uEnvironmentKind",
           describe(settings.environmentLight ? uniforms.environment.kind : EnvironmentKind::None)
               .code);
    setVec3(program, "uEnvironmentColor", uniforms.environment.color);

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
    setInt(program, "uSampler", settings.sampler == settings::SamplerKind::Sobol ? 1 : 0);
    glUniform1ui(program.uniformLocation("uSphereLightPieces"), uniforms.sphereLightPieces);
    glUniform2ui(program.uniformLocation("uSeed"), static_cast<GLuint>(settings.seed),
                 static_cast<GLuint>(settings.seed >> 32));
}

}  // namespace render
