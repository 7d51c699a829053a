// Exact ray intersections of the shapes that have one in closed form: every render meets
// polyhedra and sphere lights through them (ray_queries_traced.glsl), and --exact-geometry
// every shape it can (ray_queries_exact.glsl). Each exact* function takes a ray (unit
// direction), the interval (tMin, hit.t) in which a crossing counts, and replaces `hit` by
// the shape's first crossing in it, returning true when it did. Normals are the solid's
// outward unit normals; a disk, which has no inside, faces the ray.

struct ExactHit {
    float t;
    int object;
    vec3 normal;
};

// The first t beyond tMin at which the ray (unit direction) crosses the sphere's surface, or
// FLOAT_MAX. The chord's half-length comes from the ray's distance to the centre measured
// perpendicularly (not |oc|^2 - b^2, which cancels for far spheres).
float raySphereCrossing(vec3 origin, vec3 direction, vec3 center, float radius, float tMin)
{
    vec3 fromCenter = origin - center;
    float b = dot(fromCenter, direction);
    vec3 offAxis = fromCenter - b * direction;
    float halfChordSquared = radius * radius - dot(offAxis, offAxis);
    if (halfChordSquared < 0.0)
        return FLOAT_MAX;
    float halfChord = sqrt(halfChordSquared);
    if (-b - halfChord > tMin)
        return -b - halfChord;
    return -b + halfChord > tMin ? -b + halfChord : FLOAT_MAX;
}

// Sphere (centre, radius) = vec4.
bool exactSphere(vec3 origin, vec3 direction, vec4 sphere, float tMin, int object,
                 inout ExactHit hit)
{
    float t = raySphereCrossing(origin, direction, sphere.xyz, sphere.w, tMin);
    if (!(t < hit.t))
        return false;
    // Normalised, not divided by the radius: the point is on the sphere only to rounding, and
    // a normal a little off unit length makes a reflected direction a little off unit length,
    // which the next crossing (computed for a unit direction) puts further off the sphere:
    // light trapped by total internal reflection drifted out after about ten bounces.
    hit = ExactHit(t, object, normalize(origin + t * direction - sphere.xyz));
    return true;
}

// The interval of a ray inside a convex region, and the region's outward unit normals on
// the faces the ray enters and leaves it by.
struct ConvexInterval {
    float enter;
    float exit;
    vec3 enterNormal;
    vec3 exitNormal;
};

ConvexInterval wholeRay()
{
    return ConvexInterval(-FLOAT_MAX, FLOAT_MAX, vec3(0.0), vec3(0.0));
}

// Clips the interval by the open half-space dot(n, x) + w < 0 of plane (n, w), unit n.
void clipByHalfSpace(inout ConvexInterval interval, vec3 origin, vec3 direction, vec4 plane)
{
    float height = dot(plane.xyz, origin) + plane.w;
    float rate = dot(plane.xyz, direction);
    if (rate > 0.0) {
        float t = -height / rate;
        if (t < interval.exit) {
            interval.exit = t;
            interval.exitNormal = plane.xyz;
        }
    } else if (rate < 0.0) {
        float t = -height / rate;
        if (t > interval.enter) {
            interval.enter = t;
            interval.enterNormal = plane.xyz;
        }
    } else if (height >= 0.0) {
        interval.enter = FLOAT_MAX;  // parallel, and outside: never inside
    }
}

// The first crossing of a convex solid's boundary: entering it (outward normal against the
// ray) or, from inside, leaving it.
bool exactConvexSolid(ConvexInterval interval, float tMin, int object, inout ExactHit hit)
{
    if (!(interval.enter < interval.exit))
        return false;
    if (interval.enter > tMin) {
        if (!(interval.enter < hit.t))
            return false;
        hit = ExactHit(interval.enter, object, interval.enterNormal);
        return true;
    }
    if (interval.exit > tMin && interval.exit < hit.t && interval.exit < FLOAT_MAX) {
        hit = ExactHit(interval.exit, object, interval.exitNormal);
        return true;
    }
    return false;
}

// The scene format's polyhedron is the union of solid half-spaces, the complement of the
// convex region where every plane's distance is positive (a room's inside): its surface is
// crossed where a ray leaves that region (into the solid, outward normal n, against the
// ray) or enters it (out of the solid, outward normal n, along the ray). The region is
// clipped plane by plane with clipOutsideHalfSpace.
void clipOutsideHalfSpace(inout ConvexInterval interval, vec3 origin, vec3 direction,
                          vec4 plane)
{
    clipByHalfSpace(interval, origin, direction, -plane);
}

