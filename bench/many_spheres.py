#!/usr/bin/env python3
"""Writes a scene of N spheres of random sizes resting on a plane under one point light
(bench/scaling.sh's scenes, issue 33). The spheres fill the same square whatever N is, their
radii shrinking as 1/sqrt(N), so every scene covers about the same share of the image and
Mpaths/s measure the cost of finding surfaces among more objects, not a different picture.

With --marched F, a fraction F of the balls (every round(1/F)-th) are rounded boxes of the
same size instead, which rays march (the weak case of docs/PERFORMANCE.md's "Scenes of many
objects"); the positions and sizes are the same as without.

usage: many_spheres.py N [SEED] [--marched F] > scene.in
"""
import random
import sys


def main():
    usage = ("usage: many_spheres.py N [SEED] [--marched F]   (N: objects, a whole number >= 1;"
             " F: the fraction of them that are marched rounded boxes, 0 to 1)")
    args = sys.argv[1:]
    marched = 0.0
    if "--marched" in args:
        at = args.index("--marched")
        try:
            marched = float(args[at + 1])
        except (IndexError, ValueError):
            sys.exit(usage)
        if not 0.0 <= marched <= 1.0:
            sys.exit(usage)
        del args[at:at + 2]
    if not args or len(args) > 2 or not all(a.isdigit() for a in args) or int(args[0]) < 1:
        sys.exit(usage)
    count = int(args[0])
    rng = random.Random(int(args[1]) if len(args) > 1 else 33)
    every = round(1.0 / marched) if marched > 0.0 else 0
    half = 10.0                      # the square's half side
    spacing = 2.0 * half / count ** 0.5
    out = sys.stdout
    out.write("# %d spheres of random sizes on a plane, one point light (bench/many_spheres.py)\n" % count)
    out.write("0 9 17\n0 0 -1\n0 1 0\n45\n")           # eye, look-at, up, field of view
    out.write("1\n4 14 8  900 900 900\n")              # one point light
    out.write("4\nsolid 0.75 0.75 0.75\nsolid 0.7 0.25 0.2\nsolid 0.2 0.45 0.7\nsolid 0.6 0.6 0.3\n")
    out.write("1\n0 0 0 0 0 0 0\n")                    # one Lambertian finish
    out.write("%d\n" % count)
    out.write("0 0 polyhedron 1  0 1 0 0\n")           # the floor, y = 0
    for i in range(count - 1):
        radius = spacing * rng.uniform(0.1, 0.45)
        x = rng.uniform(-half, half)
        z = rng.uniform(-half, half)
        pigment = rng.randrange(1, 4)
        if every and i % every == 0:
            out.write("%d 0 rounded_box %.5f %.5f %.5f  %.5f %.5f %.5f  %.5f\n"
                      % (pigment, x, radius, z, radius, radius, radius, 0.3 * radius))
        else:
            out.write("%d 0 sphere %.5f %.5f %.5f %.5f\n" % (pigment, x, radius, z, radius))


if __name__ == "__main__":
    main()
