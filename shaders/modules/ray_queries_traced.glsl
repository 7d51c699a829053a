// The geometry's answers (ray_queries.glsl) by sphere tracing the scene's distance functions
// (sphere_tracing.glsl): surfaces are found within the hit tolerance of the ray's cone,
// rays leave surfaces offset by a few tolerances, and shadow rays march to their light.

// A march stops within the hit tolerance of a surface; a ray that stops there has met the
// surface only if it truly crosses it: the stop is moved along the ray onto the surface
// (intersectAlongRay), and where that does not converge the ray is passing a silhouette, an
// edge or the rim of a contact within the tolerance without meeting it. Such a near miss is
// not a hit: the march goes on past it, accepting surfaces only within a quarter of the
// tolerance, and so on up to kNearMissRetries times (1/64 of the tolerance), after which the
// closest approach is taken (its pixel's cone overlaps the surface anyway). Treating near
// misses as hits dilates every silhouette and occluder by the tolerance: a band of
// mis-shaded pixels around each object and each contact, which no sample count removes
// (docs/ACCURACY.md measures it against exact intersection).
const int kNearMissRetries = 3;
const float kNearMissToleranceScale = 0.25;

// Normals at points that are on the surface take their differences this fraction of the
// tolerance apart: near an edge (a box's rim, two objects that touch) the taps of a wider
// stencil reach the other surface and tilt the normal. Off the surface (an accepted near
// miss) the stencil must span the tolerance.
const float kOnSurfaceNormalStep = 0.25;

#if HAS_SPHERE_LIGHTS
// The nearest sphere light that rays leave out of their marches (ray_queries.glsl) which
// the ray crosses beyond `start`, and where; -1 for none. Sphere lights are met exactly, so
// a ray passing the rim of a light within the tolerance sees what lies behind it (marched,
// it would stop at the light without meeting it and see neither).
int nearestExcludedSphereLight(vec3 origin, vec3 direction, float start, out float t)
{
    int nearest = -1;
    t = FLOAT_MAX;
    for (int light = 0; light < LIGHT_COUNT && loopIterationAllowed(); ++light) {
        if (lightCullingBit(light) == 0u)  // no sphere, or one that is marched
            continue;
        float crossing =
            raySphereCrossing(origin, direction, lightPosition(light), lightRadius(light), start);
        if (crossing < t) {
            t = crossing;
            nearest = light;
        }
    }
    return nearest;
}
#endif

#if HAS_MARCHED_OBJECTS
// Marches from `start` to `end` to the first stop within the tolerance where the ray truly
// meets a surface: the stop is moved along the ray onto it (intersectAlongRay), and past a
// near miss the march goes on with a smaller tolerance, up to kNearMissRetries times. `p`
// receives the last stop, on the surface where `onSurface`.
MarchHit marchToSurface(vec3 origin, vec3 direction, float insideSign, RayCone cone,
                        RayCulling culling, float start, float end, out vec3 p,
                        out bool onSurface)
{
    int stepsLeft = start < end ? gMaxMarchSteps : 0;
    float toleranceScale = 1.0;
    float from = start;
    MarchHit hit = marchMiss(0.0);
    onSurface = false;
    for (int attempt = 0; attempt <= kNearMissRetries; ++attempt) {
        hit = sphereTrace(origin, direction, insideSign, cone, toleranceScale, culling, from,
                          end, stepsLeft);
        if (!hit.found)
            break;
        p = origin + hit.t * direction;
        onSurface = intersectAlongRay(p, direction, hit.sceneDistance, insideSign, hit.approach,
                                      hit.tolerance, culling.mask);
        if (onSurface || hit.budgetSpent)
            break;
        from = hit.t;
        toleranceScale *= kNearMissToleranceScale;
    }
    return hit;
}

