#!/usr/bin/python3
"""Tables of bench/time-to-error.sh: relative RMSE against the exact reference and the time
to reach 10 %, 5 % and 2 %, ours against the original. Reads the script's results.csv; the
exact references are SCENE-exact-11.pfm and SCENE-exact-12.pfm beside it.

The reference is the mean of two renders of 1024 spp, and its own noise (a quarter of the
mean squared difference of the two) is taken out of each squared error, so that the error
is the image's own against the true one, not its distance from a noisy reference."""

import csv
import math
import os
import sys

import numpy as np


def read_pfm(path):
    with open(path, "rb") as file:
        header = file.readline().strip()
        width, height = (int(v) for v in file.readline().split())
        scale = float(file.readline())
        channels = 3 if header == b"PF" else 1
        data = np.frombuffer(file.read(), dtype="<f4" if scale < 0 else ">f4")
    return data.reshape(height, width, channels).astype(np.float64)


def time_to(points, target):
    """Seconds at which the error falls to `target`, log-log interpolated; None if never."""
    for (t0, e0), (t1, e1) in zip(points, points[1:]):
        if e0 >= target >= e1:
            f = (math.log(target) - math.log(e0)) / (math.log(e1) - math.log(e0))
            return math.exp(math.log(t0) + f * (math.log(t1) - math.log(t0)))
    if points and points[0][1] <= target:
        return points[0][0]
    return None


def main():
    results, folder = sys.argv[1], sys.argv[2]
    rows = list(csv.DictReader(open(results)))
    targets = (0.10, 0.05, 0.02)
    summary = []
    for scene in sorted({r["scene"] for r in rows}):
        references = [read_pfm(os.path.join(folder, f"{scene}-exact-{s}.pfm")) for s in (11, 12)]
        reference = 0.5 * (references[0] + references[1])
        mean = reference.mean()
        floor_mse = np.mean((references[0] - references[1]) ** 2) / 4.0
        floor = math.sqrt(floor_mse) / mean
        print(f"{scene} (the reference's own noise, taken out: rel RMSE {floor:.4f}; the "
              f"image means: reference {mean:.4f})\n")
        curves = {}
        notes = []

        def error(row):
            # A pixel that is not finite (NaN, infinite) is wrong however it is counted: the
            # error is taken over the others, and the pixels are named.
            image = read_pfm(row["image"])
            finite = np.isfinite(image).all(axis=2)
            if not finite.all():
                notes.append(f"{row['program']}'s image at {row['spp']} spp has "
                             f"{int((~finite).sum())} pixels that are not finite; its error "
                             "is taken over the others")
            squared = ((image - reference) ** 2)[finite]
            return math.sqrt(max(np.mean(squared) - floor_mse, 0.0)) / mean

        for program in ("original", "ours"):
            mine = sorted((r for r in rows if r["scene"] == scene and r["program"] == program),
                          key=lambda r: int(r["spp"]))
            curves[program] = [(float(r["seconds"]), error(r), int(r["spp"])) for r in mine]
            if mine:
                last = read_pfm(mine[-1]["image"])
                means = last[np.isfinite(last).all(axis=2)].mean() / mean - 1.0
                print(f"{program}'s image at {mine[-1]['spp']} spp: mean {100 * means:+.1f} % "
                      "against the reference")
        print()
        print("| spp | original s | original rel RMSE | ours s | ours rel RMSE |")
        print("|---|---|---|---|---|")
        for (to, eo, n), (tu, eu, _) in zip(curves["original"], curves["ours"]):
            print(f"| {n} | {to:.2f} | {eo:.4f} | {tu:.2f} | {eu:.4f} |")
        for note in notes:
            print(f"- {note}")
        print()
        cells = [scene]
        for target in targets:
            for program in ("original", "ours"):
                t = time_to([(t, e) for t, e, _ in curves[program]], target)
                cells.append("never" if t is None else f"{t:.2f} s")
        summary.append(cells)
    header = ["scene"] + [f"{p} to {int(100 * t)} %" for t in targets
                          for p in ("original", "ours")]
    print("| " + " | ".join(header) + " |")
    print("|" + "---|" * len(header))
    for cells in summary:
        print("| " + " | ".join(cells) + " |")
    print("\n(\"never\": the error stays above the target at the largest sample count measured; "
          "a curve that flattens there is bias.)")


if __name__ == "__main__":
    main()
