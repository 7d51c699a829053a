// Lights: point lights and spherical area lights (emissive spheres), sampled for next-event
// estimation. One light is chosen per shading point with probability proportional to its
// power (the host computes the table once, not every pixel).

uniform int uUseMis;  // 1: combine light and BSDF sampling of sphere lights by MIS

vec3 lightPosition(int light) { return uLights[3 * light].xyz; }
float lightRadius(int light) { return uLights[3 * light].w; }
vec3 lightEmission(int light) { return uLights[3 * light + 1].rgb; }
float lightSelectionProbability(int light) { return uLights[3 * light + 1].w; }
bool isPointLight(int light) { return uLights[3 * light + 2].y < 0.0; }
int lightObject(int light) { return int(uLights[3 * light + 2].y); }

int selectLight(float u)
{
    for (int light = 0; light < LIGHT_COUNT - 1; ++light)
        if (u < uLights[3 * light + 2].x)
            return light;
    return LIGHT_COUNT - 1;
}

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

// Solid-angle density with which light sampling picks direction `direction` (known to hit
// the sphere) from p, selection included: what MIS weighs a BSDF-sampled hit against.
float sphereLightPdf(int light, vec3 p)
{
    float oneMinusCosThetaMax;
    if (!sphereLightCone(p, light, oneMinusCosThetaMax))
        return 0.0;
    return lightSelectionProbability(light) * uniformConePdf(oneMinusCosThetaMax);
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

// An object that refracts nothing: a dielectric of index exactly 1, between equal media.
// It has no interface, so light passes it unbent, tinted by its pigment.
bool isNullInterface(int object)
{
    ivec4 record = uObjects[object];
    vec4 finish = uFinishes[2 * record.y + 1];
    return int(finish.x) == MATERIAL_DIELECTRIC && finish.y == 1.0;
}

// The fraction of light that travels from `origin` along `direction` over `maxDistance`:
// zero when something blocks it, one when nothing does, the tint of any index-1 dielectric
// it passes through. When the segment ends on an object (a sphere light), pass its index as
// `target`: arriving within the tolerance of the target counts as reaching it. (Marching on
// to the target's surface itself would crawl for ever on rays that meet it at grazing
// angles, and be taken for occlusion.) A spent step budget counts as blocked, as a
// spent budget counts as a hit for camera and path rays.
vec3 shadowTransmittance(vec3 origin, vec3 direction, float maxDistance, float insideSign,
                         float tolerance, int target)
{
    vec3 transmittance = vec3(1.0);
    RayCulling culling = sceneRayCulling(origin, direction, tolerance, 0.0);
    float clearDistance = min(maxDistance, culling.escapeDistance);
    float t = 0.0;
    for (int step = 0; step < uMaxMarchSteps; ++step) {
        if (t >= clearDistance)
            return transmittance;
        vec3 p = origin + t * direction;
        float radius = insideSign * sceneDistanceCulled(p, culling.mask);
        if (radius < tolerance) {
#if HAS_NULL_INTERFACES || HAS_SPHERE_LIGHTS
            int nearest;
            sceneDistanceAndObjectCulled(p, culling.mask, nearest);
            if (nearest == target)
                return transmittance;
#endif
#if HAS_NULL_INTERFACES
            if (nearest >= 0 && isNullInterface(nearest)) {
                transmittance *= pigmentColor(uObjects[nearest].x, p, -direction, 0.0, tolerance);
                // Step through the surface; where the step only grazed it, the march goes
                // on from outside and crosses further along.
                t += 2.0 * tolerance;
                insideSign = sceneDistance(origin + t * direction) < 0.0 ? -1.0 : 1.0;
                continue;
            }
#endif
            return vec3(0.0);
        }
        t += radius * uStepScale;
    }
    return vec3(0.0);
}

// Next-event estimation at a non-delta surface: radiance arriving from one chosen light
// through `wo`'s side, times the BSDF and cosine, divided by the sampling densities.
// `insideSign` is the side of the solid the incoming ray travelled in.
vec3 directLighting(Surface s, vec3 wo, float tolerance, float insideSign)
{
#if LIGHT_COUNT == 0
    return vec3(0.0);
#else
    int light = selectLight(random01());
    float selection = lightSelectionProbability(light);
    if (!(selection > 0.0))
        return vec3(0.0);
    // Geometry is measured from the surface point; only the shadow ray starts off the
    // surface, far enough not to hit it again.
    vec3 p = s.position;
    float offset = 2.0 * tolerance;
    vec3 shadowOrigin = p + s.facingNormal * offset;

#if HAS_POINT_LIGHTS
    if (isPointLight(light)) {
        vec3 toLight = lightPosition(light) - p;
        float distance = length(toLight);
        vec3 wi = toLight / distance;
        float cosI = dot(s.facingNormal, wi);
        if (cosI <= 0.0 || distance <= offset)
            return vec3(0.0);
        vec3 f = bsdfEvaluate(s, wo, wi);
        if (maxComponent(f) <= 0.0)
            return vec3(0.0);
        vec3 transmittance =
            shadowTransmittance(shadowOrigin, wi, distance - offset, insideSign, tolerance, -1);
        return f * cosI * transmittance * lightEmission(light) /
               (distance * distance * selection);
    }
#endif

#if HAS_SPHERE_LIGHTS
    float oneMinusCosThetaMax;
    if (!sphereLightCone(p, light, oneMinusCosThetaMax))
        return vec3(0.0);
    vec3 axis = normalize(lightPosition(light) - p);
    vec3 wi = basisAround(axis) * sampleUniformCone(random2(), oneMinusCosThetaMax);
    float cosI = dot(s.facingNormal, wi);
    if (cosI <= 0.0)
        return vec3(0.0);
    vec3 f = bsdfEvaluate(s, wo, wi);
    if (maxComponent(f) <= 0.0)
        return vec3(0.0);
    float distance = distanceToSphereLight(p, wi, light);
    vec3 transmittance = shadowTransmittance(shadowOrigin, wi, distance, insideSign, tolerance,
                                             lightObject(light));
    if (maxComponent(transmittance) <= 0.0)
        return vec3(0.0);
    float lightPdf = selection * uniformConePdf(oneMinusCosThetaMax);
    float weight = uUseMis != 0 ? powerHeuristic(lightPdf, bsdfPdf(s, wo, wi)) : 1.0;
    return f * cosI * transmittance * lightEmission(light) * (weight / lightPdf);
#else
    return vec3(0.0);
#endif
#endif
}
