// Ray-scene intersection by sphere tracing (Hart 1996) with over-relaxation (Keinert et al.,
// "Enhanced Sphere Tracing", 2014). Needs sceneDistance, sceneDistanceAndObject and
// objectDistance from the scene module.
//
// Tolerances follow the ray, not the world: a hit is accepted when the distance falls below
// a fraction (uHitTolerance) of the footprint of the ray's cone there, and never below
// uMinimumHitDistance, which the host derives from the scene's size. So a scene scaled by
// 1e-3 or 1e3 is traced the same way.

uniform float uHitTolerance;        // fraction of the cone's footprint
uniform float uMinimumHitDistance;  // world units, from the scene's bounds
uniform float uFarDistance;         // world units, from the scene's bounds
uniform int uMaxMarchSteps;
uniform float uOverRelaxation;      // Keinert's omega; 1 is plain sphere tracing

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
    return max(uMinimumHitDistance, uHitTolerance * coneFootprint(cone, t));
}

struct MarchHit {
    bool found;
    float t;
    float sceneDistance;  // sceneDistance() at the hit point, sign included
    int object;
};

// `insideSign` is -1 when the ray starts inside the solid (inside glass): the distance is
// negated so the march heads for the boundary from within.
MarchHit sphereTrace(vec3 origin, vec3 direction, float insideSign, RayCone cone)
{
    float omega = uOverRelaxation;
    float t = 0.0;
    float stepLength = 0.0;
    float previousRadius = 0.0;
    float bestError = FLOAT_MAX;
    MarchHit best = MarchHit(false, 0.0, 0.0, -1);

    for (int step = 0; step < uMaxMarchSteps; ++step) {
        int object;
        float distance = sceneDistanceAndObject(origin + t * direction, object);
        float signedRadius = insideSign * distance;
        float radius = abs(signedRadius);

        // Over-relaxed spheres must overlap; when they do not, the relaxed step may have
        // jumped over a surface: step back inside the last safe sphere and stop relaxing.
        bool relaxationFailed = omega > 1.0 && radius + previousRadius < stepLength;
        if (relaxationFailed) {
            stepLength -= omega * stepLength;
            omega = 1.0;
        } else {
            stepLength = signedRadius * omega;
            float tolerance = hitTolerance(cone, t);
            if (radius < tolerance)
                return MarchHit(true, t, distance, object);
            float error = radius / tolerance;
            if (error < bestError) {
                bestError = error;
                best = MarchHit(true, t, distance, object);
            }
        }
        previousRadius = radius;
        if (t > uFarDistance)
            return MarchHit(false, t, distance, -1);
        t += stepLength;
    }
    // The step budget ran out before the ray escaped: it is creeping along a surface
    // (grazing) or squeezing through a narrow gap. Taking the closest approach as the hit
    // keeps a closed room closed; returning "no hit" would let the sky leak in.
    return best;
}

// True when nothing lies between `origin` and `maxDistance` along `direction`. When the
// segment ends on an object (a sphere light), pass its index as `target`: arriving within
// the tolerance of the target counts as reaching it. (Marching on to the target's surface
// itself would crawl for ever on the rays that meet it at grazing angles and be taken for
// occlusion.) A spent step budget counts as blocked, for the same reason as above.
bool unoccluded(vec3 origin, vec3 direction, float maxDistance, float insideSign,
                float tolerance, int target)
{
    float t = 0.0;
    for (int step = 0; step < uMaxMarchSteps; ++step) {
        if (t >= maxDistance)
            return true;
        vec3 p = origin + t * direction;
        float radius = insideSign * sceneDistance(p);
        if (radius < tolerance) {
            if (target < 0)
                return false;
            int nearest;
            sceneDistanceAndObject(p, nearest);
            return nearest == target;
        }
        t += radius;
    }
    return false;
}

// The object's outward normal: the gradient of its own distance by central differences on
// the four vertices of a tetrahedron (four evaluations instead of six), with a step that
// follows the hit tolerance. Zero when the gradient vanishes; the caller chooses a fallback.
vec3 objectNormal(int object, vec3 p, float step)
{
    const vec2 k = vec2(1.0, -1.0);
    vec3 gradient = k.xyy * objectDistance(object, p + k.xyy * step) +
                    k.yyx * objectDistance(object, p + k.yyx * step) +
                    k.yxy * objectDistance(object, p + k.yxy * step) +
                    k.xxx * objectDistance(object, p + k.xxx * step);
    float magnitude = length(gradient);
    return magnitude > 0.0 ? gradient / magnitude : vec3(0.0);
}
