#!/usr/bin/env python3
"""Plots bench/scaling.sh's CSV as an SVG (no plotting library needed): Mpaths/s and set-up
seconds against the number of objects, both axes logarithmic.

usage: scaling_plot.py scaling.csv scaling.svg
"""
import csv
import math
import sys


def main():
    if len(sys.argv) != 3:
        sys.exit("usage: scaling_plot.py scaling.csv scaling.svg")
    with open(sys.argv[1]) as f:
        rows = [r for r in csv.DictReader(f)]
    if not rows:
        sys.exit("scaling_plot.py: %s holds no rows" % sys.argv[1])
    xs = [float(r["objects"]) for r in rows]
    series = [("Mpaths/s", [float(r["mpaths_per_s"]) for r in rows], "#1f77b4"),
              ("set-up (s)", [float(r["setup_s"]) for r in rows], "#d62728")]
    width, height, left, right, top, bottom = 560, 340, 60, 20, 30, 50
    xlo, xhi = math.floor(math.log10(min(xs))), math.ceil(math.log10(max(xs)))
    values = [v for _, vs, _ in series for v in vs if v > 0]
    ylo, yhi = math.floor(math.log10(min(values))), math.ceil(math.log10(max(values)))

    def px(x):
        return left + (math.log10(x) - xlo) / (xhi - xlo) * (width - left - right)

    def py(y):
        return height - bottom - (math.log10(y) - ylo) / (yhi - ylo) * (height - top - bottom)

    out = ['<svg xmlns="http://www.w3.org/2000/svg" width="%d" height="%d" '
           'font-family="sans-serif" font-size="12">' % (width, height),
           '<rect width="100%" height="100%" fill="white"/>']
    for e in range(xlo, xhi + 1):
        x = px(10 ** e)
        out.append('<line x1="%.1f" y1="%d" x2="%.1f" y2="%d" stroke="#ddd"/>' % (x, top, x, height - bottom))
        out.append('<text x="%.1f" y="%d" text-anchor="middle">%s</text>' % (x, height - bottom + 16, format(10 ** e, ",")))
    for e in range(ylo, yhi + 1):
        y = py(10 ** e)
        out.append('<line x1="%d" y1="%.1f" x2="%d" y2="%.1f" stroke="#ddd"/>' % (left, y, width - right, y))
        out.append('<text x="%d" y="%.1f" text-anchor="end">%g</text>' % (left - 6, y + 4, 10 ** e))
    out.append('<text x="%d" y="%d" text-anchor="middle">objects (a plane and spheres)</text>'
               % ((left + width - right) // 2, height - 12))
    for i, (name, vs, colour) in enumerate(series):
        points = " ".join("%.1f,%.1f" % (px(x), py(v)) for x, v in zip(xs, vs) if v > 0)
        out.append('<polyline points="%s" fill="none" stroke="%s" stroke-width="2"/>' % (points, colour))
        for x, v in zip(xs, vs):
            if v > 0:
                out.append('<circle cx="%.1f" cy="%.1f" r="3.5" fill="%s"/>' % (px(x), py(v), colour))
        out.append('<text x="%d" y="%d" fill="%s">%s</text>' % (left + 10 + 110 * i, top - 10, colour, name))
    out.append("</svg>")
    with open(sys.argv[2], "w") as f:
        f.write("\n".join(out) + "\n")


if __name__ == "__main__":
    main()
