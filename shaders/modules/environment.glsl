// Radiance of rays that escape the scene. ENVIRONMENT_KIND is fixed by the host for the
// scene; the general shader reads the kind from a uniform instead. The kinds' codes
// (ENVIRONMENT_*) are generated #defines, from scene/Environments.h.

vec3 environmentRadiance(vec3 direction)
{
#if ENVIRONMENT_KIND == ENVIRONMENT_KIND_FROM_UNIFORM
    int kind = gEnvironmentKind;
#else
    const int kind = ENVIRONMENT_KIND;
#endif
    if (kind == ENVIRONMENT_SKY)
        // The seed's sky: a gradient in the world's up direction (y), whatever the camera.
        return 0.5 * vec3(0.7, 0.8, 1.0) * (1.0 - 0.5 * direction.y);
    if (kind == ENVIRONMENT_CONSTANT)
        return gEnvironmentColor;
    return vec3(0.0);
}
