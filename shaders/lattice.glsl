// The seed's molecule (its figure 14): four atoms of radius 0.5 at the corners of a
// tetrahedron, every pair joined by a bond of radius 0.175, bonds blended into the atoms
// by a polynomial smooth minimum of radius 0.35; turned to show all four atoms. A bound,
// 1-Lipschitz.
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
    float c = cos(0.35 * PI);
    float s = sin(0.35 * PI);
    q.xz = mat2(c, -s, s, c) * q.xz;
    q.xy = mat2(c, -s, s, c) * q.xy;

    const float atomRadius = 0.5;
    const float bondRadius = 0.175;
    const float blend = 0.35;
    // A regular tetrahedron with its centre at the origin, atoms 1.3 from the centre.
    const float e = 1.3 / 1.7320508;
    vec3 atoms[4] = vec3[4](vec3(e, e, e), vec3(e, -e, -e), vec3(-e, e, -e), vec3(-e, -e, e));

    float d = FLOAT_MAX;
    for (int i = 0; i < 4; ++i)
        d = min(d, sdSphere(q - atoms[i], atomRadius));
    for (int i = 0; i < 4; ++i)
        for (int j = i + 1; j < 4; ++j)
            d = opSmoothUnionPoly(d, latticeBond(q, atoms[i], atoms[j], bondRadius), blend);
    return d;
}
