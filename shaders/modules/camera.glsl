// Pinhole camera as the scene format defines it: the film point (i, j) of an image of
// size (w, h) maps to uv = ((2 (i, j) - (w, h)) / h) * tan(fovy / 2) on the plane one unit
// ahead. The frame (right, up, forward) comes orthonormal from the host.

vec3 cameraRayDirection(vec2 filmPoint)
{
    vec2 uv = (2.0 * filmPoint - gImageSize) / gImageSize.y * gTanHalfFovy;
    return normalize(uv.x * gCameraRight + uv.y * gCameraUp + gCameraForward);
}

// Angle one pixel subtends at the image centre: the spread of a camera ray's cone.
float cameraPixelSpread()
{
    return 2.0 * gTanHalfFovy / gImageSize.y;
}
