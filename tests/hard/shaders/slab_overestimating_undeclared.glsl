// The same overestimating slab as slab_overestimating.glsl, without declaring it: the
// renderer must be told with --step-scale.
// @bound 1.5

float slab_overestimating_undeclared(vec3 p, vec3 x)
{
    return 4.0 * sdBox(p - x, vec3(0.02, 1.0, 1.0));
}
