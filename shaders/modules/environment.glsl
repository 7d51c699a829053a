// Radiance of rays that escape the scene. ENVIRONMENT_KIND is fixed by the host for the
// scene; the general shader reads the kind from a uniform instead. The kinds' codes
// (ENVIRONMENT_*) are generated #defines, from scene/Environments.h.

uniform int uEnvironmentKind;
uniform vec3 uEnvironmentColor;

// Read once per pixel, before any branch (see scene_data.glsl): the code below sees copies.
int uEnvironmentKindReadOnce;
vec3 uEnvironmentColorReadOnce;
void readEnvironmentUniformsOnce()
{
    uEnvironmentKindReadOnce = uEnvironmentKind;
    uEnvironmentColorReadOnce = uEnvironmentColor;
}
#define uEnvironmentKind uEnvironmentKindReadOnce
#define uEnvironmentColor uEnvironmentColorReadOnce

vec3 environmentRadiance(vec3 direction)
{
#if ENVIRONMENT_KIND == ENVIRONMENT_KIND_FROM_UNIFORM
    int kind = uEnvironmentKind;
#else
    const int kind = ENVIRONMENT_KIND;
#endif
    if (kind == ENVIRONMENT_SKY)
        // The seed's sky: a gradient in the world's up direction (y), whatever the camera.
        return 0.5 * vec3(0.7, 0.8, 1.0) * (1.0 - 0.5 * direction.y);
    if (kind == ENVIRONMENT_CONSTANT)
        return uEnvironmentColor;
    return vec3(0.0);
}
