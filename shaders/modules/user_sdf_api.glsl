// The functions the original program offered to user SDF files (shaders/NAME.glsl), with
// its argument conventions (absolute point, shape position), so that its user files compile
// unchanged. Our own user files may use these or the sd* primitives directly.

float sphere(vec3 p, vec4 centerAndRadius)
{
    return sdSphere(p - centerAndRadius.xyz, centerAndRadius.w);
}

float plane(vec3 p, vec4 coefficients)
{
    return dot(vec4(p, 1.0), coefficients) / length(coefficients.xyz);
}

float box(vec3 p, vec3 center, vec3 halfExtents)
{
    return sdBox(p - center, halfExtents);
}

float torus(vec3 p, vec3 center, vec2 radii)
{
    return sdTorus(p - center, radii.x, radii.y);
}

float cone(vec3 p, vec3 apex, vec2 slope)
{
    return sdConeBound(p - apex, normalize(slope));
}

float cylinder(vec3 p, vec3 center, vec2 radiusAndHalfHeight)
{
    return sdCappedCylinder(p - center, radiusAndHalfHeight.x, radiusAndHalfHeight.y);
}

float disk(vec3 p, vec3 center, vec3 normal, float radius)
{
    return sdDisk(p - center, normalize(normal), radius);
}
