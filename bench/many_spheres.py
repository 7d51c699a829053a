#!/usr/bin/env python3
"""Writes a scene of N spheres of random sizes resting on a plane under one point light
(bench/scaling.sh's scenes, issue 33). The spheres fill the same square whatever N is, their
radii shrinking as 1/sqrt(N), so every scene covers about the same share of the image and
Mpaths/s measure the cost of finding surfaces among more objects, not a different picture.

usage: many_spheres.py N [SEED] > scene.in
"""
import random
import sys


def main():
    if len(sys.argv) < 2 or not sys.argv[1].isdigit() or int(sys.argv[1]) < 1:
        sys.exit("usage: many_spheres.py N [SEED]   (N: spheres, a whole number >= 1)")
    count = int(sys.argv[1])
    rng = random.Random(int(sys.argv[2]) if len(sys.argv) > 2 else 33)
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
    for _ in range(count - 1):
        radius = spacing * rng.uniform(0.1, 0.45)
        x = rng.uniform(-half, half)
        z = rng.uniform(-half, half)
        out.write("%d 0 sphere %.5f %.5f %.5f %.5f\n" % (rng.randrange(1, 4), x, radius, z, radius))


if __name__ == "__main__":
    main()
