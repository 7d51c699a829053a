#!/usr/bin/env python3
"""Generates the project's own image textures (textures/*.ppm), deterministically.

    python3 tools/make_textures.py

brick.ppm: running-bond red bricks with grey mortar and per-brick tone variation.
blur.ppm:  soft overlapping colour blobs (the classic scenes' "blur" texture).
Both 256x256, binary PPM (P6), tileable.
"""
import math
import os
import random

SIZE = 256
HERE = os.path.dirname(os.path.abspath(__file__))
OUT = os.path.join(HERE, "..", "textures")


def write_ppm(name, pixels):
    path = os.path.join(OUT, name)
    with open(path, "wb") as f:
        f.write(b"P6\n%d %d\n255\n" % (SIZE, SIZE))
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


if __name__ == "__main__":
    os.makedirs(OUT, exist_ok=True)
    brick()
    blur()
