// The seed's CSG solid (its figures 4 and 12): a cube of half-side 1 rounded by intersecting
// it with a sphere of radius 1.35, with three cylindrical holes of radius 0.7 drilled
// through it along the axes. A bound, 1-Lipschitz.
// @bound 1.4
// @intersect csgIntersect

float csg(vec3 p, vec3 x)
{
    vec3 q = p - x;
    float roundedCube = opIntersection(sdSphere(q, 1.35), sdBox(q, vec3(1.0)));
    float drills = min(min(length(q.xy), length(q.yz)), length(q.xz)) - 0.7;
    return opDifference(roundedCube, drills);
}

// The same solid met exactly, by intervals along the ray (Roth 1982): the rounded cube is
// convex, so the ray is inside it over one interval; each drill is an infinite cylinder, one
// interval too; the solid is the first less the three. Its surface is crossed at an end of
// the cube's interval that lies in no drill, or at an end of a drill's interval that lies
// inside the cube and in no other drill.

// The interval (enter, exit) of the ray inside the drill along `axis` (0: x, 1: y, 2: z):
// the disk of radius 0.7 in the other two coordinates. Empty: enter > exit.
vec2 csgDrillInterval(vec3 q, vec3 d, int axis)
{
    vec2 qa = axis == 0 ? q.yz : (axis == 1 ? q.xz : q.xy);
    vec2 da = axis == 0 ? d.yz : (axis == 1 ? d.xz : d.xy);
    float planar = dot(da, da);
    if (planar == 0.0)
        return dot(qa, qa) < 0.49 ? vec2(-FLOAT_MAX, FLOAT_MAX) : vec2(1.0, -1.0);
    float along = dot(qa, da) / planar;
    vec2 offAxis = qa - along * da;
    float halfChordSquared = (0.49 - dot(offAxis, offAxis)) / planar;
    if (halfChordSquared < 0.0)
        return vec2(1.0, -1.0);
    float halfChord = sqrt(halfChordSquared);
    return vec2(-along - halfChord, -along + halfChord);
}

bool csgInsideAnyDrill(float t, vec2 drillX, vec2 drillY, vec2 drillZ)
{
    return (drillX.x < t && t < drillX.y) || (drillY.x < t && t < drillY.y) ||
           (drillZ.x < t && t < drillZ.y);
}

// The drill's wall at q: the solid's outward normal there points to the drill's axis.
vec3 csgDrillNormal(vec3 q, int axis)
{
    vec3 radial = q;
    radial[axis] = 0.0;
    return -normalize(radial);
}

bool csgIntersect(vec3 origin, vec3 direction, vec3 x, float tMin, float tMax, out float t,
                  out vec3 normal)
{
    vec3 q = origin - x;
    t = tMax;
    normal = vec3(0.0);
    // The sphere's chord, then the box's slabs, clip one interval.
    float b = dot(q, direction);
    vec3 offCenter = q - b * direction;
    float halfChordSquared = 1.35 * 1.35 - dot(offCenter, offCenter);
    if (halfChordSquared < 0.0)
        return false;
    float halfChord = sqrt(halfChordSquared);
    float enter = -b - halfChord;
    float exit = -b + halfChord;
    vec3 enterNormal = (q + enter * direction) / 1.35;
    vec3 exitNormal = (q + exit * direction) / 1.35;
    for (int axis = 0; axis < 3; ++axis) {
        float rate = direction[axis];
        if (rate == 0.0) {
            if (abs(q[axis]) >= 1.0)
                return false;
            continue;
        }
        float side = rate > 0.0 ? 1.0 : -1.0;
        float near = (-side - q[axis]) / rate;
        float far = (side - q[axis]) / rate;
        vec3 face = vec3(0.0);
        face[axis] = side;
        if (near > enter) {
            enter = near;
            enterNormal = -face;
        }
        if (far < exit) {
            exit = far;
            exitNormal = face;
        }
    }
    if (!(enter < exit))
        return false;
    vec2 drillX = csgDrillInterval(q, direction, 0);
    vec2 drillY = csgDrillInterval(q, direction, 1);
    vec2 drillZ = csgDrillInterval(q, direction, 2);
    bool found = false;
    if (enter > tMin && enter < t && !csgInsideAnyDrill(enter, drillX, drillY, drillZ)) {
        t = enter;
        normal = enterNormal;
        found = true;
    }
    if (exit > tMin && exit < t && !csgInsideAnyDrill(exit, drillX, drillY, drillZ)) {
        t = exit;
        normal = exitNormal;
        found = true;
    }
    for (int axis = 0; axis < 3; ++axis) {
        vec2 drill = axis == 0 ? drillX : (axis == 1 ? drillY : drillZ);
        for (int end = 0; end < 2; ++end) {
            float crossing = drill[end];
            if (crossing > tMin && crossing < t && enter < crossing && crossing < exit &&
                !csgInsideAnyDrill(crossing, drillX, drillY, drillZ)) {
                t = crossing;
                normal = csgDrillNormal(q + crossing * direction, axis);
                found = true;
            }
        }
    }
    return found;
}