bool exactHalfSpaceUnion(ConvexInterval outside, float tMin, int object, inout ExactHit hit)
{
    // The normals clipByHalfSpace recorded point out of the region, into the solid: the
    // solid's outward normal is their opposite.
    outside.enterNormal = -outside.enterNormal;
    outside.exitNormal = -outside.exitNormal;
    return exactConvexSolid(outside, tMin, object, hit);
}

// A slab |x_axis - centre| < halfWidth along one axis of the shape's frame.
void clipBySlab(inout ConvexInterval interval, float origin, float direction, float halfWidth,
                vec3 axis)
{
    if (direction == 0.0) {
        if (abs(origin) >= halfWidth)
            interval.enter = FLOAT_MAX;
        return;
    }
    float near = (-sign(direction) * halfWidth - origin) / direction;
    float far = (sign(direction) * halfWidth - origin) / direction;
    if (near > interval.enter) {
        interval.enter = near;
        interval.enterNormal = -sign(direction) * axis;
    }
    if (far < interval.exit) {
        interval.exit = far;
        interval.exitNormal = sign(direction) * axis;
    }
}

// Axis-aligned box (centre, half extents) in the frame of `origin` and `direction`.
bool exactBox(vec3 origin, vec3 direction, vec3 center, vec3 halfExtents, float tMin,
              int object, inout ExactHit hit)
{
    vec3 q = origin - center;
    ConvexInterval interval = wholeRay();
    clipBySlab(interval, q.x, direction.x, halfExtents.x, vec3(1.0, 0.0, 0.0));
    clipBySlab(interval, q.y, direction.y, halfExtents.y, vec3(0.0, 1.0, 0.0));
    clipBySlab(interval, q.z, direction.z, halfExtents.z, vec3(0.0, 0.0, 1.0));
    return exactConvexSolid(interval, tMin, object, hit);
}

// Capped cylinder around y (centre, radius, half-height): the slab |y| < h and the infinite
// cylinder x^2 + z^2 < r^2, whose chord is found as the sphere's is, in the xz plane.
bool exactCappedCylinder(vec3 origin, vec3 direction, vec3 center, float radius,
                         float halfHeight, float tMin, int object, inout ExactHit hit)
{
    vec3 q = origin - center;
    ConvexInterval interval = wholeRay();
    clipBySlab(interval, q.y, direction.y, halfHeight, vec3(0.0, 1.0, 0.0));
    float planar = dot(direction.xz, direction.xz);
    if (planar > 0.0) {
        float along = dot(q.xz, direction.xz) / planar;
        vec2 offAxis = q.xz - along * direction.xz;
        float halfChordSquared = (radius * radius - dot(offAxis, offAxis)) / planar;
        if (halfChordSquared < 0.0)
            return false;
        float halfChord = sqrt(halfChordSquared);
        float near = -along - halfChord;
        float far = -along + halfChord;
        if (near > interval.enter) {
            interval.enter = near;
            vec2 radial = (q.xz + near * direction.xz) / radius;
            interval.enterNormal = vec3(radial.x, 0.0, radial.y);
        }
        if (far < interval.exit) {
            interval.exit = far;
            vec2 radial = (q.xz + far * direction.xz) / radius;
            interval.exitNormal = vec3(radial.x, 0.0, radial.y);
        }
    } else if (dot(q.xz, q.xz) >= radius * radius) {
        return false;
    }
    return exactConvexSolid(interval, tMin, object, hit);
}

// Infinite cone with its apex at `apex` and its axis along y, the solid where
// dot(unitSlope, (|q.xz|, q.y)) < 0 for q = p - apex (sdConeBound). Its surface is the nappe
// of a^2 |q.xz|^2 = b^2 q.y^2 on which a |q.xz| = -b q.y; the quadratic's roots on the other
// nappe, where a |q.xz| = b q.y, are no crossing. The normal is the gradient of the bound,
// unit wherever |q.xz| > 0.
bool exactCone(vec3 origin, vec3 direction, vec3 apex, vec2 unitSlope, float tMin, int object,
               inout ExactHit hit)
{
    vec3 q = origin - apex;
    float a2 = unitSlope.x * unitSlope.x;
    float b2 = unitSlope.y * unitSlope.y;
    float quadratic = a2 * dot(direction.xz, direction.xz) - b2 * direction.y * direction.y;
    float halfLinear = a2 * dot(q.xz, direction.xz) - b2 * q.y * direction.y;
    float constant = a2 * dot(q.xz, q.xz) - b2 * q.y * q.y;
    float first;
    float second;
    float discriminant = halfLinear * halfLinear - quadratic * constant;
    if (discriminant < 0.0)
        return false;
    // The root that does not cancel, and the other from the product of the roots; a ray
    // parallel to one of the cone's lines (no quadratic term) crosses it once.
    float k = -(halfLinear + (halfLinear >= 0.0 ? sqrt(discriminant) : -sqrt(discriminant)));
    if (abs(quadratic) > 1e-7 * abs(k)) {
        first = k / quadratic;
        second = k != 0.0 ? constant / k : first;
    } else if (k != 0.0) {
        first = second = constant / k;
    } else {
        return false;
    }
    float near = min(first, second);
    float far = max(first, second);
    for (int root = 0; root < 2; ++root) {
        float t = root == 0 ? near : far;
        if (!(t > tMin && t < hit.t))
            continue;
        vec3 at = q + t * direction;
        float radial = length(at.xz);
        if (abs(unitSlope.x * radial + unitSlope.y * at.y) >
            abs(unitSlope.x * radial - unitSlope.y * at.y))
            continue;
        vec2 outward = radial > 0.0 ? at.xz / radial : vec2(0.0);
        hit = ExactHit(t, object,
                       normalize(vec3(unitSlope.x * outward.x, unitSlope.y,
                                      unitSlope.x * outward.y)));
        return true;
    }
    return false;
}

