// Lights, sampled for next-event estimation. One light is chosen per shading point with
// probability proportional to its power (the host computes the table once, not every
// pixel); its kind (scene/Lights.h) then chooses a direction towards it. Each kind defines
// here <prefix>Sample (false where it has no sample to give), and where it is no delta
// <prefix>Pdf; the dispatchers over the kinds,
// lightSample and lightPdf, are generated from the table (render/KindDispatchers.cpp) and
// follow this module. Whether the light is seen is the geometry's business
// (shadowTransmittance, ray_queries.glsl).

// What light sampling chose at a shading point.
struct LightSample {
    vec3 direction;  // unit, from the shading point towards the light
    float distance;  // how far along it the light lies (FLOAT_MAX for a light at infinity)
    int target;      // the object the shadow ray ends on (a light that is an object), or -1
    // What arrives along `direction`, over the densities of choosing it (the light's
    // selection included): solid angle, or for a point light its 1 / distance^2 in its place.
    vec3 arriving;
    // The solid-angle density of choosing `direction`, selection included, which MIS weighs
    // against the BSDF's; 0 for a point light (no BSDF sample can reach it).
    float pdf;
};

int selectLight(float u)
{
    for (int light = 0; light < LIGHT_COUNT - 1 && loopIterationAllowed(); ++light)
        if (u < lightCumulativeProbability(light))
            return light;
    return LIGHT_COUNT - 1;
}

// --- point lights: a delta ------------------------------------------------------------------

#if HAS_POINT_LIGHTS
bool pointLightSample(int light, vec3 p, vec2 u, float selection, out LightSample chosen)
{
    vec3 toLight = lightPosition(light) - p;
    float distance = length(toLight);
    chosen = LightSample(toLight / distance, distance, -1,
                         lightEmission(light) / (distance * distance * selection), 0.0);
    return true;
}
#endif

// --- sphere lights: emissive spheres, sampled by the cone they subtend ----------------------

#if HAS_SPHERE_LIGHTS
// The cone a sphere subtends from p, as 1 - cos(thetaMax) computed as sin^2 / (1 + cos)
// without cancellation, so a sphere of radius 1e-4 at distance 100 keeps its solid angle.
// False when p is inside the sphere (it has no cone then).
bool sphereLightCone(vec3 p, int light, out float oneMinusCosThetaMax)
{
    vec3 toCenter = lightPosition(light) - p;
    float radius = lightRadius(light);
    float sin2ThetaMax = radius * radius / dot(toCenter, toCenter);
    oneMinusCosThetaMax = sin2ThetaMax / (1.0 + sqrt(max(0.0, 1.0 - sin2ThetaMax)));
    return sin2ThetaMax < 1.0 && oneMinusCosThetaMax > 0.0;
}

// True when the ray from `origin` along unit `direction` meets the light's sphere.
bool rayMeetsSphereLight(vec3 origin, vec3 direction, int light)
{
    vec3 toCenter = lightPosition(light) - origin;
    float along = dot(direction, toCenter);
    float radius = lightRadius(light);
    vec3 closest = toCenter - along * direction;
    return along > 0.0 && dot(closest, closest) <= radius * radius;
}

// Distance from p along unit `direction` to the near side of the light's sphere, in the form
// c / (b + sqrt(b^2 - c)) that keeps its digits for a far, tiny sphere.
float distanceToSphereLight(vec3 p, vec3 direction, int light)
{
    vec3 toCenter = lightPosition(light) - p;
    float radius = lightRadius(light);
    float b = dot(direction, toCenter);
    float c = dot(toCenter, toCenter) - radius * radius;
    float discriminant = max(b * b - c, 0.0);
    return c / (b + sqrt(discriminant));
}

bool sphereLightSample(int light, vec3 p, vec2 u, float selection, out LightSample chosen)
{
    float oneMinusCosThetaMax;
    if (!sphereLightCone(p, light, oneMinusCosThetaMax))
        return false;
    vec3 axis = normalize(lightPosition(light) - p);
    vec3 wi = basisAround(axis) * sampleUniformCone(u, oneMinusCosThetaMax);
    float pdf = selection * uniformConePdf(oneMinusCosThetaMax);
    chosen = LightSample(wi, distanceToSphereLight(p, wi, light), lightObject(light),
                         lightEmission(light) / pdf, pdf);
    return true;
}

// The solid-angle density with which sphereLightSample picks `direction` (known to meet the
// sphere) from p, before selection.
float sphereLightPdf(int light, vec3 p, vec3 direction)
{
    float oneMinusCosThetaMax;
    if (!sphereLightCone(p, light, oneMinusCosThetaMax))
        return 0.0;
    return uniformConePdf(oneMinusCosThetaMax);
}
#endif

// --- the environment map: sampled by its own distribution (environment.glsl) ---------------

#if HAS_ENVIRONMENT_LIGHT
// Towards the map's brighter texels (sampleEnvironmentMap); none where the direction chosen
// brings nothing (a texel the filter only borders on, or the environment switched off).
bool environmentLightSample(int light, vec3 p, vec2 u, float selection, out LightSample chosen)
{
    EnvironmentMapSample map = sampleEnvironmentMap(u);
    vec3 radiance = environmentRadiance(map.direction);
    if (!(map.pdf > 0.0) || maxComponent(radiance) <= 0.0)
        return false;
    float pdf = selection * map.pdf;
    chosen = LightSample(map.direction, FLOAT_MAX, -1, radiance / pdf, pdf);
    return true;
}

float environmentLightPdf(int light, vec3 p, vec3 direction)
{
    return environmentMapPdf(direction);
}
#endif
