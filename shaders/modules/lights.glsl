// Lights: point lights and spherical area lights (emissive spheres), sampled for next-event
// estimation. One light is chosen per shading point with probability proportional to its
// power (the host computes the table once, not every pixel). Whether the light is seen is
// the geometry's business (shadowTransmittance, ray_queries.glsl).

int selectLight(float u)
{
    for (int light = 0; light < LIGHT_COUNT - 1 && loopIterationAllowed(); ++light)
        if (u < lightCumulativeProbability(light))
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

// Next-event estimation at a non-delta surface: radiance arriving from one chosen light
// through `wo`'s side, times the BSDF and cosine, divided by the sampling densities.
// `insideSign` is the side of the solid the incoming ray travelled in. `uSelection` picks the
// light, `uPoint` the direction towards it (uniform on [0, 1), from the sampler).
// Each kind of light only chooses the direction, the distance and what arrives; the BSDF and
// the shadow ray are written once for both: llvmpipe executes both sides of every branch, so
// a shadow march per kind would be paid twice in scenes with both kinds.
vec3 directLighting(Surface s, vec3 wo, float tolerance, float insideSign, float uSelection,
                    vec2 uPoint)
{
#if LIGHT_COUNT == 0
    return vec3(0.0);
#else
    int light = selectLight(uSelection);
    float selection = lightSelectionProbability(light);
    if (!(selection > 0.0))
        return vec3(0.0);
    // Geometry is measured from the surface point; only the shadow ray starts off the
    // surface (shadowTransmittance), far enough not to hit it again.
    vec3 p = s.position;
    vec3 wi = s.facingNormal;
    float distance = 0.0;
    int target = -1;
    // What arrives along wi, over the density of choosing it (solid angle for sphere lights;
    // point lights are a delta, their 1 / distance^2 in its place).
    vec3 arriving = vec3(0.0);
    // Solid-angle density of light sampling, for MIS; 0 for point lights (no BSDF sample
    // can reach them).
    float lightPdf = 0.0;
#if HAS_POINT_LIGHTS
    if (isPointLight(light)) {
        vec3 toLight = lightPosition(light) - p;
        distance = length(toLight);
        wi = toLight / distance;
        arriving = lightEmission(light) / (distance * distance * selection);
    }
#endif
#if HAS_SPHERE_LIGHTS
#if HAS_POINT_LIGHTS
    else
#endif
    {
        float oneMinusCosThetaMax;
        if (!sphereLightCone(p, light, oneMinusCosThetaMax))
            return vec3(0.0);
        vec3 axis = normalize(lightPosition(light) - p);
        wi = basisAround(axis) * sampleUniformCone(uPoint, oneMinusCosThetaMax);
        distance = distanceToSphereLight(p, wi, light);
        target = lightObject(light);
        lightPdf = selection * uniformConePdf(oneMinusCosThetaMax);
        arriving = lightEmission(light) / lightPdf;
    }
#endif
    float cosI = dot(s.facingNormal, wi);
    if (cosI <= 0.0)
        return vec3(0.0);
    vec3 f = bsdfEvaluate(s, wo, wi);
    if (maxComponent(f) <= 0.0)
        return vec3(0.0);
    vec3 transmittance = shadowTransmittance(s, wi, distance, insideSign, tolerance, target);
    if (maxComponent(transmittance) <= 0.0)
        return vec3(0.0);
    float weight = lightPdf > 0.0 && gMultipleImportanceSampling ? powerHeuristic(lightPdf, bsdfPdf(s, wo, wi))
                                                  : 1.0;
    return f * cosI * transmittance * arriving * weight;
#endif
}
