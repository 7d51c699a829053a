// Signed distance functions of the primitives, centred at the origin (transform the point,
// not the shape). Each says whether it is EXACT (the true Euclidean distance) or a BOUND
// (never larger than the true distance) and its Lipschitz factor: the sphere tracer's steps
// are safe only for bounds with factor 1. Formulas after Inigo Quilez,
// https://iquilezles.org/articles/distfunctions/, unless noted.

// Sphere of radius r. EXACT, Lipschitz 1.
float sdSphere(vec3 p, float radius)
{
    return length(p) - radius;
}

// Solid half-space dot(n, p) + d <= 0 for a unit normal n, packed as vec4(n, d). EXACT,
// Lipschitz 1.
float sdHalfSpace(vec3 p, vec4 plane)
{
    return dot(plane.xyz, p) + plane.w;
}

// Axis-aligned box with half extents b. EXACT, Lipschitz 1.
float sdBox(vec3 p, vec3 halfExtents)
{
    vec3 q = abs(p) - halfExtents;
    return length(max(q, 0.0)) + min(max(q.x, max(q.y, q.z)), 0.0);
}

// Torus around the y axis. EXACT, Lipschitz 1.
float sdTorus(vec3 p, float majorRadius, float minorRadius)
{
    vec2 q = vec2(length(p.xz) - majorRadius, p.y);
    return length(q) - minorRadius;
}

// Infinite cone, apex at the origin, axis y, opening towards -y, as the scene format
// defines it: dot(normalize(a, b), (length(p.xz), p.y)). BOUND, Lipschitz 1: it is the
// distance, in the (radius, height) half-plane, to the whole line the cone's side lies on,
// which is never more than the distance to the side itself.
float sdConeBound(vec3 p, vec2 unitSlope)
{
    return dot(unitSlope, vec2(length(p.xz), p.y));
}

// Cylinder around y with radius r and half-height h, capped. EXACT, Lipschitz 1.
float sdCappedCylinder(vec3 p, float radius, float halfHeight)
{
    vec2 d = abs(vec2(length(p.xz), p.y)) - vec2(radius, halfHeight);
    return min(max(d.x, d.y), 0.0) + length(max(d, 0.0));
}

// Disk of zero thickness with unit normal n. EXACT, Lipschitz 1, and never negative: it has
// no inside.
float sdDisk(vec3 p, vec3 unitNormal, float radius)
{
    float height = dot(p, unitNormal);
    float radial = length(p - height * unitNormal);
    return length(vec2(max(radial - radius, 0.0), height));
}

// Box of half extents b whose edges and corners are rounded with radius r <= min(b): the
// points within r of the box of half extents b - r. EXACT, Lipschitz 1: the distance to that
// inner box (sdBox) less r.
float sdRoundedBox(vec3 p, vec3 halfExtents, float radius)
{
    return sdBox(p, halfExtents - radius) - radius;
}
