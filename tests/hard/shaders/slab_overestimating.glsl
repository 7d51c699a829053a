// A thin slab, 0.04 thick, standing in the yz plane at position x: its exact distance
// multiplied by 4, so the function overestimates by that factor and plain sphere tracing
// steps through the slab. It declares so, and the renderer steps by distance / 4.
// @lipschitz 4
// @bound 1.5

float slab_overestimating(vec3 p, vec3 x)
{
    return 4.0 * sdBox(p - x, vec3(0.02, 1.0, 1.0));
}
