// Ray-scene intersection by sphere tracing (Hart 1996) with over-relaxation (Keinert et al.,
// "Enhanced Sphere Tracing", 2014). Needs sceneDistance and sceneDistanceAndObject from the
// scene module, and their culled forms with sceneRayCulling (ray_culling.glsl).
//
// The three marchers, side by side, with one contract: each steps along a unit direction
// from its origin through the pieces a culling mask leaves (ray_culling.glsl), never past a
// point the caller knows to be clear of every surface, never beyond the distance it is
// given, and each step evaluated is taken from a budget the caller holds.
//   sphereTrace     a path's ray: over-relaxed, to the first surface within the ray cone's
//                   hit tolerance (or its closest approach where the budget runs out);
//   shadowMarch     a shadow ray's segment: plain steps, to the first stop within a given
//                   tolerance or the segment's clear end; what a stop means (the light, a
//                   near miss, a blocker) the caller judges (ray_queries_traced.glsl);
//   coneClearance   a whole pixel's cone of camera rays at once: how far all of them may go
//                   before any comes within its tolerance of a surface.
// Hits are moved onto the surface by intersectAlongRay, and normals taken by sceneNormal.
//
// Tolerances follow the ray, not the world: a hit is accepted when the distance falls below
// a fraction (gHitTolerance) of the footprint of the ray's cone there, and never below
// gMinimumHitDistance, which the host derives from the scene's size. So a scene scaled by
// 1e-3 or 1e3 is traced the same way.

// A ray's footprint: `width` at its origin, growing by `spread` per unit of distance.
struct RayCone {
    float width;
    float spread;
};

float coneFootprint(RayCone cone, float t)
{
    return cone.width + cone.spread * t;
}

float hitTolerance(RayCone cone, float t)
{
    return max(gMinimumHitDistance, gHitTolerance * coneFootprint(cone, t));
}

struct MarchHit {
    bool found;
    float t;
    float sceneDistance;  // sceneDistance() at the hit point, sign included
    int object;
    // How fast the distance to the surface fell along the ray over the march's last step
    // (the secant slope of the signed radius): 1 heading straight at a plane, near 0
    // grazing it, 0 where unknown.
    float approach;
    float tolerance;   // the tolerance the hit was accepted within
    bool budgetSpent;  // the step budget ran out: the hit is the closest approach
};

// No surface met: the ray escaped at t, or nothing was marched.
MarchHit marchMiss(float t)
{
    return MarchHit(false, t, 0.0, -1, 0.0, 0.0, false);
}

// A surface met within `tolerance` at t, approached at the secant slope `approach`.
MarchHit marchHit(float t, float sceneDistance, int object, float approach, float tolerance)
{
    return MarchHit(true, t, sceneDistance, object, approach, tolerance, false);
}

// The closest approach to a surface so far, at t: the hit where the step budget runs out.
MarchHit marchClosestApproach(float t, float sceneDistance, int object, float tolerance)
{
    return MarchHit(true, t, sceneDistance, object, 0.0, tolerance, true);
}

// The budget spent with no surface approached: what a march returns before it has any.
MarchHit marchNothingApproached()
{
    return MarchHit(false, 0.0, 0.0, -1, 0.0, 0.0, true);
}

// The pieces of the scene the ray may come near, and how far it may meet any (see
// ray_culling.glsl).
RayCulling rayCulling(vec3 origin, vec3 direction, RayCone cone)
{
    return sceneRayCulling(origin, direction, hitTolerance(cone, 0.0),
                           gHitTolerance * cone.spread);
}

