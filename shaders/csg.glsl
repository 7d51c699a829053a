// The seed's CSG solid (its figures 4 and 12): a cube of half-side 1 rounded by intersecting
// it with a sphere of radius 1.35, with three cylindrical holes of radius 0.7 drilled
// through it along the axes. A bound, 1-Lipschitz.
// @bound 1.4

float csg(vec3 p, vec3 x)
{
    vec3 q = p - x;
    float roundedCube = opIntersection(sdSphere(q, 1.35), sdBox(q, vec3(1.0)));
    float drills = min(min(length(q.xy), length(q.yz)), length(q.xz)) - 0.7;
    return opDifference(roundedCube, drills);
}
