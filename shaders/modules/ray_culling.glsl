// Per-ray culling for the sphere tracer. Before a ray is marched, every piece of the scene
// that the ray can never come within its hit tolerance of is left out of the distance the
// march evaluates, and the distance past which it can come near none of them ends the march
// as a miss. A piece is a marched object held inside its bounding ball (shapes with a closed
// form, planes and cones among them, are met exactly and never marched). The tests are
// exact statements about the ray and those balls, so the march meets the same surfaces; it
// only stops spending steps on what lies behind the ray or what it moves away from. That
// matters most where a ray leaves a surface: without culling it creeps away from it in
// steps as small as its height above it, and a ray leaving an open scene marched on to the
// far distance instead of ending where it passed the last object.
//
// A ray's tolerance at distance t is at most tolerance0 + toleranceGrowth * t (RayCone);
// a piece counts as approached where its bound comes within that of the ray.

struct RayCulling {
    uint mask;             // bit k set: piece k may be approached
    float escapeDistance;  // past this distance along the ray no piece may be approached
    float entryDistance;   // before this distance along the ray no piece may be approached
};

// Cones so wide that the tolerance grows as fast as the ray travels (a field of view near
// 180 degrees) are not culled: the margins below assume a much slower growth.
const float kMaxCullableToleranceGrowth = 0.25;

RayCulling noRayCulling()
{
    return RayCulling(0xffffffffu, FLOAT_MAX, 0.0);
}

// A piece inside a ball and behind planes (N, W) (inside where dot(N, p) + W <= 0: a user
// SDF's `@hull`), written by the scene's code as
//   BallChord chord = ballChord(ball, ...); clipChord(chord, plane, ...) for each plane;
//   approachChord(culling, bit, chord);
// (the planes by constant slots: an index computed at run time into the scene's values,
// which the shader holds as a local array, makes llvmpipe keep the whole array in memory).
// The ball's chord is clipped by each plane moved out by the ball's margin: within the chord
// the ray's tolerance is at most that margin, so a ray that comes within its tolerance of
// the piece does so inside the clipped chord.
struct BallChord {
    float entry;
    float exit;    // below entry: the ray passes the piece by
    float margin;  // the largest tolerance the ray has within the chord
};

// The ball's chord along the ray. The ball is widened by the largest tolerance the ray can
// have while it is inside the widened ball, m = tolerance0 + growth (t_far + r + m) solved for
// m, and a little more for rounding.
BallChord ballChord(vec4 ball, vec3 origin, vec3 direction, float tolerance0,
                    float toleranceGrowth)
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
        return BallChord(0.0, -1.0, margin);
    float halfChord = sqrt(halfChordSquared);
    return BallChord(max(along - halfChord, 0.0), along + halfChord, margin);
}

void clipChord(inout BallChord chord, vec4 plane, vec3 origin, vec3 direction)
{
    // Where along the ray dot(N, p) + W - margin changes sign, and which way.
    float height = dot(plane.xyz, origin) + plane.w - chord.margin;
    float rate = dot(plane.xyz, direction);
    if (rate > 0.0)
        chord.exit = min(chord.exit, -height / rate);
    else if (rate < 0.0)
        chord.entry = max(chord.entry, -height / rate);
    else if (height > 0.0)
        chord.exit = -1.0;
}

void approachChord(inout RayCulling culling, uint bit, BallChord chord)
{
    if (chord.exit < chord.entry)
        return;
    culling.mask |= bit;
    culling.escapeDistance = max(culling.escapeDistance, chord.exit);
    culling.entryDistance = min(culling.entryDistance, chord.entry);
}

// A piece inside a ball (centre, radius) alone: its chord, unclipped.
void cullByBall(inout RayCulling culling, uint bit, vec4 ball, vec3 origin, vec3 direction,
                float tolerance0, float toleranceGrowth)
{
    approachChord(culling, bit,
                  ballChord(ball, origin, direction, tolerance0, toleranceGrowth));
}
