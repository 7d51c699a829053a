// A (2, 3) torus knot (a trefoil) lying in the xy plane around the z axis at position x:
// two tubes of radius 1 orbit a ring of radius 6 at distance 1.35 from its core, turning
// 1.5 times per revolution, so after one revolution they have swapped and the two are one
// closed curve.
//
// The twist makes the field stretch around the ring: it can overestimate the distance, by
// less than a factor 2 (worst near the ring's axis). The renderer steps by distance / 2.
// @lipschitz 2.0
// @bound 8.5

float knot(vec3 p, vec3 x)
{
    vec3 q = p - x;
    float ringDistance = length(q.xy);
    float angle = atan(q.y, q.x);
    // The point in the half-plane through the z axis at this angle, relative to the ring's
    // core circle, turned back by the strands' twist at this angle.
    vec2 section = vec2(ringDistance - 6.0, q.z);
    float twist = 1.5 * angle;
    float c = cos(twist);
    float s = sin(twist);
    section = vec2(c * section.x + s * section.y, -s * section.x + c * section.y);
    // Two strands, mirror images across the core.
    section.x = abs(section.x) - 1.35;
    return length(section) - 1.0;
}
