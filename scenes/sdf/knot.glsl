// A (2, 3) torus knot (a trefoil) lying in the xy plane around the z axis at position x:
// two tubes of radius 1 orbit a ring of radius 6 at distance 1.35 from its core, turning
// 1.5 times per revolution, so after one revolution they have swapped and the two are one
// closed curve.
//
// The twist stretches the field around the ring: moving a unit along the ring turns the
// cross-section by 1.5 / r radians (r: the distance from the z axis), which moves a point
// rho from the core by 1.5 rho / r in it. So the twisted tubes' distance d changes by at most
// L = sqrt(1 + (1.5 rho / r)^2) per unit, and d / L is a safe step. L is taken at the worst
// point of the ball that step could reach (rho + s, r - s for s = d / L here), so the value
// returned is a true lower bound of the distance, close to it near the tubes (L is 1 to
// 1.4 there) rather than the half a global factor of 2 would give. Away from the knot the
// distance to the torus that holds both strands (2.35 from the core) is the better bound.
// @bound 8.5
// Both strands lie in the slab of the torus that holds them, |z| <= 2.35 about x: rays that
// cross the ball but not the slab (or cross the slab steeply, as shadow rays towards the
// light in front of the knot do) march none or only a short part of it.
// @hull 0 0  1 2.4
// @hull 0 0 -1 2.4

float knot(vec3 p, vec3 x)
{
    vec3 q = p - x;
    float ringDistance = length(q.xy);
    // The point in the half-plane through the z axis at this angle, relative to the ring's
    // core circle, turned back by the strands' twist at this angle.
    vec2 core = vec2(ringDistance - 6.0, q.z);
    float coreDistance = length(core);
    // Well outside the torus that holds both strands (in the ring's hole, say), its distance
    // is bound enough, and the twisted tubes are not worth evaluating.
    float torusBound = coreDistance - 2.35;
    if (torusBound > 0.5)
        return torusBound;
    // The twist, 1.5 times the angle around the ring, as three times the half angle, whose
    // direction is that of (r + x, y) (or, where x < 0 and that cancels, of (|y|, r - x)
    // turned to y's side): cos 3a = h.x (4 h.x^2 - 3) and sin 3a = h.y (3 - 4 h.y^2) for the
    // unit h = v / |v|, that is v.x (4 v.x^2 - 3 |v|^2) / |v|^3 and likewise, with one
    // inverse square root where atan, cos and sin would cost several polynomials each.
    vec2 towardsHalfAngle = q.x >= 0.0 ? vec2(ringDistance + q.x, q.y)
                                       : vec2(abs(q.y), (q.y >= 0.0 ? 1.0 : -1.0) *
                                                            (ringDistance - q.x));
    float lengthSquared = dot(towardsHalfAngle, towardsHalfAngle);
    float inverseLength = inversesqrt(lengthSquared);
    float inverseCube = inverseLength * inverseLength * inverseLength;
    vec2 v = towardsHalfAngle;
    float c = v.x * (4.0 * v.x * v.x - 3.0 * lengthSquared) * inverseCube;
    float s = v.y * (3.0 * lengthSquared - 4.0 * v.y * v.y) * inverseCube;
    vec2 section = vec2(c * core.x + s * core.y, -s * core.x + c * core.y);
    // Two strands, mirror images across the core.
    section.x = abs(section.x) - 1.35;
    float tubes = length(section) - 1.0;

    // d / sqrt(1 + (1.5 rho / r)^2) written as d r / sqrt(r^2 + (1.5 rho)^2): no division.
    float ring = max(ringDistance, 1e-6);
    float reach = abs(tubes) * ring *
                  inversesqrt(ring * ring + 2.25 * coreDistance * coreDistance);
    float worstRing = max(ringDistance - reach, 1e-6);
    float worstCore = coreDistance + reach;
    float bound = tubes * worstRing *
                  inversesqrt(worstRing * worstRing + 2.25 * worstCore * worstCore);
    return max(bound, torusBound);
}
