#include "scene/Lights.h"

#include "scene/KindCodes.h"

namespace scene {

namespace {

constexpr double kPi = 3.14159265358979323846;

double average(const glm::dvec3& v)
{
    return (v.x + v.y + v.z) / 3.0;
}

}  // namespace

// --- the kinds: where their lights come from and their power ------------------------------

// The classic file's point-light section.
void listPointLights(const Scene& scene, std::vector<Light>& lights)
{
    for (const PointLight& point : scene.pointLights) {
        Light light;
        light.kind = LightKind::Point;
        light.position = point.position;
        light.emission = point.intensity;
        lights.push_back(light);
    }
}

// 4 pi I: an isotropic point of intensity I.
double pointLightPower(const Light& light, const LightPowerContext&)
{
    return 4.0 * kPi * average(glm::dvec3(light.emission));
}

// Every emissive top-level sphere (scene/Scene.h).
void listSphereLights(const Scene& scene, std::vector<Light>& lights)
{
    for (const SphereLight& sphere : sphereLights(scene)) {
        Light light;
        light.kind = LightKind::Sphere;
        light.position = sphere.center;
        light.radius = sphere.radius;
        light.emission = sphere.radiance;
        light.object = sphere.object;
        lights.push_back(light);
    }
}

// 4 pi^2 r^2 L: radiance L leaving a sphere's area 4 pi r^2 into pi steradians of projected
// solid angle.
double sphereLightPower(const Light& light, const LightPowerContext&)
{
    const double radius = light.radius;
    return 4.0 * kPi * kPi * radius * radius * average(glm::dvec3(light.emission));
}

// An environment map is a light, sampled by its own distribution (render/EnvironmentMap.h);
// the other environments are found by the rays that escape only. A map may be left to the
// escaping rays too (Environment::importanceSampled), to measure what sampling it buys.
void listEnvironmentLights(const Scene& scene, std::vector<Light>& lights)
{
    const Environment& environment = scene.environment;
    if (environment.kind != EnvironmentKind::Map || !environment.importanceSampled)
        return;
    Light light;
    light.kind = LightKind::Environment;
    light.emission = glm::vec3(environment.intensity);
    lights.push_back(light);
}

// The power the scene's bounding disc intercepts: pi R^2 times the radiance integrated over
// all directions (PBRT 4e, section 12.5.2, ImageInfiniteLight::Phi).
double environmentLightPower(const Light& light, const LightPowerContext& context)
{
    const double radius = context.sceneRadius;
    return kPi * radius * radius *
           average(glm::dvec3(light.emission) * context.environmentIntegral);
}

// --- the table ---------------------------------------------------------------------------

const std::vector<LightDescription>& lightDescriptions()
{
    static const std::vector<LightDescription> descriptions = [] {
        std::vector<LightDescription> list;
#define SCENE_LIGHT_DESCRIPTION(kind, name, featureSwitch, glslPrefix, emitter, lister, power)     \
    list.push_back({LightKind::kind, static_cast<int>(list.size()), #kind, name, featureSwitch,    \
                    glslPrefix, emitter, lister, power});
        SCENE_LIGHTS(SCENE_LIGHT_DESCRIPTION)
#undef SCENE_LIGHT_DESCRIPTION
        return list;
    }();
    return descriptions;
}

const LightDescription& describe(LightKind kind)
{
    return lightDescriptions()[static_cast<std::size_t>(kind)];
}

std::string codeName(const LightDescription& description)
{
    return codeName("LIGHT_", description.identifier);
}

std::vector<Light> sceneLights(const Scene& scene)
{
    std::vector<Light> lights;
    for (const LightDescription& description : lightDescriptions())
        description.list(scene, lights);
    return lights;
}

std::vector<double> lightPowers(const std::vector<Light>& lights, const LightPowerContext& context)
{
    std::vector<double> powers;
    for (const Light& light : lights)
        powers.push_back(describe(light.kind).power(light, context));
    return powers;
}

bool emitsLight(const Scene& scene)
{
    auto bright = [](const glm::vec3& value) {
        return value.x > 0.0f || value.y > 0.0f || value.z > 0.0f;
    };
    for (const PointLight& point : scene.pointLights)
        if (bright(point.intensity))
            return true;
    for (const SphereLight& sphere : sphereLights(scene))
        if (bright(sphere.radiance))
            return true;
    switch (scene.environment.kind) {
    case EnvironmentKind::None:
        return false;
    case EnvironmentKind::Sky:
        return true;
    case EnvironmentKind::Constant:
        return bright(scene.environment.color);
    case EnvironmentKind::Map:
        return scene.environment.intensity > 0.0f;
    }
    return true;
}

}  // namespace scene
