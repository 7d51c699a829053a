// The geometry's answers (ray_queries.glsl) by exact intersection, for --exact-geometry: the
// generated exactSceneIntersect finds each object's first crossing in closed form
// (exact_shapes.glsl), so hits lie on the surface itself, to rounding, with the shape's own
// normal, and a ray that passes a silhouette, an edge or a contact however closely goes on
// past it. Rays start on the surface and ignore crossings closer than exactRayStart(). It is
// the independent reference that tells the sphere tracer's geometric error from noise: the
// transport, the sampler and the seed are the same, only this module differs.

// Crossings this close to a ray's origin are the surface it leaves: rounding, at 1e-5 of the
// scene's size (gMinimumHitDistance), keeps every intersection's error far below it.
float exactRayStart()
{
    return 4.0 * gMinimumHitDistance;
}

// The first crossing of the scene's surface, the boundary of the union of its solids, in
// (tMin, tMax). A crossing of one object's surface inside another solid is no surface of the
// union (a hidden face where solids overlap) and is passed; that is a sign test of the exact
// distance functions of these shapes.
ExactHit nearestUnionCrossing(vec3 origin, vec3 direction, float tMin, float tMax)
{
    const int kHiddenFaces = 8;
    float from = tMin;
    for (int face = 0; face < kHiddenFaces && loopIterationAllowed(); ++face) {
        ExactHit hit = ExactHit(tMax, -1, vec3(0.0));
        exactSceneIntersect(origin, direction, from, hit);
        if (hit.object < 0 || !(sceneDistance(origin + hit.t * direction) < -exactRayStart()))
            return hit;
        from = hit.t;
    }
    return ExactHit(tMax, -1, vec3(0.0));
}

SurfaceHit findSurface(vec3 origin, vec3 direction, float insideSign, RayCone cone,
                       float start, int containing)
{
    // No far distance: every finite shape lies well within it, and planes are met however
    // far away (as the traced renderer meets them).
    ExactHit hit = nearestUnionCrossing(origin, direction, start, FLOAT_MAX);
    if (hit.object < 0)
        return noSurfaceHit();
    SurfaceHit surface;
    surface.found = true;
    surface.object = containing >= 0 ? containing : hit.object;
    surface.t = hit.t;
    surface.position = origin + hit.t * direction;
    surface.normal = hit.normal;
    surface.footprint = coneFootprint(cone, hit.t);
    surface.tolerance = exactRayStart();
    return surface;
}

// The next ray starts on the surface itself; which side it travels on follows from the
// direction alone.
bool spawn(vec3 p, vec3 facingNormal, vec3 direction, float tolerance, int object,
           inout float insideSign, out vec3 origin, out float start, out int containing)
{
    if (dot(direction, facingNormal) < 0.0)
        insideSign = -insideSign;
    origin = p;
    start = exactRayStart();
    containing = insideSign < 0.0 ? object : -1;
    return true;
}

vec3 shadowTransmittance(Surface s, vec3 wi, float distance, float insideSign, float tolerance,
                         int target)
{
    const int kMaxShadowCrossings = 32;
    // A point light's segment ends just short of it; a sphere light's just beyond its near
    // side, so that the crossing there is found and recognised as the target.
    float limit = target < 0 ? distance * (1.0 - 1e-6) : distance * (1.0 + 1e-4);
    vec3 transmittance = vec3(1.0);
    float from = exactRayStart();
    for (int crossing = 0; crossing < kMaxShadowCrossings && loopIterationAllowed(); ++crossing) {
        ExactHit hit = nearestUnionCrossing(s.position, wi, from, limit);
        if (hit.object < 0 || hit.object == target)
            return transmittance;
        if (!isNullInterface(hit.object))
            return vec3(0.0);
        transmittance *= pigmentColor(objectPigment(hit.object), s.position + hit.t * wi, -wi,
                                      0.0, 0.0, random01());
        from = hit.t + exactRayStart();
    }
    return vec3(0.0);
}

float cameraMarchStart(ivec2 pixel)
{
    return 0.0;
}
