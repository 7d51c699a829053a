// Pinhole camera as the scene format defines it: the film point (i, j) of an image of
// size (w, h) maps to uv = ((2 (i, j) - (w, h)) / h) * tan(fovy / 2) on the plane one unit
// ahead. The frame (right, up, forward) comes orthonormal from the host. A scene whose
// camera has a thin lens (HAS_THIN_LENS) has its rays leave the lens instead of the eye.

uniform vec3 uCameraEye;
uniform vec3 uCameraRight;
uniform vec3 uCameraUp;
uniform vec3 uCameraForward;
uniform float uTanHalfFovy;
uniform vec2 uImageSize;

// Read once per pixel, before any branch (see scene_data.glsl): the code below sees copies.
vec3 uCameraEyeReadOnce;
vec3 uCameraRightReadOnce;
vec3 uCameraUpReadOnce;
vec3 uCameraForwardReadOnce;
float uTanHalfFovyReadOnce;
vec2 uImageSizeReadOnce;
void readCameraUniformsOnce()
{
    uCameraEyeReadOnce = uCameraEye;
    uCameraRightReadOnce = uCameraRight;
    uCameraUpReadOnce = uCameraUp;
    uCameraForwardReadOnce = uCameraForward;
    uTanHalfFovyReadOnce = uTanHalfFovy;
    uImageSizeReadOnce = uImageSize;
}
#define uCameraEye uCameraEyeReadOnce
#define uCameraRight uCameraRightReadOnce
#define uCameraUp uCameraUpReadOnce
#define uCameraForward uCameraForwardReadOnce
#define uTanHalfFovy uTanHalfFovyReadOnce
#define uImageSize uImageSizeReadOnce

vec3 cameraRayDirection(vec2 filmPoint)
{
    vec2 uv = (2.0 * filmPoint - uImageSize) / uImageSize.y * uTanHalfFovy;
    return normalize(uv.x * uCameraRight + uv.y * uCameraUp + uCameraForward);
}

#if HAS_THIN_LENS
uniform float uLensRadius;     // the aperture's radius, world units
uniform float uFocusDistance;  // from the eye to the plane of focus, along the view

// Read once per pixel, before any branch (see scene_data.glsl): the code below sees copies.
float uLensRadiusReadOnce;
float uFocusDistanceReadOnce;
void readLensUniformsOnce()
{
    uLensRadiusReadOnce = uLensRadius;
    uFocusDistanceReadOnce = uFocusDistance;
}
#define uLensRadius uLensRadiusReadOnce
#define uFocusDistance uFocusDistanceReadOnce

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
#else
void readLensUniformsOnce() {}
#endif

// The camera ray through film point `filmPoint`: its origin and unit direction. Through a
// thin lens (PBRT 3e, section 6.2.3) every ray through the film point meets the pinhole's
// ray on the plane of focus, uFocusDistance ahead along the view; it leaves a point of the
// aperture drawn uniformly by the sampler's own lens dimension (sampler.glsl).
void cameraRay(vec2 filmPoint, out vec3 origin, out vec3 direction)
{
    origin = uCameraEye;
    direction = cameraRayDirection(filmPoint);
#if HAS_THIN_LENS
    vec3 focus = uCameraEye + direction * (uFocusDistance / dot(direction, uCameraForward));
    vec2 lens = uLensRadius * concentricDiskPoint(sample2D(SAMPLE_LENS));
    origin = uCameraEye + lens.x * uCameraRight + lens.y * uCameraUp;
    direction = normalize(focus - origin);
#endif
}

// Angle one pixel subtends at the image centre: the spread of a camera ray's cone.
float cameraPixelSpread()
{
    return 2.0 * uTanHalfFovy / uImageSize.y;
}