// Marches the ray from `startDistance` (which the caller knows to be clear of every
// surface; 0: the origin) to `endDistance` through the pieces `culling` leaves, accepting a
// surface within `toleranceScale` times the ray's hit tolerance. `insideSign` is -1 when the
// ray starts inside the solid (inside glass): the distance is negated so the march heads for
// the boundary from within. Each step evaluated is taken from `stepsLeft`.
MarchHit sphereTrace(vec3 origin, vec3 direction, float insideSign, RayCone cone,
                     float toleranceScale, RayCulling culling, float startDistance,
                     float endDistance, inout int stepsLeft)
{
    float farDistance = min(endDistance, culling.escapeDistance);
    float omega = gOverRelaxation;
    // Before the first piece's bound the ray can approach nothing: no step is spent there.
    float t = max(startDistance, culling.entryDistance);
    float stepLength = 0.0;
    float previousRadius = 0.0;
    // The last point the march accepted (not one a failed relaxed step reached), for the
    // secant slope at a hit.
    float acceptedT = t;
    float acceptedRadius = 0.0;
    float bestError = FLOAT_MAX;
    MarchHit best = marchNothingApproached();

    for (; stepsLeft > 0 && loopIterationAllowed(); --stepsLeft) {
        COUNT_MARCH_STEP();
        if (t >= farDistance) {
            // Escaped, unless a relaxed step jumped past the part of the ray its safe sphere
            // covered: a surface may lie there. Then it is undone as a failed relaxation.
            if (t - stepLength + previousRadius >= farDistance)
                return marchMiss(t);
            stepLength -= omega * stepLength;
            omega = 1.0;
            t += stepLength;
            continue;
        }
        int object;
        float distance = sceneDistanceAndObjectCulled(origin + t * direction, culling.mask, object);
        float signedRadius = insideSign * distance;
        float radius = abs(signedRadius);

        // Over-relaxed spheres must overlap; when they do not, the relaxed step may have
        // jumped over a surface: step back inside the last safe sphere and stop relaxing.
        // A relaxed step that lands inside a solid has crossed its surface even where the
        // spheres touch (a plane met head on): it is undone too, so that hits are always
        // approached from the ray's side.
        bool relaxationFailed =
            omega > 1.0 && (radius + previousRadius < stepLength || signedRadius < 0.0);
        if (relaxationFailed) {
            stepLength -= omega * stepLength;
            omega = 1.0;
        } else {
            stepLength = signedRadius * omega * gStepScale;
            float tolerance = toleranceScale * hitTolerance(cone, t);
            if (radius < tolerance) {
                // The secant needs a previous point on the ray's side of the surface: inside
                // a solid the distance is to whatever face is nearest in there (the hidden
                // face where two boxes touch), not to this one.
                float approach = acceptedRadius > 0.0
                                     ? (acceptedRadius - signedRadius) / (t - acceptedT)
                                     : 0.0;
                --stepsLeft;
                return marchHit(t, distance, object, approach, tolerance);
            }
            float error = radius / tolerance;
            if (error < bestError) {
                bestError = error;
                best = marchClosestApproach(t, distance, object, tolerance);
            }
            acceptedT = t;
            acceptedRadius = signedRadius;
        }
        previousRadius = radius;
        t += stepLength;
    }
    // The step budget ran out before the ray escaped. If it came within about a tolerance of
    // a surface it is creeping along it (grazing) or squeezing through a narrow gap, where the
    // pixel's cone overlaps that surface anyway: the closest approach is taken as the hit,
    // which keeps a closed room closed (returning "no hit" would let the sky leak in). A ray
    // that stayed far from everything was escaping and sees the environment.
    const float kCandidateErrorLimit = 1.5;
    best.found = bestError < kCandidateErrorLimit && best.object >= 0;
    return best;
}

// Steps a shadow ray from `t` along unit `direction` (`insideSign` as for sphereTrace) through
// the pieces `mask` leaves until it stops within `stopTolerance` of a surface, reaches
// `clearDistance` (t is then at least that) or spends `stepsLeft`. Returns the signed radius
// at the stop (FLOAT_MAX where it reached the end first); acceptedT and acceptedRadius keep
// the last point passed clear of every surface, for the stop's secant slope. Plain steps,
// not over-relaxed: shadow segments are short, and a relaxed step that fails costs one more
// evaluation than it saves (measured worse, docs/PERFORMANCE.md).
// `nearest` receives the object nearest the stop where the caller asks which one it is (a
// light the segment reaches, an index-1 surface it passes): the step's own evaluation tells,
// where one more evaluation at the stop would cost a whole scene distance per stop.
float shadowMarch(vec3 origin, vec3 direction, float insideSign, uint mask, float clearDistance,
                  float stopTolerance, inout float t, inout float acceptedT,
                  inout float acceptedRadius, inout int stepsLeft, out int nearest)
{
    float radius = FLOAT_MAX;
    nearest = -1;
    for (; stepsLeft > 0 && loopIterationAllowed(); --stepsLeft) {
        COUNT_WORK(workShadowSteps, 1);
        if (t >= clearDistance)
            break;
#if HAS_NULL_INTERFACES || HAS_SPHERE_LIGHTS
        radius = insideSign * sceneDistanceAndObjectCulled(origin + t * direction, mask, nearest);
#else
        radius = insideSign * sceneDistanceCulled(origin + t * direction, mask);
#endif
        if (radius < stopTolerance)
            break;
        acceptedT = t;
        acceptedRadius = radius;
        t += radius * gStepScale;
    }
    return radius;
}

