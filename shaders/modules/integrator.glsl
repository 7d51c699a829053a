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

// Starts the next ray at surface point p, off the surface by twice the hit tolerance (so
// its march does not find p again), on the side `direction` leaves to, and updates
// `insideSign` for it. The offset is taken along the new direction, not along the normal:
// then the ray's line still passes through p, and a chain of specular bounces keeps its
// geometry (a normal offset shifts each reflected line by the offset, and light trapped
// by total internal reflection in a sphere drifts out after a few bounces). At grazing
// directions, where that would go far along the surface, part of the offset is along the
// normal instead.
// `facingNormal` points to the side the ray arrived from (Surface.facingNormal, which the
// BSDFs sampled against): a direction on that side stays in the region the ray travelled
// in, one on the other side crosses into the other region. The offset point can land
// beyond another surface, in a solid the ray never entered: near an edge or a corner (an
// offset from a room's wall, out through the next wall, would then see the sky), or along a
// grazing direction inside a concave surface. Then the offset is retried along the normal,
// once, and twice as far; failing that the path ends there.
// `containing` receives the object the new ray starts inside (-1 outside every object).
bool spawn(vec3 p, vec3 facingNormal, vec3 direction, float tolerance, inout float insideSign,
           out vec3 origin, out int containing)
{
    const float kMinimumCosine = 0.25;
    float cosLeaving = dot(direction, facingNormal);
    bool crosses = cosLeaving < 0.0;
    float side = crosses ? -1.0 : 1.0;
    float expectedSign = crosses ? -insideSign : insideSign;
    float clearance = 2.0 * tolerance;
    float along = clearance / max(abs(cosLeaving), kMinimumCosine);
    float normalPart = max(0.0, clearance - along * abs(cosLeaving));
    for (int attempt = 0; attempt < 3; ++attempt) {
        if (attempt == 0)
            origin = p + direction * along + facingNormal * (side * normalPart);
        else
            origin = p + facingNormal * (side * float(attempt) * clearance);
        if (expectedSign * sceneDistanceAndObject(origin, containing) > 0.0) {
            insideSign = expectedSign;
            if (insideSign > 0.0)
                containing = -1;
            return true;
        }
    }
    return false;
}

// Most paths carry no more than 16 crossings of index-1 dielectrics (see lights.glsl).
const int kMaxNullCrossings = 32;

// A path between segments: the ray about to be traced and what the path has gathered.
struct PathState {
    vec3 origin;
    vec3 direction;
    RayCone cone;
    float insideSign;  // -1 while the ray travels inside a solid
    int containing;    // the solid it travels in, or -1
    vec3 throughput;
    float radianceScale;  // product of the refractions' (eta_o / eta_i)^2
    vec3 radiance;
    bool previousWasDelta;
    float previousPdf;
    vec3 previousPosition;
    int scattering;
    int nullCrossings;
};

// The most segments (traced rays) one path can take.
int maxSegmentsPerPath()
{
    return uMaxBounces + 1 + kMaxNullCrossings;
}

PathState startPath(vec2 filmPoint)
{
    PathState path;
    path.origin = uCameraEye;
    path.direction = cameraRayDirection(filmPoint);
    path.cone = RayCone(0.0, cameraPixelSpread());
    // A ray inside a solid can only leave that solid: where another surface touches it
    // (glass resting on a floor), a hit within the tolerance of both is the solid's.
    path.insideSign = sceneDistanceAndObject(path.origin, path.containing) < 0.0 ? -1.0 : 1.0;
    if (path.insideSign > 0.0)
        path.containing = -1;
    path.throughput = vec3(1.0);
    path.radianceScale = 1.0;
    path.radiance = vec3(0.0);
    path.previousWasDelta = true;  // the camera ray: emission seen directly counts in full
    path.previousPdf = 0.0;
    path.previousPosition = path.origin;
    path.scattering = 0;
    path.nullCrossings = 0;
    return path;
}