// Torus around the y axis (centre, major radius R, minor radius r): the quartic
// (|p|^2 + R^2 - r^2)^2 = 4 R^2 |p.xz|^2 along the ray, written from the point w of the ray
// nearest the centre, p = w + y d (w perpendicular to d), in units of R + r, so that its
// coefficients stay near 1 however far the ray starts:
//     y^4 + P y^2 + Q y + S = 0,  P = 2k - 4R^2 |d.xz|^2,  Q = -8 R^2 (w.xz . d.xz),
//     S = k^2 - 4 R^2 |w.xz|^2,   k = |w|^2 + R^2 - r^2.
// Ferrari's method: the resolvent U^3 + 2P U^2 + (P^2 - 4S) U - Q^2 = 0 has a root U >= 0,
// and with u = sqrt(U), z = (U + P) / 2 the quartic is the product of
// y^2 - u y + z + Q / (2u) and y^2 + u y + z - Q / (2u). Roots are polished by Newton's
// method on the quartic, and each is checked against the torus's exact distance.
float torusQuarticNewton(float y, float P, float Q, float S)
{
    for (int i = 0; i < 2; ++i) {
        float y2 = y * y;
        float value = (y2 + P) * y2 + Q * y + S;
        float slope = (4.0 * y2 + 2.0 * P) * y + Q;
        if (slope != 0.0)
            y -= value / slope;
    }
    return y;
}

// The roots of y^2 + b y + c = 0 (as near, far), or false.
bool torusQuadraticRoots(float b, float c, out float near, out float far)
{
    float discriminant = 0.25 * b * b - c;
    near = far = 0.0;
    if (discriminant < 0.0)
        return false;
    float root = sqrt(discriminant);
    near = -0.5 * b - root;
    far = -0.5 * b + root;
    return true;
}

// Whether the ray's point at t is truly on the torus (its exact distance there near 0): a
// root of the quartic that float32 left far off (near a tangency) is none.
bool torusCrossingIsReal(float t, vec3 o, vec3 direction, float majorRadius, float minorRadius,
                         float scale)
{
    vec3 p = o + t * direction;
    vec2 radial = vec2(length(p.xz) - majorRadius, p.y);
    return abs(length(radial) - minorRadius) <= 1e-3 * scale;
}

