// The seed's molecule (its figure 14): four atoms of radius 0.5 at the corners of a
// tetrahedron, every pair joined by a bond of radius 0.175, bonds blended into the atoms
// by a polynomial smooth minimum of radius 0.35; turned to show all four atoms. A bound,
// 1-Lipschitz. Polynomial rather than the seed's exponential smooth minimum: an exp and a
// log per bond made classic scene 6 2.2 times slower on llvmpipe (0.45 -> 0.20 Mpaths/s at
// 400x300); figure 14's twin, scenes/fig14_molecule.glsl, is this solid with the
// exponential blend of the seed's figure.
// @bound 2.1

float latticeBond(vec3 p, vec3 a, vec3 b, float radius)
{
    vec3 pa = p - a;
    vec3 ba = b - a;
    float along = clamp(dot(pa, ba) / dot(ba, ba), 0.0, 1.0);
    return length(pa - ba * along) - radius;
}

float lattice(vec3 p, vec3 x)
{
    vec3 q = p - x;
    // Turned 63 degrees about y, then about z, so no bond points at the camera.
    const float cosine = cos(0.35 * PI);
    const float sine = sin(0.35 * PI);
    const mat2 turn = mat2(cosine, -sine, sine, cosine);
    q.xz = turn * q.xz;
    q.xy = turn * q.xy;

    const float atomRadius = 0.5;
    const float bondRadius = 0.175;
    const float blend = 0.35;
    // A regular tetrahedron with its centre at the origin, atoms 1.3 from the centre. Written
    // out rather than looped over an array: software rasterisers run local arrays slowly.
    const float e = 1.3 / 1.7320508;
    const vec3 a = vec3(e, e, e);
    const vec3 b = vec3(e, -e, -e);
    const vec3 c = vec3(-e, e, -e);
    const vec3 d = vec3(-e, -e, e);

    float atoms = min(min(sdSphere(q - a, atomRadius), sdSphere(q - b, atomRadius)),
                      min(sdSphere(q - c, atomRadius), sdSphere(q - d, atomRadius)));
    float result = opSmoothUnionPoly(atoms, latticeBond(q, a, b, bondRadius), blend);
    result = opSmoothUnionPoly(result, latticeBond(q, a, c, bondRadius), blend);
    result = opSmoothUnionPoly(result, latticeBond(q, a, d, bondRadius), blend);
    result = opSmoothUnionPoly(result, latticeBond(q, b, c, bondRadius), blend);
    result = opSmoothUnionPoly(result, latticeBond(q, b, d, bondRadius), blend);
    result = opSmoothUnionPoly(result, latticeBond(q, c, d, bondRadius), blend);
    return result;
}
