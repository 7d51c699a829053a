// The seed's molecule (its figure 14): four atoms of radius 0.5 at the corners of a
// tetrahedron, every pair joined by a bond of radius 0.175, bonds blended into the atoms
// by a polynomial smooth minimum of radius 0.35; turned to show all four atoms. A bound,
// 1-Lipschitz. Polynomial rather than the seed's exponential smooth minimum: an exp and a
// log per bond made classic scene 6 2.2 times slower on llvmpipe (0.45 -> 0.20 Mpaths/s at
// 400x300); figure 14's twin, scenes/fig14_molecule.glsl, is this solid with the
// exponential blend of the seed's figure. The atoms' far sides are 1.3 + 0.5 from the
// centre, and the blends lie between atoms: every point of the surface is within 1.8 of it
// (20 000 directions sampled on the CPU reached 1.801 at most), and the bound declares 1.85.
// The ball is more than twice the molecule's volume: the surface also lies within 0.51 of the
// tetrahedron of the atoms' centres (its faces 1.3 / 3 from the centre, their outward normals
// those of the turned atoms, negated; 12 million points sampled around the atoms, 0.5010 at
// most beyond a face), and the four planes below (0.97 = 0.4333 + 0.5367 beyond each face)
// leave rays that pass the ball but not the molecule out of their marches.
// @bound 1.85
// @hull  0.6289698 -0.7765344 -0.0373005 0.97
// @hull -0.8669621 -0.2523113 -0.4297857 0.97
// @hull -0.1618836  0.2523113  0.9540087 0.97
// @hull  0.3998759  0.7765344 -0.4869226 0.97
// @hull  0.2061074  0.8910065  0.4045085 1.29
// @hull -0.2061074 -0.8910065 -0.4045085 1.29
// @hull -0.4045085  0.4539905 -0.7938926 1.29
// @hull  0.4045085 -0.4539905  0.7938926 1.29
// @hull -0.8910065  0.0000000  0.4539905 1.29
// @hull  0.8910065  0.0000000 -0.4539905 1.29

// The distance from p to the bond from a to b, of the lattice's bond radius. Every bond has
// the same length, the tetrahedron's edge 2 sqrt(2) e for atoms e (1, 1, 1) from the centre:
// the projection multiplies by its inverse square instead of dividing.
const float kLatticeCorner = 1.3 / 1.7320508;
const float kLatticeInverseBondLengthSquared = 1.0 / (8.0 * kLatticeCorner * kLatticeCorner);
float latticeBond(vec3 p, vec3 a, vec3 b)
{
    vec3 pa = p - a;
    vec3 bond = b - a;
    float along = clamp(dot(pa, bond) * kLatticeInverseBondLengthSquared, 0.0, 1.0);
    return length(pa - bond * along) - 0.175;
}

// The atoms turned 63 degrees about z, then about y (the point's turns about y then z,
// undone), so no bond points at the camera: the turn is applied to four constants instead of
// to every point.
const float kLatticeCosine = 0.45399049974;  // cos(0.35 pi)
const float kLatticeSine = 0.89100652419;    // sin(0.35 pi)
vec3 latticeAtom(vec3 atom)
{
    // The inverse of q.xz = turn * q.xz followed by q.xy = turn * q.xy, turn = ((c, -s), (s, c))
    // in GLSL's column order: first xy, then xz, each by the transpose.
    mat2 back = mat2(kLatticeCosine, kLatticeSine, -kLatticeSine, kLatticeCosine);
    atom.xy = back * atom.xy;
    atom.xz = back * atom.xz;
    return atom;
}

float lattice(vec3 p, vec3 x)
{
    vec3 q = p - x;
    const float atomRadius = 0.5;
    const float blend = 0.35;
    // A regular tetrahedron with its centre at the origin, atoms 1.3 from the centre. Written
    // out rather than looped over an array: software rasterisers run local arrays slowly.
    const float e = kLatticeCorner;
    vec3 a = latticeAtom(vec3(e, e, e));
    vec3 b = latticeAtom(vec3(e, -e, -e));
    vec3 c = latticeAtom(vec3(-e, e, -e));
    vec3 d = latticeAtom(vec3(-e, -e, e));

    // The nearest atom's centre, by squared distances: one square root instead of four.
    vec3 pa = q - a;
    vec3 pb = q - b;
    vec3 pc = q - c;
    vec3 pd = q - d;
    float result = sqrt(min(min(dot(pa, pa), dot(pb, pb)), min(dot(pc, pc), dot(pd, pd)))) -
                   atomRadius;
    result = opSmoothUnionPoly(result, latticeBond(q, a, b), blend);
    result = opSmoothUnionPoly(result, latticeBond(q, a, c), blend);
    result = opSmoothUnionPoly(result, latticeBond(q, a, d), blend);
    result = opSmoothUnionPoly(result, latticeBond(q, b, c), blend);
    result = opSmoothUnionPoly(result, latticeBond(q, b, d), blend);
    result = opSmoothUnionPoly(result, latticeBond(q, c, d), blend);
    return result;
}
