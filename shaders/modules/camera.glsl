// Pinhole camera as the scene format defines it: the film point (i, j) of an image of
// size (w, h) maps to uv = ((2 (i, j) - (w, h)) / h) * tan(fovy / 2) on the plane one unit
// ahead. The frame (right, up, forward) comes orthonormal from the host. A scene whose
// camera has a thin lens (HAS_THIN_LENS) has its rays leave the lens instead of the eye.

vec3 cameraRayDirection(vec2 filmPoint)
{
    vec2 uv = (2.0 * filmPoint - gImageSize) / gImageSize.y * gTanHalfFovy;
    return normalize(uv.x * gCameraRight + uv.y * gCameraUp + gCameraForward);
}

#if HAS_THIN_LENS
// Shirley and Chiu's concentric map of the unit square onto the unit disk ("A Low
// Distortion Map Between Disk and Square", 1997): uniform on the disk, and it keeps the
// stratification of the sampler's points, which a polar map would crowd at the centre.
vec2 concentricDiskPoint(vec2 u)
{
    vec2 p = 2.0 * u - 1.0;
    if (p.x == 0.0 && p.y == 0.0)
        return vec2(0.0);
    float radius;
    float phi;
    if (abs(p.x) > abs(p.y)) {
        radius = p.x;
        phi = (PI / 4.0) * (p.y / p.x);
    } else {
        radius = p.y;
        phi = PI / 2.0 - (PI / 4.0) * (p.x / p.y);
    }
    return radius * vec2(cos(phi), sin(phi));
}
#endif

// The camera ray through film point `filmPoint`: its origin and unit direction. Through a
// thin lens (PBRT 3e, section 6.2.3) every ray through the film point meets the pinhole's
// ray on the plane of focus, gFocusDistance ahead along the view; it leaves a point of the
// aperture drawn uniformly by the sampler's own lens dimension (sampler.glsl).
void cameraRay(vec2 filmPoint, out vec3 origin, out vec3 direction)
{
    origin = gCameraEye;
    direction = cameraRayDirection(filmPoint);
#if HAS_THIN_LENS
    vec3 focus = gCameraEye + direction * (gFocusDistance / dot(direction, gCameraForward));
    vec2 lens = gLensRadius * concentricDiskPoint(sample2D(SAMPLE_LENS));
    origin = gCameraEye + lens.x * gCameraRight + lens.y * gCameraUp;
    direction = normalize(focus - origin);
#endif
}

// Angle one pixel subtends at the image centre: the spread of a camera ray's cone.
float cameraPixelSpread()
{
    return 2.0 * gTanHalfFovy / gImageSize.y;
}