#ifdef MARCHES_OBJECT_BY_OBJECT
// The general shader's march (shape_interpreter.glsl): the marched objects of `mask` one at a
// time, front to back in the order the ray comes near their bounds (nextMarchedObject), each
// marched as marchToSurface marches, through its own distance only and only along its own
// stretch of the ray, until no object begins before the nearest hit so far. A ray inside a
// marched solid (`containing`) can only leave it: that object alone is marched. On return
// gMarchedObject is the hit's object, whose distance the normal is taken from.
MarchHit marchObjectByObject(vec3 origin, vec3 direction, float insideSign, RayCone cone,
                             uint mask, float start, float end, int containing, out vec3 p,
                             out bool onSurface)
{
    MarchHit nearest = marchMiss(end);
    p = origin;
    onSurface = false;
    float tolerance0 = hitTolerance(cone, 0.0);
    float growth = gHitTolerance * cone.spread;
    bool inside = insideSign < 0.0 && containing >= 0;
    float afterT = -FLOAT_MAX;
    int afterObject = -1;
    for (int round = 0; loopIterationAllowed(); ++round) {
        float reach = nearest.found ? nearest.t : end;
        vec2 stretch = vec2(start, reach);
        int object = inside ? (round == 0 ? containing : -1)
                            : nextMarchedObject(origin, direction, tolerance0, growth, mask,
                                                start, reach, afterT, afterObject, stretch);
        if (object < 0)
            break;
        afterT = stretch.x;
        afterObject = object;
        gMarchedObject = object;
        vec3 stop;
        bool stopOnSurface;
        MarchHit hit = marchToSurface(origin, direction, insideSign, cone,
                                      RayCulling(0xffffffffu, stretch.y, stretch.x), start,
                                      reach, stop, stopOnSurface);
        if (hit.found && (!nearest.found || hit.t < nearest.t)) {
            nearest = hit;
            p = stop;
            onSurface = stopOnSurface;
        }
    }
    gMarchedObject = nearest.object;
    return nearest;
}
#endif

// The surface a march found (hit.found), at its stop `p`: the object whose surface the
// point is on, and the normal there. Where the stop is not on the surface even after the
// near-miss retries, it is projected along the normal, which lands on the surface within the
// tolerance, safely.
SurfaceHit marchedSurface(MarchHit hit, vec3 p, bool onSurface, vec3 origin, vec3 direction,
                          float insideSign, RayCone cone, int containing)
{
    SurfaceHit surface;
    surface.found = true;
    surface.t = hit.t;
    surface.footprint = coneFootprint(cone, hit.t);
    surface.tolerance = hitTolerance(cone, hit.t);
    int object = hit.object;
#if HAS_MARCHED_UNION
    if (onSurface) {
        // Where two objects come within the tolerance of each other (a contact), the
        // march's nearest object at the stop may be the other one. (Only marched objects:
        // the march met none of those met exactly; with one marched surface it is that one.)
        sceneDistanceAndObjectCulled(p, 0xffffffffu, object);
        COUNT_WORK(workEvaluations, 1);
    }
#endif
    // On the surface, with the on-surface step; off it, or on a surface of zero thickness,
    // at the march's stop, which lies on the side the ray came from.
    vec3 normal = sceneNormal(p, kOnSurfaceNormalStep * surface.tolerance, onSurface,
                              origin + hit.t * direction, surface.tolerance, insideSign);
    if (normal == vec3(0.0))
        normal = -direction;
    if (!onSurface)
        p -= normal * hit.sceneDistance;
    surface.object = containing >= 0 ? containing : object;
    surface.position = p;
    surface.normal = normal;
    return surface;
}
#endif

// The surface of an exact crossing, or none.
SurfaceHit exactSurface(ExactHit exact, vec3 origin, vec3 direction, RayCone cone)
{
    if (exact.object < 0)
        return noSurfaceHit();
    SurfaceHit surface;
    surface.found = true;
    surface.object = exact.object;
    surface.t = exact.t;
    surface.position = origin + exact.t * direction;
    surface.normal = exact.normal;
    surface.footprint = coneFootprint(cone, exact.t);
    surface.tolerance = hitTolerance(cone, exact.t);
    return surface;
}

