// Per-ray culling for the sphere tracer. Before a ray is marched, every piece of the scene
// that the ray can never come within its hit tolerance of is left out of the distance the
// march evaluates, and the distance past which it can come near none of them ends the march
// as a miss. A piece is a part of the scene's union held inside a simple bounding shape: a
// half-space (each plane of a polyhedron; the side of a cone's apex it lies on) or a ball
// (a sphere, a finite object's bounding sphere). The tests are exact statements about the
// ray and those bounds, so the march meets the same surfaces; it only stops spending steps
// on what lies behind the ray or what it moves away from. That matters most where a ray
// leaves a surface: without culling it creeps away from it in steps as small as its
// height above it (a ray leaving a floor at 30 degrees took about nine steps to get clear),
// and a ray leaving an open scene marched on to the far distance instead of ending where it
// passed the last object.
//
// A ray's tolerance at distance t is at most tolerance0 + toleranceGrowth * t (RayCone);
// a piece counts as approached where its bound comes within that of the ray.

uniform int uRayCulling;  // 0: every ray evaluates every object (--no-culling)

struct RayCulling {
    uint mask;             // bit k set: piece k may be approached
    float escapeDistance;  // past this distance along the ray no piece may be approached
};

// Cones so wide that the tolerance grows as fast as the ray travels (a field of view near
// 180 degrees) are not culled: the margins below assume a much slower growth.
const float kMaxCullableToleranceGrowth = 0.25;

RayCulling noRayCulling()
{
    return RayCulling(0xffffffffu, FLOAT_MAX);
}

// A piece inside the half-space k (n.x + w) <= 0, stored as vec4(k n, k w), where k (at
// most 1) is a lower bound of the piece's distance over its half-space distance outside it
// (1 for a plane). The ray's height above it changes linearly, and so does its tolerance:
// the piece is near only while the one is below the other.
void cullByHalfSpace(inout RayCulling culling, uint bit, vec4 scaledPlane, vec3 origin,
                     vec3 direction, float tolerance0, float toleranceGrowth)
{
    float gap = dot(scaledPlane.xyz, origin) + scaledPlane.w - tolerance0;
    float opening = dot(scaledPlane.xyz, direction) - toleranceGrowth;
    if (gap > 0.0 && opening >= 0.0)
        return;
    culling.mask |= bit;
    culling.escapeDistance =
        max(culling.escapeDistance, opening > 0.0 ? -gap / opening : FLOAT_MAX);
}

// A piece inside a ball (centre, radius). The ball is widened by the largest tolerance the
// ray can have while it is inside the widened ball, m = tolerance0 + growth (t_far + r + m)
// solved for m, and a little more for rounding.
void cullByBall(inout RayCulling culling, uint bit, vec4 ball, vec3 origin, vec3 direction,
                float tolerance0, float toleranceGrowth)
{
    vec3 toCenter = ball.xyz - origin;
    float along = dot(toCenter, direction);
    float margin = 1.25 * (tolerance0 + toleranceGrowth * (max(along, 0.0) + ball.w)) /
                   (1.0 - toleranceGrowth);
    float reach = ball.w + margin;
    // The perpendicular part directly, not |toCenter|^2 - along^2: a tiny ball far away
    // would lose all its digits to cancellation.
    vec3 offAxis = toCenter - along * direction;
    float halfChordSquared = reach * reach - dot(offAxis, offAxis);
    if (halfChordSquared < 0.0)
        return;
    float exit = along + sqrt(halfChordSquared);
    if (exit < 0.0)
        return;
    culling.mask |= bit;
    culling.escapeDistance = max(culling.escapeDistance, exit);
}
