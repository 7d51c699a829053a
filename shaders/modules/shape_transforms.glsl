// Similarity transforms of shapes: world = R (s local) + T. A shape is evaluated at the
// local point R^T (p - T) / s and its distance scaled back by s, which keeps an exact
// distance exact and a bound a bound (the Lipschitz factor is unchanged).
// Parameters: R's three columns in slots first..first+2, (T, s) in slot first+3.

vec3 toLocalPoint(vec3 p, int first)
{
    vec4 translationAndScale = SHAPE_PARAMETER(first + 3);
    vec3 d = p - translationAndScale.xyz;
    return vec3(dot(SHAPE_PARAMETER(first).xyz, d), dot(SHAPE_PARAMETER(first + 1).xyz, d),
                dot(SHAPE_PARAMETER(first + 2).xyz, d)) /
           translationAndScale.w;
}

float toWorldDistance(float localDistance, int first)
{
    return localDistance * SHAPE_PARAMETER(first + 3).w;
}

vec3 toLocalDirection(vec3 direction, int first)
{
    return vec3(dot(SHAPE_PARAMETER(first).xyz, direction),
                dot(SHAPE_PARAMETER(first + 1).xyz, direction),
                dot(SHAPE_PARAMETER(first + 2).xyz, direction));
}

vec3 toWorldDirection(vec3 local, int first)
{
    return local.x * SHAPE_PARAMETER(first).xyz + local.y * SHAPE_PARAMETER(first + 1).xyz +
           local.z * SHAPE_PARAMETER(first + 2).xyz;
}