// The first surface along the ray. What the pixel sees is where its ray meets the surface:
// stops are moved along the ray onto it (see intersectAlongRay; without it a lit plane comes
// out about 1 % too bright, a floor seen at grazing angles shows its pattern displaced
// towards the camera, and a convex mirror, whose reflected directions follow the point,
// reflects the wrong part of the room near its rim), and the object is the one whose
// surface the point is on (marchToSurface, marchedSurface). The normal is taken at the final
// point: decisions such as which side the ray came from are ill-conditioned at grazing
// incidence and must match it.
SurfaceHit findSurface(vec3 origin, vec3 direction, float insideSign, RayCone cone,
                       float start, int containing)
{
    // Top-level shapes with a closed form (polyhedra, spheres, boxes, cylinders, disks, cones)
    // are met exactly (the culled distances the march evaluates leave them out): the march
    // ends where the ray crosses one. A ray inside a solid can only leave
    // it: inside one met exactly, its exit is the answer and nothing is marched; inside a
    // marched one, no exact crossing counts. `start` only says where marched objects may begin
    // (the camera's cone march leaves the exact ones out too): an exact one may be crossed
    // before it. Planes are met however far away (the far distance only bounds what is
    // marched): a floor reaches the horizon.
    ExactHit exact = ExactHit(FLOAT_MAX, -1, vec3(0.0));
    exactSurfacesIntersect(origin, direction, 0.0, containing, exact);
#if HAS_MARCHED_OBJECTS
    RayCulling culling = rayCulling(origin, direction, cone);
    float end = min(gFarDistance, exact.t);
    if (containing >= 0 && exact.object == containing)
        end = min(end, start);
#endif
#if HAS_SPHERE_LIGHTS
    int light = -1;
    float lightT = FLOAT_MAX;
    if (insideSign > 0.0) {
        light = nearestExcludedSphereLight(origin, direction, start, lightT);
#if HAS_MARCHED_OBJECTS
        culling.mask &= ~gSphereLightPieces;
        end = min(end, lightT);
#endif
    }
#endif
#if HAS_MARCHED_OBJECTS
    // A ray that came near nothing but lights has nothing to march (its culling distance
    // still reaches past the lights): with no piece left the distance is FLOAT_MAX, and a
    // relaxed step of it overflows, after which the march would spin through its whole
    // budget on NaN.
    if (culling.mask == 0u)
        end = min(end, start);
    vec3 p;
    bool onSurface;
#ifdef MARCHES_OBJECT_BY_OBJECT
    MarchHit hit = marchObjectByObject(origin, direction, insideSign, cone, culling.mask, start,
                                       end, containing, p, onSurface);
#else
    MarchHit hit =
        marchToSurface(origin, direction, insideSign, cone, culling, start, end, p, onSurface);
#endif
    if (hit.found)
        return marchedSurface(hit, p, onSurface, origin, direction, insideSign, cone,
                              containing);
#endif
    // Nothing marched before the nearest exact crossing, if any.
#if HAS_SPHERE_LIGHTS
    if (light >= 0 && lightT < exact.t)
        exact = ExactHit(lightT, lightObject(light),
                         normalize(origin + lightT * direction - lightPosition(light)));
#endif
    return exactSurface(exact, origin, direction, cone);
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
// beyond another surface, in a solid the ray never entered: in the crease where a solid
// stands on a floor or touches a wall, near an edge or a corner of a room, or along a
// grazing direction inside a concave surface. Then the offset is taken again, shorter
// (kOffsetShrinks times, by kOffsetShrink each): in an acute crease (a ball or a rounded
// solid resting on the floor) the gap narrows below two tolerances over most of a pixel,
// and every path from there used to end or start on the wrong side: the crease's line came
// out 14 % too dark (tests/render/EdgeBiasTest.cpp). A ray that starts nearer its surface
// than the tolerance stops at once and is marched on as a near miss (findSurface). Failing
// all of those the offset is retried along the normal, once, and twice as far; failing
// that the path ends there.
// `containing` receives the object the new ray starts inside (-1 outside every object);
// its march starts at its origin.
const float kMinimumSpawnCosine = 0.0625;
const int kMaxShadowCrossings = 32;
const int kOffsetShrinks = 3;
const float kOffsetShrink = 0.25;

// The point `clearance` off the surface at p (normal n, towards the side the ray leaves
// to) along unit `direction`, whose cosine with n is `cosLeaving` (>= 0): along the
// direction, but for grazing directions partly along the normal. `along` receives how far
// along the direction it lies.
vec3 offsetAlongRay(vec3 p, vec3 n, vec3 direction, float cosLeaving, float clearance,
                    out float along)
{
    along = clearance / max(cosLeaving, kMinimumSpawnCosine);
    float normalPart = max(0.0, clearance - along * cosLeaving);
    return p + direction * along + n * normalPart;
}

bool spawn(vec3 p, vec3 facingNormal, vec3 direction, float tolerance, int object,
           inout float insideSign, out vec3 origin, out float start, out int containing)
{
    start = 0.0;
    float cosLeaving = dot(direction, facingNormal);
    bool crosses = cosLeaving < 0.0;
    vec3 leaving = crosses ? -facingNormal : facingNormal;
    float expectedSign = crosses ? -insideSign : insideSign;
    float clearance = 2.0 * tolerance;
    float along;
    for (int attempt = 0; attempt <= kOffsetShrinks + 2; ++attempt) {
        if (attempt <= kOffsetShrinks)
            origin = offsetAlongRay(p, leaving, direction, abs(cosLeaving),
                                    clearance * pow(kOffsetShrink, float(attempt)), along);
        else
            origin = p + leaving * (float(attempt - kOffsetShrinks) * clearance);
        COUNT_WORK(workEvaluations, 1);
        if (expectedSign * sceneDistanceAndObject(origin, containing) > 0.0) {
            insideSign = expectedSign;
            if (insideSign > 0.0)
                containing = -1;
            return true;
        }
    }
    return false;
}

// Where a shadow segment starts: `clearance` off the surface along wi, as spawn offsets rays
// (offsetAlongRay: the segment's line still passes through the shading point, so what it
// sees of the light is what the point sees; an offset along the normal raises the point, and
// shadows near contacts and edges shift by it), `along` of it along wi. Where the offset
// carries the origin into a solid (the crease where a solid stands on a floor, a room's
// corner), the segment starts nearer the surface, as spawn's rays do (shrinkShadowStart); it
// would otherwise count as blocked.
struct ShadowStart {
    vec3 origin;
    float along;
    float clearance;
    int shrinks;
};

// `start` taken again kOffsetShrink times nearer the surface at s; false (and `start` as it
// was) once it has been kOffsetShrinks times.
bool shrinkShadowStart(inout ShadowStart start, Surface s, vec3 wi, float cosLeaving)
{
    if (start.shrinks >= kOffsetShrinks)
        return false;
    ++start.shrinks;
    start.clearance *= kOffsetShrink;
    start.origin =
        offsetAlongRay(s.position, s.facingNormal, wi, cosLeaving, start.clearance, start.along);
    return true;
}

// Shapes met exactly, which marches leave out, block the segment (to `distance` from s) where
// it crosses one; index-1 ones only tint `transmittance`, and are passed one crossing after
// another. A solid met exactly that the segment leaves before anything else holds its start:
// the start is taken nearer the surface. True when a shape blocks.
bool exactShapesBlock(Surface s, vec3 wi, float cosLeaving, float distance, float tolerance,
                      int target, inout ShadowStart start, inout vec3 transmittance)
{
    float from = 0.0;
    for (int crossing = 0; crossing < kMaxShadowCrossings && loopIterationAllowed();
         ++crossing) {
        ExactHit wall = ExactHit(distance - start.along, -1, vec3(0.0));
        exactSurfacesIntersect(start.origin, wi, from, -1, wall);
        if (wall.object < 0 || wall.object == target)
            break;
        if (from == 0.0 && dot(wall.normal, wi) > 0.0 && shrinkShadowStart(start, s, wi, cosLeaving))
            continue;
        if (!isNullInterface(wall.object))
            return true;
#if HAS_NULL_INTERFACES
        transmittance *= pigmentColor(objectPigment(wall.object), start.origin + wall.t * wi,
                                      -wi, 0.0, 0.0, random01());
        from = wall.t + tolerance;
#endif
    }
    return false;
}

#if HAS_SPHERE_LIGHTS
// Sphere lights that rays leave out of their marches block the segment where it crosses
// them exactly (but the target).
bool excludedSphereLightsBlock(vec3 origin, vec3 wi, float maxDistance, int target)
{
    for (int light = 0; light < LIGHT_COUNT && loopIterationAllowed(); ++light)
        if (lightCullingBit(light) != 0u && lightObject(light) != target &&
            raySphereCrossing(origin, wi, lightPosition(light), lightRadius(light), 0.0) <
                maxDistance)
            return true;
    return false;
}
#endif

const int kMaxShadowStops = kNearMissRetries + kMaxShadowCrossings + 1;

#if HAS_MARCHED_OBJECTS
// The segment marched to its clear end (see shadowTransmittance); `culling` was measured
// from `culledFrom` along wi. The march runs in two nested loops: the inner one (shadowMarch,
// sphere_tracing.glsl) only steps, one distance each, until the ray escapes or stops near a
// surface; this one judges the stop (the light reached, an index-1 surface passed, a near
// miss marched on, a start inside a marched solid, or a blocker) and goes round again only
// while some ray of the SIMD group marches on. llvmpipe executes a branch for the whole group
// whenever one lane takes it, so a judgement inside the step loop would be paid at nearly
// every step.
vec3 marchedTransmittance(Surface s, vec3 wi, float cosLeaving, float distance,
                          float insideSign, RayCulling culling, float culledFrom,
                          float tolerance, int target, ShadowStart start, vec3 transmittance)
{
    float clearDistance = min(distance - start.along, culling.escapeDistance);
    // A segment that starts nearer its surface than the tolerance would stop there at once.
    float stopTolerance = min(tolerance, 0.5 * start.clearance);
    int retries = 0;
    int stepsLeft = gMaxMarchSteps;
    // Before the first piece's bound the segment can approach nothing.
    float t = min(culling.entryDistance, clearDistance);
    float acceptedT = t;
    float acceptedRadius = 0.0;
    for (int stop = 0; stop < kMaxShadowStops && loopIterationAllowed(); ++stop) {
        int nearest;
        float radius = shadowMarch(start.origin, wi, insideSign, culling.mask, clearDistance,
                                   stopTolerance, t, acceptedT, acceptedRadius, stepsLeft, nearest);
        if (t >= clearDistance)
            return transmittance;
        if (!(radius < stopTolerance))
            return vec3(0.0);  // the step budget is spent
        // The origin is inside a marched solid: the offset fell into a crease.
        if (t == 0.0 && radius < 0.0 && shrinkShadowStart(start, s, wi, cosLeaving)) {
            clearDistance = min(distance - start.along,
                                culling.escapeDistance + culledFrom - start.along);
            stopTolerance = min(stopTolerance, 0.5 * start.clearance);
            continue;
        }
        --stepsLeft;
        vec3 p = start.origin + t * wi;
#if HAS_NULL_INTERFACES || HAS_SPHERE_LIGHTS
        if (nearest == target)
            return transmittance;
#endif
#if HAS_NULL_INTERFACES
        if (nearest >= 0 && isNullInterface(nearest)) {
            transmittance *= pigmentColor(objectPigment(nearest), p, -wi, 0.0, tolerance,
                                          random01());
            // Step through the surface; where the step only grazed it, the march goes on
            // from outside and crosses further along.
            t += 2.0 * tolerance;
#ifdef MARCHES_OBJECT_BY_OBJECT
            // Marched one object at a time: inside or outside that object.
            float objectDistanceHere = sceneDistanceCulled(start.origin + t * wi, culling.mask);
            insideSign = objectDistanceHere < 0.0 ? -1.0 : 1.0;
#else
            insideSign = sceneDistance(start.origin + t * wi) < 0.0 ? -1.0 : 1.0;
#endif
            acceptedRadius = 0.0;
            continue;
        }
#endif
        float approach =
            acceptedRadius > 0.0 ? (acceptedRadius - radius) / (t - acceptedT) : 0.0;
        vec3 q = p;
        if (radius <= 0.0 || retries == kNearMissRetries ||
            intersectAlongRay(q, wi, insideSign * radius, insideSign, approach, stopTolerance,
                              culling.mask))
            return vec3(0.0);
        // A near miss: march on past it with a smaller tolerance.
        ++retries;
        stopTolerance *= kNearMissToleranceScale;
        acceptedT = t;
        acceptedRadius = radius;
        t += radius * gStepScale;
    }
    return vec3(0.0);
}
#endif

#if HAS_MARCHED_OBJECTS && defined(MARCHES_OBJECT_BY_OBJECT)
// The general shader's shadow march (shape_interpreter.glsl): every marched object of `mask`
// whose bound the segment comes near, one at a time in the order it comes near them, each
// marched through its own distance along its own stretch (marchedTransmittance, with that
// stretch as its culling), until one blocks the light. A segment that starts inside the
// solid the path travels in (insideSign < 0) heads for that solid's boundary from within.
vec3 marchedObjectsTransmittance(Surface s, vec3 wi, float cosLeaving, float distance,
                                 float insideSign, uint mask, float tolerance, int target,
                                 ShadowStart start, vec3 transmittance)
{
    float afterT = -FLOAT_MAX;
    int afterObject = -1;
    while (loopIterationAllowed()) {
        vec2 stretch;
        int object = nextMarchedObject(start.origin, wi, tolerance, 0.0, mask, 0.0,
                                       distance - start.along, afterT, afterObject, stretch);
        if (object < 0)
            return transmittance;
        afterT = stretch.x;
        afterObject = object;
        gMarchedObject = object;
        float objectSign =
            insideSign < 0.0 && objectDistance(object, start.origin) < 0.0 ? -1.0 : 1.0;
        transmittance = marchedTransmittance(s, wi, cosLeaving, distance, objectSign,
                                             RayCulling(0xffffffffu, stretch.y, stretch.x),
                                             start.along, tolerance, target, start, transmittance);
        if (transmittance == vec3(0.0))
            return transmittance;
    }
    return vec3(0.0);  // the loop budget is spent
}
#endif

// The light's transmittance along a shadow segment from s to `distance` along wi. It leaves
// from off the surface, on the side the path arrived from (ShadowStart), and marches to the
// far end. Sphere lights that rays leave out of their marches block the segment where it
// crosses them exactly; when the segment ends on a light that is still marched, arriving
// within the tolerance of it counts as reaching it. (Marching on to the target's surface
// itself would crawl for ever on rays that meet it at grazing angles, and be taken for
// occlusion.) A stop near another surface blocks the light only if the ray truly meets it,
// as findSurface decides for its hits: a shadow ray grazing a silhouette or slipping past
// the rim of a contact within the tolerance goes on, with a smaller one. A spent step budget
// counts as blocked, as a spent budget counts as a hit for camera and path rays.
vec3 shadowTransmittance(Surface s, vec3 wi, float distance, float insideSign, float tolerance,
                         int target)
{
    COUNT_WORK(workShadowRays, 1);
    float cosLeaving = dot(wi, s.facingNormal);
    ShadowStart start;
    start.clearance = 2.0 * tolerance;
    start.shrinks = 0;
    start.origin =
        offsetAlongRay(s.position, s.facingNormal, wi, cosLeaving, start.clearance, start.along);
    if (target < 0 && distance <= start.along)
        return vec3(0.0);
    vec3 transmittance = vec3(1.0);
    if (exactShapesBlock(s, wi, cosLeaving, distance, tolerance, target, start, transmittance))
        return vec3(0.0);
    RayCulling culling = sceneRayCulling(start.origin, wi, tolerance, 0.0);
    float culledFrom = start.along;  // where along wi from the surface it was measured
#if HAS_SPHERE_LIGHTS
    if (insideSign > 0.0) {
        culling.mask &= ~gSphereLightPieces;
        if (excludedSphereLightsBlock(start.origin, wi, distance - start.along, target))
            return vec3(0.0);
    }
#endif
#if !HAS_MARCHED_OBJECTS
    return transmittance;
#elif defined(MARCHES_OBJECT_BY_OBJECT)
    return marchedObjectsTransmittance(s, wi, cosLeaving, distance, insideSign, culling.mask,
                                       tolerance, target, start, transmittance);
#else
    return marchedTransmittance(s, wi, cosLeaving, distance, insideSign, culling, culledFrom,
                                tolerance, target, start, transmittance);
#endif
}

// How far every camera ray through `pixel` travels before any surface comes within its hit
// tolerance: the pixel's rays fill a cone around the one through its centre, and that cone
// is marched once (coneClearance, sphere_tracing.glsl) so that each of the pixel's paths
// starts its camera ray there instead of at the eye.
float cameraMarchStart(ivec2 pixel)
{
#if !HAS_MARCHED_OBJECTS || defined(MARCHES_OBJECT_BY_OBJECT)
    // (Marched object by object, each ray's march begins where it comes near an object's
    // bound: a cone march of the whole scene would walk the hierarchy at every step.)
    return 0.0;
#endif
    vec3 axis = cameraRayDirection(vec2(pixel) + 0.5);
    // Every ray through the pixel lies within half the pixel's diagonal of the axis; a pixel
    // subtends the largest angle at the centre of the image.
    float growth = (0.7072 + gHitTolerance) * cameraPixelSpread();
    float tolerance0 = gMinimumHitDistance;
#if HAS_THIN_LENS
    // Through a lens, rays leave within gLensRadius of the eye and turn from the pinhole's
    // ray by at most gLensRadius / gFocusDistance (they meet it on the plane of focus, at
    // least that far): a ray's point at distance t lies within gLensRadius + t times that
    // angle of the pinhole's, so a cone that much wider holds every one.
    tolerance0 += gLensRadius;
    growth += gLensRadius / gFocusDistance;
#endif
    RayCulling culling = sceneRayCulling(gCameraEye, axis, tolerance0, growth);
    float limit = min(gFarDistance, culling.escapeDistance);
    return coneClearance(gCameraEye, axis, tolerance0, growth, culling, limit);
}
