// Pinhole camera as the scene format defines it: the film point (i, j) of an image of
// size (w, h) maps to uv = ((2 (i, j) - (w, h)) / h) * tan(fovy / 2) on the plane one unit
// ahead. The frame (right, up, forward) comes orthonormal from the host.

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

// Angle one pixel subtends at the image centre: the spread of a camera ray's cone.
float cameraPixelSpread()
{
    return 2.0 * uTanHalfFovy / uImageSize.y;
}
