// The path tracer: one path per call, an unbiased estimate of the radiance through a pixel
// (Kajiya 1986), with next-event estimation for point and sphere lights and multiple
// importance sampling (Veach 1997, power heuristic) between light and BSDF sampling of
// sphere lights, so that no light is counted twice.

uniform int uMaxBounces;          // scattering events after the camera ray (the seed: 16)
uniform int uRussianRouletteDepth;  // scattering events that roulette never ends (the seed: 4)

// Smallest cosine between wo and the facing normal (see Surface.facingNormal).
const float kMinimumViewCosine = 1e-4;

Surface surfaceAt(int object, vec3 p, vec3 normal, vec3 wo, float insideSign, float footprint,
                  float tolerance)
{
    ivec4 record = uObjects[object];
    vec4 finishA = uFinishes[2 * record.y];
    vec4 finishB = uFinishes[2 * record.y + 1];
    Surface s;
    s.position = p;
    s.normal = normal;
    s.entering = insideSign > 0.0;
    vec3 facing = insideSign * normal;
    float cosView = dot(facing, wo);
    if (cosView < kMinimumViewCosine)
        facing = normalize(facing + (kMinimumViewCosine - cosView) * wo);
    s.facingNormal = facing;
    s.color = pigmentColor(record.x, p, normal, footprint, tolerance);
    s.emission = finishA.rgb;
    s.phongExponent = finishA.w;
    s.material = int(finishB.x);
    s.ior = finishB.y;
    s.lightIndex = record.z;
    return s;
}

vec3 tracePath(vec2 filmPoint)
{
    vec3 origin = uCameraEye;
    vec3 direction = cameraRayDirection(filmPoint);
    RayCone cone = RayCone(0.0, cameraPixelSpread());
    float insideSign = sceneDistance(origin) < 0.0 ? -1.0 : 1.0;

    vec3 radiance = vec3(0.0);
    vec3 throughput = vec3(1.0);
    bool previousWasDelta = true;  // the camera ray: emission seen directly counts in full
    float previousPdf = 0.0;
    vec3 previousPosition = origin;

    int scattering = 0;
    int nullCrossings = 0;
    const int kMaxNullCrossings = 32;
    for (int segment = 0; segment <= uMaxBounces + kMaxNullCrossings; ++segment) {
        MarchHit hit = sphereTrace(origin, direction, insideSign, cone);
        if (!hit.found) {
            radiance += throughput * environmentRadiance(direction);
            break;
        }

        vec3 marched = origin + hit.t * direction;
        float footprint = coneFootprint(cone, hit.t);
        float tolerance = hitTolerance(cone, hit.t);
        vec3 normal = objectNormal(hit.object, marched, tolerance);
        if (normal == vec3(0.0))
            normal = -direction;
        // The march stopped within `tolerance` of the surface. One Newton step along the
        // ray (free: distance and normal are known) puts the point where this ray meets the
        // surface, exactly for planes; at grazing incidence, where that step is unstable, the
        // point is projected along the normal instead.
        float cosIncidence = abs(dot(direction, normal));
        vec3 p = abs(hit.sceneDistance) < 4.0 * tolerance * cosIncidence
                     ? marched + direction * (insideSign * hit.sceneDistance / cosIncidence)
                     : marched - normal * hit.sceneDistance;
        vec3 wo = -direction;
        Surface s = surfaceAt(hit.object, p, normal, wo, insideSign, footprint, tolerance);

#if HAS_SPHERE_LIGHTS
        // Emission, seen from outside the sphere.
        if (s.lightIndex >= 0 && s.entering) {
            float weight = 1.0;
            if (!previousWasDelta)
                weight = uUseMis != 0
                             ? powerHeuristic(previousPdf,
                                              sphereLightPdf(s.lightIndex, previousPosition))
                             : 0.0;
            radiance += throughput * s.emission * weight;
        }
#endif
#if HAS_NULL_INTERFACES
        if (isNullInterface(hit.object) && nullCrossings < kMaxNullCrossings) {
            // No interface, no scattering event: the ray goes on unbent, tinted.
            throughput *= s.color;
            ++nullCrossings;
            origin = p - s.facingNormal * (2.0 * tolerance);
            insideSign = sceneDistance(origin) < 0.0 ? -1.0 : 1.0;
            cone = RayCone(footprint, cone.spread);
            continue;
        }
#endif
        if (scattering == uMaxBounces)
            break;
        ++scattering;

        if (!isDeltaMaterial(s.material))
            radiance += throughput * directLighting(s, wo, tolerance, insideSign);

        BsdfSample scattered = bsdfSample(s, wo);
        if (!scattered.valid)
            break;
        throughput *= scattered.weight;
        previousWasDelta = scattered.isDelta;
        previousPdf = scattered.pdf;
        // Light sampling measured its cone from the surface point; MIS weighs the same pdfs.
        previousPosition = p;

        // Past the first scattering events, end dim paths at random and reweight the
        // survivors: unbiased, and no throughput clamp undoes it.
        if (scattering > uRussianRouletteDepth) {
            float survival = min(1.0, maxComponent(throughput));
            if (!(random01() < survival))
                break;
            throughput /= survival;
        }

        // Specular chains keep the pixel's cone; a diffuse or glossy bounce integrates
        // over directions, so its rays resolve the scene at this point's footprint.
        cone = RayCone(footprint, scattered.isDelta ? cone.spread : 0.0);
        float side = dot(scattered.direction, normal) >= 0.0 ? 1.0 : -1.0;
        origin = p + normal * (side * 2.0 * tolerance);
        direction = scattered.direction;
        insideSign = sceneDistance(origin) < 0.0 ? -1.0 : 1.0;
    }
    return radiance;
}
