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
    float marchStart;  // how far along the ray its march may begin (see cameraClearDistance)
};

// The most segments (traced rays) one path can take.
int maxSegmentsPerPath()
{
    return uMaxBounces + 1 + kMaxNullCrossings;
}

// Where the camera is: inside which solid (-1 outside every one). A ray inside a solid can
// only leave that solid: where another surface touches it (glass resting on a floor), a hit
// within the tolerance of both is the solid's.
int cameraContainingObject()
{
    int containing;
    return sceneDistanceAndObject(uCameraEye, containing) < 0.0 ? containing : -1;
}

// How far every camera ray through `pixel` travels before any surface comes within its hit
// tolerance: the pixel's rays fill a cone around the one through its centre, and that cone
// is marched once (cone marching, as in Amanatides, "Ray tracing with cones", 1984) so that
// each of the pixel's paths starts its camera ray there instead of at the eye. A step from
// t may advance by as much as leaves every point of the cone up to t + step farther from the
// nearest surface than its tolerance: for a distance d at the cone's axis, a cone whose
// rays stray at most `spread` per unit from the axis and tolerances growing by `growth`,
// that is (d - tolerance0 - (spread + growth) t) / (1 + spread + growth). The same cone
// bounds the culling (ray_culling.glsl takes the cone's spread as growth of tolerance).
float cameraClearDistance(ivec2 pixel)
{
    vec3 axis = cameraRayDirection(vec2(pixel) + 0.5);
    // Every ray through the pixel lies within half the pixel's diagonal of the axis; a pixel
    // subtends the largest angle at the centre of the image.
    float growth = (0.7072 + uHitTolerance) * cameraPixelSpread();
    float tolerance0 = uMinimumHitDistance;
    RayCulling culling = sceneRayCulling(uCameraEye, axis, tolerance0, growth);
    float limit = min(uFarDistance, culling.escapeDistance);
    const int kConeSteps = 64;
    float t = 0.0;
    for (int step = 0; step < kConeSteps && t < limit; ++step) {
        float clearance = sceneDistanceCulled(uCameraEye + t * axis, culling.mask) -
                          tolerance0 - growth * t;
        float advance = 0.9 * uStepScale * clearance / (1.0 + growth);
        // Near a surface the steps shrink geometrically; the camera rays' own marches,
        // each from here, finish the approach.
        if (advance < tolerance0 + growth * t)
            break;
        t += advance;
    }
    return min(t, limit);
}

// `cameraClear`: where the camera ray's march may begin (cameraClearDistance, 0 from inside).
PathState startPath(vec2 filmPoint, int cameraContaining, float cameraClear)
{
    PathState path;
    path.origin = uCameraEye;
    path.direction = cameraRayDirection(filmPoint);
    path.cone = RayCone(0.0, cameraPixelSpread());
    path.containing = cameraContaining;
    path.insideSign = cameraContaining >= 0 ? -1.0 : 1.0;
    path.throughput = vec3(1.0);
    path.radianceScale = 1.0;
    path.radiance = vec3(0.0);
    path.previousWasDelta = true;  // the camera ray: emission seen directly counts in full
    path.previousPdf = 0.0;
    path.previousPosition = path.origin;
    path.scattering = 0;
    path.nullCrossings = 0;
    path.marchStart = cameraClear;
    return path;
}

// Traces the path's next ray and scatters at what it hits. Returns false once the path has
// ended, its radiance then final.
bool continuePath(inout PathState path)
{
    MarchHit hit = sphereTrace(path.origin, path.direction, path.insideSign, path.cone,
                               path.marchStart);
    path.marchStart = 0.0;
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
    // The march stopped within `tolerance` of the surface. What the pixel sees, though, is
    // where its ray meets the surface: rays of the pixel's own cone (camera rays and specular
    // chains) are first moved along the ray onto it (see intersectAlongRay; without it a lit
    // plane comes out about 1 % too bright, a floor seen at grazing angles shows its pattern
    // displaced towards the camera, and a convex mirror, whose reflected directions follow the
    // point, reflects the wrong part of the room near its rim). Elsewhere, and where that
    // does not converge, the point is projected along the normal, which lands on the surface
    // within the tolerance, safely. The normal is taken at the final point: decisions such as
    // which side the ray came from are ill-conditioned at grazing incidence and must match it.
    vec3 p = marched;
    bool onSurface = path.cone.spread > 0.0 &&
                     intersectAlongRay(p, direction, hit.sceneDistance, insideSign, hit.approach,
                                       tolerance);
    vec3 normal = sceneNormal(p, tolerance, insideSign);
    if (normal == vec3(0.0))
        normal = -direction;
    if (!onSurface)
        p -= normal * hit.sceneDistance;
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
