// What the light transport asks of the geometry, and nothing more. Two modules answer it:
// ray_queries_traced.glsl by sphere tracing the scene's distance functions (every render),
// and ray_queries_exact.glsl by intersecting the shapes that have a closed form
// analytically (--exact-geometry, the independent reference for the sphere tracer's
// geometric error). The integrator, the lights and the materials are the same for both, so
// two renders that differ in this module alone, with one seed, differ by geometry only.
//
// Each module defines:
//
//   SurfaceHit findSurface(vec3 origin, vec3 direction, float insideSign, RayCone cone,
//                          float start, int containing)
//       The first surface the ray meets at or beyond `start` along it: where (on the
//       surface), which object, and its outward normal. `insideSign` is -1 for a ray that
//       travels inside the solid `containing` (which it can then only leave).
//
//   bool spawn(vec3 p, vec3 facingNormal, vec3 direction, float tolerance, int object,
//              inout float insideSign, out vec3 origin, out float start, out int containing)
//       The next ray from point p on the surface of `object` along `direction`: where it
//       starts and how far along it the next findSurface may begin, which side of the
//       surface it travels on (`facingNormal` points to the side the path arrived from) and
//       the solid it starts in. False where no ray can leave p that way (the path ends).
//
//   vec3 shadowTransmittance(Surface s, vec3 wi, float distance, float insideSign,
//                            float tolerance, int target)
//       The fraction of light arriving at surface point s.position from `distance` away
//       along unit `wi`: zero when something blocks it, the tint of any index-1 dielectric
//       it passes through. `target` is the object at the far end (a sphere light), or -1.
//
//   float cameraMarchStart(ivec2 pixel)
//       How far along every camera ray through `pixel` findSurface may begin.

struct SurfaceHit {
    bool found;
    int object;
    float t;          // along the ray
    vec3 position;    // on the surface
    vec3 normal;      // the object's outward normal there, unit
    float footprint;  // the width of the ray's cone there
    float tolerance;  // the hit tolerance there, which the next ray's offsets follow
};

SurfaceHit noSurfaceHit()
{
    return SurfaceHit(false, -1, 0.0, vec3(0.0), vec3(0.0), 0.0, 0.0);
}

// Where the camera is: inside which solid (-1 outside every one). A ray inside a solid can
// only leave that solid: where another surface touches it (glass resting on a floor), a hit
// within the tolerance of both is the solid's.
int cameraContainingObject()
{
    int containing;
    return sceneDistanceAndObject(gCameraEye, containing) < 0.0 ? containing : -1;
}