// How far along unit `axis` from `origin` every ray of a cone may travel before any surface
// comes within its tolerance, up to `limit`: the cone's rays stray at most `growth` per unit
// from the axis, tolerances included, and the tolerance at the origin is `tolerance0`.
// A step from t may advance by as much as leaves every point of the cone up to t + step
// farther from the nearest surface than its tolerance: for a distance d at the axis that is
// (d - tolerance0 - growth t) / (1 + growth) (cone marching, as in Amanatides, "Ray tracing
// with cones", 1984). `culling` must be a culling by the same cone: the march starts where
// it first comes near a piece's bound and evaluates only the pieces it leaves.
float coneClearance(vec3 origin, vec3 axis, float tolerance0, float growth, RayCulling culling,
                    float limit)
{
    const int kConeSteps = 64;
    float t = min(culling.entryDistance, limit);
    for (int step = 0; step < kConeSteps && t < limit && loopIterationAllowed(); ++step) {
        COUNT_WORK(workCameraSteps, 1);
        float clearance =
            sceneDistanceCulled(origin + t * axis, culling.mask) - tolerance0 - growth * t;
        float advance = 0.9 * gStepScale * clearance / (1.0 + growth);
        // Near a surface the steps shrink geometrically; the rays' own marches, each from
        // here, finish the approach.
        if (advance < tolerance0 + growth * t)
            break;
        t += advance;
    }
    return min(t, limit);
}

// The gradient of the marched part of the scene's distance (every object but the polyhedra,
// which rays meet exactly, with their own normals) by central differences along the three
// axes. Six evaluations rather than the four of a tetrahedral stencil: the tetrahedron's
// error is first order in the step (its vertices do not cancel the Hessian's off-diagonal
// terms), enough to tilt a mirror's normal by 1e-3 and move the reflection of a small light
// by a visible fraction of a pixel. Its length is 1 wherever the distance is exact and
// smooth. Leaving the planes out keeps a floor or a wall from tilting the normal of an
// object that touches it.
// `bend` receives sum over the axes of |d(p + h e) + d(p - h e)| / h, which for p on the
// surface (d(p) = 0) is the difference of the forward and backward differences: about h
// times the field's second derivatives where it is smooth (under 0.01 for a curvature
// radius of 100 steps), of order 1 where the taps straddle a kink of the field.
vec3 sceneGradient(vec3 p, float step, out float bend)
{
    COUNT_WORK(workEvaluations, 6);
    const uint every = 0xffffffffu;
    // One call in a loop over the six taps (the same taps, the same sums), not six calls: the
    // general shader's distance is its interpreter, inlined wherever it is called, and on
    // SIMD hardware that runs both sides of a branch (llvmpipe among it) six calls would be
    // paid by every group of rays, also where none of them met a marched surface, while the
    // loop goes round once only there.
    vec3 forward = vec3(0.0);
    vec3 backward = vec3(0.0);
    for (int tap = 0; tap < 6 && loopIterationAllowed(); ++tap) {
        vec3 axis = vec3(equal(ivec3(tap % 3), ivec3(0, 1, 2)));
        float side = tap < 3 ? 1.0 : -1.0;
        float d = sceneDistanceCulled(p + side * step * axis, every);
        forward += tap < 3 ? d * axis : vec3(0.0);
        backward += tap < 3 ? vec3(0.0) : d * axis;
    }
    vec3 sums = abs(forward + backward);
    bend = (sums.x + sums.y + sums.z) / step;
    return (forward - backward) / (2.0 * step);
}

// The outward normal of the scene's marched surface at p (within the hit tolerance of it),
// with a difference step that follows the tolerance. It is the gradient of the whole marched
// distance, not the hit object's: where objects meet (two boxes sharing a face: one flat
// top) the surface is their union, and one object's own gradient turns at its edge where
// the union's does not.
// A stencil that straddles an edge of the solid (where two of its faces meet: the rim of a
// hole, the bottom edge of a solid standing on a floor) averages the two faces' gradients
// and tilts the normal by up to half the edge's angle, over a band as wide as the step: a
// sixteenth of a pixel along every edge of a marched solid was shaded with the wrong normal,
// and the crease of a CSG solid standing on a floor came out 2-4 % too dark
// (tests/render/EdgeBiasTest.cpp). On the surface the taps show it: the forward and backward
// differences disagree (sceneGradient's `bend`). The gradient is then taken again with a
// step kNormalRefinement times smaller, at most kNormalRefinements times and not below what
// float32 resolves (kFinestNormalStep): the band narrows by that factor each time. Where the
// field only bends fast (a thin tube), the smaller step gives the same direction, and the
// first is kept. (The gradient's length would not do: a user SDF that returns a bound, and
// a smooth blend, have no unit gradient anywhere, and every hit on them would pay a second
// gradient.)
// The union of distances is exact only outside the solid, though; inside, near a face
// that two objects share, it measures the distance to that hidden face, and taps that
// reach there tilt the gradient at any step. Where two or more objects are marched
// (HAS_MARCHED_UNION), a gradient whose length is not 1 says so: it is then taken again
// from a point backed off the surface by the taps' reach, on the side the ray came from,
// where every tap is outside. `side` is +1 for rays outside the solid, -1 inside.
// A gradient that (nearly) vanishes, as on a surface of zero thickness (a disk, whose
// distance rises on both sides), is taken again at the fallback point `q` with step
// `qStep`, if `tryP` was true; zero when that vanishes too: the caller chooses then.
// The attempts are one loop round a single gradient: llvmpipe executes both sides of every
// branch, so a gradient written out once per case would cost all of them every time, while
// a loop goes round again only when some pixel of the SIMD group needs it.
const float kNormalRefinement = 8.0;
const int kNormalRefinements = 2;
// A bend above this is a kink: at a right-angled edge, a tilt of about 0.4 degrees.
const float kNormalKink = 0.03;
// In units of gMinimumHitDistance, 1e-5 of the scene's size: distances there are good to
// a few units in the last place, which leave a gradient of this step within about 1e-2.
const float kFinestNormalStep = 0.25;
// Two gradients closer than this (a cosine: 0.5 degrees) point the same way.
const float kSameNormal = 0.99996;

