// Next-event estimation at a non-delta surface: radiance arriving from one chosen light
// through `wo`'s side, times the BSDF and cosine, divided by the sampling densities, and
// weighted by multiple importance sampling (Veach 1997, power heuristic) against the BSDF
// sampling that may find the same light (integrator.glsl). `insideSign` is the side of the
// solid the incoming ray travelled in. `uSelection` picks the light, `uPoint` the direction
// towards it (uniform on [0, 1), from the sampler).
// Each kind of light only chooses the direction, the distance and what arrives (lightSample,
// generated over the kinds of lights.glsl); the BSDF and the shadow ray are written once for
// all: llvmpipe executes both sides of every branch, so a shadow march per kind would be paid
// once for each kind in scenes with several.
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
    LightSample chosen;
    if (!lightSample(light, s.position, uPoint, selection, chosen))
        return vec3(0.0);
    // Read into variables of their own, not used as the struct's fields below: so the
    // compiler makes the same instructions as it did before the kinds were dispatched, and
    // the images stay the same bit for bit (fields used in place gave 1-ulp differences).
    vec3 wi = chosen.direction;
    float distance = chosen.distance;
    int target = chosen.target;
    float lightPdf = chosen.pdf;
    vec3 arriving = chosen.arriving;
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