// Traces the path's next ray and scatters at what it hits. Returns false once the path has
// ended, its radiance then final.
bool continuePath(inout PathState path)
{
    MarchHit hit = sphereTrace(path.origin, path.direction, path.insideSign, path.cone);
    if (!hit.found) {
        path.radiance += path.throughput * environmentRadiance(path.direction);
        return false;
    }
    if (path.containing >= 0)
        hit.object = path.containing;

    vec3 direction = path.direction;
    float insideSign = path.insideSign;
    vec3 marched = path.origin + hit.t * direction;
    float footprint = coneFootprint(path.cone, hit.t);
    float tolerance = hitTolerance(path.cone, hit.t);
    vec3 normal = sceneNormal(marched, tolerance, insideSign);
    if (normal == vec3(0.0))
        normal = -direction;
    // The march stopped within `tolerance` of the surface. Projected along the normal, the
    // point lands on the surface within that distance, safely. What the pixel sees, though,
    // is where its ray meets the surface: rays of the pixel's own cone (camera rays and
    // specular chains) take one Newton step along the ray (exact for planes; without it a
    // lit plane comes out about 1 % too bright), accepted only where it clearly brings the
    // point closer to the surface (not at grazing incidence on a curve, which the ray may
    // not meet at all, nor into another solid near an edge). The normal is then taken again
    // at the new point: decisions such as which side the ray came from are ill-conditioned
    // at grazing incidence and must match the point.
    vec3 p = marched - normal * hit.sceneDistance;
    float cosIncidence = abs(dot(direction, normal));
    if (path.cone.spread > 0.0 && abs(hit.sceneDistance) < 4.0 * tolerance * cosIncidence) {
        vec3 onRay = marched + direction * (insideSign * hit.sceneDistance / cosIncidence);
        if (abs(sceneDistance(onRay)) <= 0.5 * abs(hit.sceneDistance)) {
            vec3 normalOnRay = sceneNormal(onRay, tolerance, insideSign);
            if (normalOnRay != vec3(0.0)) {
                p = onRay;
                normal = normalOnRay;
            }
        }
    }
    vec3 wo = -direction;
    Surface s = surfaceAt(hit.object, p, normal, wo, insideSign, footprint, tolerance);

#if HAS_SPHERE_LIGHTS
    // Emission, seen from outside the sphere, only along rays that truly meet it: the march
    // accepts rays passing within the hit tolerance, which would widen every light by that
    // much (bright outlines), and light sampling never picks those directions either.
    if (s.lightIndex >= 0 && s.entering &&
        rayMeetsSphereLight(path.origin, path.direction, s.lightIndex)) {
        float weight = 1.0;
        if (!path.previousWasDelta)
            weight = uUseMis != 0
                         ? powerHeuristic(path.previousPdf,
                                          sphereLightPdf(s.lightIndex, path.previousPosition))
                         : 0.0;
        path.radiance += path.throughput * s.emission * weight;
    }
#endif
#if HAS_NULL_INTERFACES
    if (isNullInterface(hit.object) && path.nullCrossings < kMaxNullCrossings) {
        // No interface, no scattering event: the ray goes on unbent, tinted.
        path.throughput *= s.color;
        ++path.nullCrossings;
        path.cone = RayCone(footprint, path.cone.spread);
        return spawn(p, s.facingNormal, direction, tolerance, path.insideSign, path.origin,
                     path.containing);
    }
#endif
    if (path.scattering == uMaxBounces)
        return false;
    ++path.scattering;

    if (!isDeltaMaterial(s.material))
        path.radiance += path.throughput * directLighting(s, wo, tolerance, insideSign);

    BsdfSample scattered = bsdfSample(s, wo);
    if (!scattered.valid)
        return false;
    path.throughput *= scattered.weight;
    path.radianceScale *= scattered.radianceScale;
    path.previousWasDelta = scattered.isDelta;
    path.previousPdf = scattered.pdf;
    // Light sampling measured its cone from the surface point; MIS weighs the same pdfs.
    path.previousPosition = p;

    // Past the first scattering events, end dim paths at random and reweight the survivors:
    // unbiased, and no throughput clamp undoes it. Dimness is judged without the
    // refractions' radiance scaling, which leaving the medium undoes.
    if (path.scattering > uRussianRouletteDepth) {
        float survival = min(1.0, maxComponent(path.throughput) / path.radianceScale);
        if (!(random01() < survival))
            return false;
        path.throughput /= survival;
    }

    // Specular chains keep the pixel's cone; a diffuse or glossy bounce integrates over
    // directions, so its rays resolve the scene at this point's footprint.
    path.cone = RayCone(footprint, scattered.isDelta ? path.cone.spread : 0.0);
    path.direction = scattered.direction;
    return spawn(p, s.facingNormal, scattered.direction, tolerance, path.insideSign,
                 path.origin, path.containing);
}