bool exactTorus(vec3 origin, vec3 direction, vec3 center, float majorRadius,
                float minorRadius, float tMin, int object, inout ExactHit hit)
{
    vec3 o = origin - center;
    float scale = majorRadius + minorRadius;
    float along = dot(o, direction);
    vec3 w = (o - along * direction) / scale;
    float wSquared = dot(w, w);
    if (wSquared >= 1.0)
        return false;  // the ray misses the bounding sphere
    float R = majorRadius / scale;
    float r = minorRadius / scale;
    float R2 = R * R;
    float k = wSquared + R2 - r * r;
    float P = 2.0 * k - 4.0 * R2 * dot(direction.xz, direction.xz);
    float Q = -8.0 * R2 * dot(w.xz, direction.xz);
    float S = k * k - 4.0 * R2 * dot(w.xz, w.xz);

    // The resolvent's largest root, from the depressed cubic V^3 + a V + b = 0, U = V - 2P/3.
    float A = 2.0 * P;
    float B = P * P - 4.0 * S;
    float C = -Q * Q;
    float a = B - A * A / 3.0;
    float b = (2.0 * A * A * A) / 27.0 - A * B / 3.0 + C;
    float halfB = 0.5 * b;
    float discriminant = halfB * halfB + a * a * a / 27.0;
    float V;
    if (discriminant >= 0.0) {
        // V = w + w', with w and w' the cube roots of -b/2 +- sqrt(discriminant), whose
        // product is -a/3: one cube root, of the term that does not cancel, gives both.
        float root = sqrt(discriminant);
        float term = halfB > 0.0 ? -halfB - root : -halfB + root;
        float w = sign(term) * pow(abs(term), 1.0 / 3.0);
        V = w != 0.0 ? w - a / (3.0 * w) : 0.0;
    } else {
        float radius = sqrt(-a / 3.0);
        float angle = acos(clamp(-halfB / (radius * radius * radius), -1.0, 1.0));
        V = 2.0 * radius * cos(angle / 3.0);
    }
    float U = V - A / 3.0;
    // Newton's method on the resolvent, whose root float32 Cardano leaves rough.
    for (int i = 0; i < 2; ++i) {
        float value = ((U + A) * U + B) * U + C;
        float slope = (3.0 * U + 2.0 * A) * U + B;
        if (slope != 0.0)
            U -= value / slope;
    }
    U = max(U, 0.0);

    // The quartic's real roots are those of two quadratics y^2 + b y + c: its factors, or, where
    // Q is near 0 (y^4 + P y^2 + S, a quadratic in y^2), y^2 = each root of that quadratic.
    // Both cases feed one loop over the four candidates: on SIMD hardware that runs both sides
    // of a branch (llvmpipe among it), two loops of candidates would cost twice the one.
    float u = sqrt(U);
    vec2 linear;    // b of the two quadratics
    vec2 constant;  // c of the two quadratics
    if (u > 1e-4) {
        float z = 0.5 * (U + P);
        float split = Q / (2.0 * u);
        linear = vec2(-u, u);
        constant = vec2(z + split, z - split);
    } else {
        float low;
        float high;
        bool real = torusQuadraticRoots(P, S, low, high);
        linear = vec2(0.0);
        constant = real ? vec2(-high, -low) : vec2(1.0);  // y^2 + 1: no real root
    }
    vec4 candidates = vec4(FLOAT_MAX);  // the quartic's real roots, unpolished
    float near;
    float far;
    if (torusQuadraticRoots(linear.x, constant.x, near, far))
        candidates.xy = vec2(near, far);
    if (torusQuadraticRoots(linear.y, constant.y, near, far))
        candidates.zw = vec2(near, far);
    // Only the nearest root beyond tMin is polished (Newton's method on the quartic) and
    // checked, and the next one only where that one fails: on SIMD hardware a check written
    // out for each of the four roots costs all four every time, while a loop goes round
    // again only when some ray of the group needs it. Roots more than 1e-3 (in units of
    // R + r) short of tMin are passed over unpolished: polishing moves a root far less.
    float best = hit.t;
    bool found = false;
    float passed = (tMin + along) / scale - 1e-3;
    for (int attempt = 0; attempt < 4; ++attempt) {
        vec4 ahead = mix(vec4(FLOAT_MAX), candidates, greaterThan(candidates, vec4(passed)));
        float y0 = min(min(ahead.x, ahead.y), min(ahead.z, ahead.w));
        if (y0 == FLOAT_MAX)
            break;
        float t = scale * torusQuarticNewton(y0, P, Q, S) - along;
        if (!(t < best))
            break;  // the roots further on are no nearer
        if (t > tMin && torusCrossingIsReal(t, o, direction, majorRadius, minorRadius, scale)) {
            best = t;
            found = true;
            break;
        }
        passed = y0;
    }
    if (!found)
        return false;
    vec3 p = o + best * direction;
    vec3 ring = majorRadius * normalize(vec3(p.x, 0.0, p.z));
    hit = ExactHit(best, object, normalize(p - ring));
    return true;
}

// A user SDF's own intersection (its file's // @intersect function) taken into `hit`: the
// function's result, crossing and outward normal, evaluated first (GLSL evaluates a call's
// arguments from left to right).
bool exactUserCrossing(bool found, float t, vec3 normal, int object, inout ExactHit hit)
{
    if (found)
        hit = ExactHit(t, object, normal);
    return found;
}

// Disk (centre, radius) = vec4 with unit normal n: the ray's crossing of its plane, if it is
// within the radius. It faces the ray.
bool exactDisk(vec3 origin, vec3 direction, vec4 disk, vec3 normal, float tMin, int object,
               inout ExactHit hit)
{
    float rate = dot(normal, direction);
    if (rate == 0.0)
        return false;
    float t = dot(disk.xyz - origin, normal) / rate;
    if (!(t > tMin && t < hit.t))
        return false;
    vec3 fromCenter = origin + t * direction - disk.xyz;
    vec3 inPlane = fromCenter - dot(fromCenter, normal) * normal;
    if (dot(inPlane, inPlane) > disk.w * disk.w)
        return false;
    hit = ExactHit(t, object, rate < 0.0 ? normal : -normal);
    return true;
}
