// The molecule of fig14-smooth-csg-cornell-usersdf.in, the seed's figure 14 written as the
// seed wrote it, in GLSL: four atoms of radius 0.5 at the corners of a tetrahedron, every
// pair joined by a bond of radius 0.175, all blended by the seed's exponential smooth
// minimum -log(e^(-k a) + e^(-k b)) / k with k = 9, as fig14-smooth-csg-cornell.in blends
// them in CSG syntax; turned to show all four atoms. scenes/sdf/lattice.glsl is the same solid
// with the polynomial smooth minimum, for classic scene 6.
// A bound, 1-Lipschitz: the gradient of the smooth minimum is a convex combination of its
// operands' gradients. The smooth minimum swells the solid by at most log(7) / k = 0.22
// beyond the atoms' 1.8 from the centre, inside the bound.
// @bound 2.1

float fig14MoleculeBond(vec3 p, vec3 a, vec3 b, float radius)
{
    vec3 pa = p - a;
    vec3 ba = b - a;
    float along = clamp(dot(pa, ba) / dot(ba, ba), 0.0, 1.0);
    return length(pa - ba * along) - radius;
}

float fig14_molecule(vec3 p, vec3 x)
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
    const float sharpness = 9.0;
    // A regular tetrahedron with its centre at the origin, atoms 1.3 from the centre. Written
    // out rather than looped over an array: software rasterisers run local arrays slowly.
    const float e = 1.3 / 1.7320508;
    const vec3 a = vec3(e, e, e);
    const vec3 b = vec3(e, -e, -e);
    const vec3 c = vec3(-e, e, -e);
    const vec3 d = vec3(-e, -e, e);

    // The exponential smooth minimum of several operands does not depend on their order.
    float atoms = min(min(sdSphere(q - a, atomRadius), sdSphere(q - b, atomRadius)),
                      min(sdSphere(q - c, atomRadius), sdSphere(q - d, atomRadius)));
    float result = opSmoothUnionExp(atoms, fig14MoleculeBond(q, a, b, bondRadius), sharpness);
    result = opSmoothUnionExp(result, fig14MoleculeBond(q, a, c, bondRadius), sharpness);
    result = opSmoothUnionExp(result, fig14MoleculeBond(q, a, d, bondRadius), sharpness);
    result = opSmoothUnionExp(result, fig14MoleculeBond(q, b, c, bondRadius), sharpness);
    result = opSmoothUnionExp(result, fig14MoleculeBond(q, b, d, bondRadius), sharpness);
    result = opSmoothUnionExp(result, fig14MoleculeBond(q, c, d, bondRadius), sharpness);
    return result;
}