vec3 sceneNormal(vec3 p, float step, bool tryP, vec3 q, float qStep, float side)
{
    vec3 at = tryP ? p : q;
    float h = tryP ? step : qStep;
    bool atFallback = !tryP;
    bool backedOff = false;
    int refinements = 0;
    vec3 coarser = vec3(0.0);  // the direction before the last refinement; 0: none
    for (int attempt = 0; attempt < kNormalRefinements + 4; ++attempt) {
        float bend;
        vec3 gradient = sceneGradient(at, h, bend);
        float magnitude = length(gradient);
        vec3 direction = magnitude > 0.0 ? gradient / magnitude : vec3(0.0);
        if (!atFallback && !backedOff) {
            if (dot(direction, coarser) > kSameNormal)
                return coarser;
            if (bend > kNormalKink && refinements < kNormalRefinements && magnitude > 0.1 &&
                h > kNormalRefinement * kFinestNormalStep * gMinimumHitDistance) {
                coarser = direction;
                h /= kNormalRefinement;
                ++refinements;
                continue;
            }
        }
        if (HAS_MARCHED_UNION != 0 && !backedOff && magnitude > 0.5 &&
            abs(magnitude - 1.0) > 0.01) {
            at += (side * 1.75 * h) * direction;
            backedOff = true;
            continue;
        }
        if (backedOff ? magnitude > 0.0 : magnitude > 0.5)
            return direction;
        if (atFallback)
            break;
        at = q;
        h = qStep;
        atFallback = true;
        backedOff = false;
    }
    return vec3(0.0);
}

// Moves `point`, where a march along unit `direction` through the pieces `mask` leaves
// stopped at their distance `distance` (sign included; `insideSign` as for the march), along
// the ray onto the surface, by Newton's method with the slope along the ray fixed at the
// march's last secant slope `approach` (the chord method): exact in one step for planes, a
// few for curves. True when it converged to within 1/1024 of `tolerance` (or what float32
// resolves there); false, and `point` unchanged, where it does not
// converge (a ray passing a curved silhouette within the tolerance without meeting it, or
// running into another surface near an edge) or where the ray is so close to tangent that
// the point would move more than 16 tolerances. The convergence must be that tight: the
// distance along a ray that passes a silhouette has a minimum, the height it passes at, and
// Newton's iterates settle there; a looser test takes every ray passing within it for a hit
// and dilates silhouettes by that much (3 % too bright at the rim of a mirror sphere with
// 1/32, against exact intersection).
bool intersectAlongRay(inout vec3 point, vec3 direction, float distance, float insideSign,
                       float approach, float tolerance, uint mask)
{
    const float kMinimumApproach = 1.0 / 16.0;
    const float kConverged = 1.0 / 1024.0;
    const int kIterations = 4;
    if (!(approach >= kMinimumApproach))
        return false;
    // Float32 distances near q are good to a few units in the last place of its coordinates.
    float converged = max(kConverged * tolerance, 4e-6 * length(point));
    vec3 q = point;
    float d = distance;
    for (int i = 0; i < kIterations && abs(d) > converged; ++i) {
        vec3 next = q + direction * (insideSign * d / approach);
        float nextDistance = sceneDistanceCulled(next, mask);
        COUNT_WORK(workEvaluations, 1);
        if (!(abs(nextDistance) < 0.5 * abs(d)))
            return false;
        q = next;
        d = nextDistance;
    }
    if (!(abs(d) <= converged))
        return false;
    point = q;
    return true;
}
