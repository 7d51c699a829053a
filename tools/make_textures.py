#!/usr/bin/env python3
"""Generates the project's own image textures (textures/*.ppm), deterministically.

    python3 tools/make_textures.py

brick.ppm:  running-bond red bricks with grey mortar and per-brick tone variation.
blur.ppm:   soft overlapping colour blobs (the classic scenes' "blur" texture).
marble.ppm: white marble with grey veins (turbulent value noise), 128x128.
wood.ppm:   brown wood grain with darker growth rings, 128x128.
Brick and blur are 256x256; all are binary PPM (P6) and tileable.
"""
import math
import os
import random

SIZE = 256
HERE = os.path.dirname(os.path.abspath(__file__))
OUT = os.path.join(HERE, "..", "textures")


def write_ppm(name, pixels, size=SIZE):
    path = os.path.join(OUT, name)
    with open(path, "wb") as f:
        f.write(b"P6\n%d %d\n255\n" % (size, size))
        f.write(bytes(pixels))
    print("wrote", os.path.normpath(path))


def clamp8(v):
    return max(0, min(255, int(round(v))))


def brick():
    rng = random.Random(7)
    rows, columns = 8, 4
    brick_h, brick_w = SIZE // rows, SIZE // columns
    tones = {(r, c): rng.uniform(0.75, 1.15) for r in range(rows) for c in range(columns + 1)}
    pixels = []
    for y in range(SIZE):
        row = y // brick_h
        shift = (brick_w // 2) if row % 2 else 0
        for x in range(SIZE):
            xs = (x + shift) % SIZE
            column = xs // brick_w
            in_mortar = (y % brick_h) < 3 or (xs % brick_w) < 3
            grain = rng.uniform(-12, 12)
            if in_mortar:
                v = 165 + grain
                pixels += [clamp8(v), clamp8(v), clamp8(v * 0.97)]
            else:
                t = tones[(row, column)]
                pixels += [clamp8(150 * t + grain), clamp8(62 * t + grain * 0.5),
                           clamp8(45 * t + grain * 0.4)]
    write_ppm("brick.ppm", pixels)


def blur():
    rng = random.Random(11)
    blobs = [(rng.uniform(0, SIZE), rng.uniform(0, SIZE), rng.uniform(25, 70),
              (rng.uniform(0.1, 1.0), rng.uniform(0.1, 1.0), rng.uniform(0.1, 1.0)))
             for _ in range(18)]
    pixels = []
    for y in range(SIZE):
        for x in range(SIZE):
            color = [0.15, 0.15, 0.2]
            for bx, by, radius, tint in blobs:
                # Wrapped distance keeps the texture tileable.
                dx = min(abs(x - bx), SIZE - abs(x - bx))
                dy = min(abs(y - by), SIZE - abs(y - by))
                w = math.exp(-(dx * dx + dy * dy) / (2 * radius * radius))
                for c in range(3):
                    color[c] += 0.6 * w * tint[c]
            pixels += [clamp8(255 * min(1.0, c)) for c in color]
    write_ppm("blur.ppm", pixels)


class PeriodicNoise:
    """Value noise on a lattice of `cells` x `cells` that wraps around, so it tiles."""

    def __init__(self, seed, cells):
        rng = random.Random(seed)
        self.cells = cells
        self.values = [[rng.random() for _ in range(cells)] for _ in range(cells)]

    def __call__(self, u, v):
        # u, v in [0, 1): smoothstep-interpolated lattice values.
        x, y = u * self.cells, v * self.cells
        x0, y0 = int(math.floor(x)), int(math.floor(y))
        fx, fy = x - x0, y - y0
        sx, sy = fx * fx * (3 - 2 * fx), fy * fy * (3 - 2 * fy)
        n = self.cells
        a = self.values[y0 % n][x0 % n]
        b = self.values[y0 % n][(x0 + 1) % n]
        c = self.values[(y0 + 1) % n][x0 % n]
        d = self.values[(y0 + 1) % n][(x0 + 1) % n]
        return (a * (1 - sx) + b * sx) * (1 - sy) + (c * (1 - sx) + d * sx) * sy


def turbulence(octaves, u, v):
    return sum(noise(u, v) / (2 ** i) for i, noise in enumerate(octaves))


def marble(size=128):
    octaves = [PeriodicNoise(23 + i, 4 * 2 ** i) for i in range(4)]
    pixels = []
    for y in range(size):
        for x in range(size):
            u, v = x / size, y / size
            # Veins: a sine across the diagonal, bent by turbulence (Perlin 1985).
            t = math.sin(2 * math.pi * (2 * u + v) + 3.0 * turbulence(octaves, u, v))
            vein = abs(t) ** 0.25
            pixels += [clamp8(255 * (0.45 + 0.48 * vein)), clamp8(255 * (0.45 + 0.47 * vein)),
                       clamp8(255 * (0.47 + 0.46 * vein))]
    write_ppm("marble.ppm", pixels, size)


def wood(size=128):
    fibre = PeriodicNoise(31, 16)
    wobble = PeriodicNoise(37, 4)
    pixels = []
    for y in range(size):
        for x in range(size):
            u, v = x / size, y / size
            # Growth rings as stripes along v, wavy with low-frequency noise; fine fibres on top.
            rings = 9 * u + 0.8 * wobble(u, v)
            ring = 0.5 + 0.5 * math.cos(2 * math.pi * rings)
            tone = 0.75 + 0.25 * ring ** 3 + 0.08 * (fibre(u * 0.25, v) - 0.5)
            pixels += [clamp8(255 * 0.62 * tone), clamp8(255 * 0.40 * tone),
                       clamp8(255 * 0.22 * tone)]
    write_ppm("wood.ppm", pixels, size)


if __name__ == "__main__":
    os.makedirs(OUT, exist_ok=True)
    brick()
    blur()
    marble()
    wood()
