#pragma once
// The light kinds, each described once in SCENE_LIGHTS: its name, the #define that compiles it
// into a shader, the prefix of its GLSL functions, what kind of emitter it is, where a scene's
// lights of the kind come from and how bright each one is. The enum, the shaders' codes
// (LIGHT_<KIND>, as generated #defines), the feature switches, the list of a scene's lights
// (sceneLights: the shaders' light records, in table order), the shaders' dispatchers over
// lights (render/KindDispatchers.cpp) and the names in `--features` all come from this list.
// The shaders tell a light's kind by its code in its record, never by its place in the list.
//
// Adding a light kind: a row here, its lister and power below it in Lights.cpp, and its
// functions in shaders/modules/lights.glsl: <prefix>Sample, and for a kind that is not a
// delta <prefix>Pdf, with the signatures the others have. (A kind written with words of its
// own in a scene file also needs them in the scene model and the parser.)
// tests/scene/KindTablesTest.cpp walks every row.
#include "scene/Scene.h"

#include <glm/glm.hpp>

#include <string>
#include <vector>

namespace scene {

struct Light;
struct LightPowerContext;
using LightLister = void (*)(const Scene& scene, std::vector<Light>& lights);
using LightPower = double (*)(const Light& light, const LightPowerContext& context);

void listPointLights(const Scene& scene, std::vector<Light>& lights);
void listSphereLights(const Scene& scene, std::vector<Light>& lights);
void listEnvironmentLights(const Scene& scene, std::vector<Light>& lights);
double pointLightPower(const Light& light, const LightPowerContext& context);
double sphereLightPower(const Light& light, const LightPowerContext& context);
double environmentLightPower(const Light& light, const LightPowerContext& context);

//  X(kind, name, feature switch, GLSL prefix, emitter, lister, power), in code order
#define SCENE_LIGHTS(X)                                                                            \
    X(Point, "point", "HAS_POINT_LIGHTS", "pointLight", Emitter::DeltaPosition, listPointLights,   \
      pointLightPower)                                                                             \
    X(Sphere, "sphere", "HAS_SPHERE_LIGHTS", "sphereLight", Emitter::Surface, listSphereLights,    \
      sphereLightPower)                                                                            \
    X(Environment, "environment", "HAS_ENVIRONMENT_LIGHT", "environmentLight", Emitter::Infinite,  \
      listEnvironmentLights, environmentLightPower)

// Where the light comes from, which says how rays meet it (Mitsuba 3's emitter flags name the
// same distinctions).
enum class Emitter {
    // A point: light from one direction only at each shading point, which no BSDF-sampled
    // ray can meet. It has no density, and multiple importance sampling leaves it out.
    DeltaPosition,
    // The surface of an object of the scene (the object's index is in its record): rays that
    // hit the object meet it.
    Surface,
    // Infinitely far: rays that leave the scene meet it. Shadow rays towards it run to the
    // scene's end.
    Infinite,
};

enum class LightKind {
#define SCENE_LIGHT_ENUMERATOR(kind, ...) kind,
    SCENE_LIGHTS(SCENE_LIGHT_ENUMERATOR)
#undef SCENE_LIGHT_ENUMERATOR
};

// One light of the scene, whatever its kind: what its record in the shaders holds.
struct Light {
    LightKind kind = LightKind::Point;
    glm::vec3 position{0.0f};  // a point light's position, a sphere light's centre
    float radius = 0.0f;       // a sphere light's
    // A point light's intensity I (W/sr), a sphere light's radiance; an environment light's
    // intensity scale, in each channel (its radiance is the map's, times that).
    glm::vec3 emission{0.0f};
    int object = -1;  // the object that is the light (Emitter::Surface), else -1
};

// What a light's power may depend on beyond its record.
struct LightPowerContext {
    double sceneRadius = 1.0;  // the bounding sphere's (scene/SceneBounds.h)
    // The environment map's radiance integrated over the sphere of directions, per channel,
    // before its intensity scale (W/m^2 per channel); zero where the scene has no map.
    glm::dvec3 environmentIntegral{0.0};
};

struct LightDescription {
    LightKind kind;
    int code;                // its place in the list; the shaders' LIGHT_<IDENTIFIER>
    const char* identifier;  // the enumerator's name
    const char* name;
    const char* featureSwitch;  // 1 where the shader has the kind
    const char* glslPrefix;     // its functions <prefix>Sample and <prefix>Pdf
    Emitter emitter;
    LightLister list;  // appends the scene's lights of this kind, in the scene's order
    LightPower power;  // emitted power, by which next-event estimation chooses among lights
};

// Every light kind, in code order.
const std::vector<LightDescription>& lightDescriptions();
const LightDescription& describe(LightKind kind);
// The shaders' name for a light kind's code: LIGHT_ and the identifier in capitals.
std::string codeName(const LightDescription& description);

// Every light of the scene, kind by kind in table order (within a kind, in the scene's
// order): the shaders' light records.
std::vector<Light> sceneLights(const Scene& scene);

// Whether anything in the scene gives light: a point or sphere light that is not black, or an
// environment that is not (none, a black colour, a map at intensity 0). A scene that gives
// none renders black whatever the samples; the program warns before rendering it.
bool emitsLight(const Scene& scene);

// The emitted power of each light of `lights` (channels averaged), in double: the power of a
// bright, large sphere light (radiance near the float maximum) overflows float, and one
// infinite power would make every selection probability NaN.
std::vector<double> lightPowers(const std::vector<Light>& lights, const LightPowerContext& context);

}  // namespace scene
