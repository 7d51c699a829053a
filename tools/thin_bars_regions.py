"""The denoiser's error on thin geometry, by region: the numbers of docs/ACCURACY.md's
"Denoising" reading for scenes/thin-bars.in.

    ~/.local/share/raytracer/oidn-venv/bin/python tools/thin_bars_regions.py

Run after tools/denoise_report.py has rendered the scene (its renders in
build-denoise/thin-bars/: the 1024-spp reference, raw and denoised at 4 to 256 spp). Splits
the pixels three ways: the bars (any sample met one: a 64-spp render's albedo buffer is not
the wall's white there), the bars' shadows (wall pixels with no bar in or beside them,
darker by 0.02 than the median of their 7x7 neighbourhood in the reference) and the rest
(wall and floor). For each, the mean absolute error of the tone-mapped luminance, raw and
denoised, and the share of pixels denoising made worse; and the shadows' depth, their mean
darkness below that median, which the denoiser takes away.
"""

import os
import re
import subprocess
import sys

import numpy as np
from numpy.lib.stride_tricks import sliding_window_view

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from denoise_report import ROOT, display, read_pfm, render  # noqa: E402

WHITE = 0.8  # the wall's and the floor's pigment
LUMINANCE = np.array([0.2126, 0.7152, 0.0722])


def albedo_of(exr, height, width):
    """The albedo layer of a render file, through oiiotool's text dump."""
    text = subprocess.run(["oiiotool", "--dumpdata", exr, ], capture_output=True, text=True,
                          check=True).stdout
    header = subprocess.run(["oiiotool", "--info", "-v", exr], capture_output=True, text=True,
                            check=True).stdout
    names = re.search(r"channel list: (.*)", header).group(1).split(", ")
    columns = [names.index(f"albedo.{c}") for c in "RGB"]
    albedo = np.zeros((height, width, 3))
    for line in text.splitlines():
        match = re.match(r"\s*Pixel \((\d+), (\d+)\): (.*)", line)
        if match:
            values = match.group(3).split()
            albedo[int(match.group(2)), int(match.group(1))] = [float(values[c])
                                                                for c in columns]
    return albedo


def main():
    scene = os.path.join(ROOT, "scenes", "thin-bars.in")
    work = os.path.join(ROOT, "build-denoise", "thin-bars")
    raytracer = os.path.join(ROOT, "build", "raytracer")
    reference = read_pfm(os.path.join(work, "reference-1024.pfm"))
    height, width, _ = reference.shape
    features = os.path.join(work, "features-64.exr")
    render(raytracer, scene, (width, height), 64, 5, features, ["--feature-buffers"])
    albedo = albedo_of(features, height, width)

    def luminance(image):
        return display(image) @ LUMINANCE

    reference_luminance = luminance(reference)
    padded = np.pad(reference_luminance, 3, mode="edge")
    median = np.median(sliding_window_view(padded, (7, 7)), axis=(-1, -2))
    bars = np.abs(albedo - WHITE).max(axis=2) > 0.01
    beside = np.pad(bars, 1)
    beside = np.max([beside[1 + dy:height + 1 + dy, 1 + dx:width + 1 + dx]
                     for dy in (-1, 0, 1) for dx in (-1, 0, 1)], axis=0)
    shadows = ~beside & (reference_luminance < median - 0.02)
    rest = ~(beside | shadows)
    print(f"pixels: bars {bars.sum()}, shadows {shadows.sum()}, rest {rest.sum()}")
    print("| spp | bars raw | bars denoised | shadows raw | shadows denoised | shadows made "
          "worse | rest raw | rest denoised | shadow depth ref / raw / denoised |")
    print("|---|---|---|---|---|---|---|---|---|")
    for spp in (4, 16, 64, 256):
        raw = luminance(read_pfm(os.path.join(work, f"raw-{spp}.pfm")))
        denoised = luminance(read_pfm(os.path.join(work, f"raw-{spp}.denoised.pfm")))
        raw_error = np.abs(raw - reference_luminance)
        denoised_error = np.abs(denoised - reference_luminance)
        depth = [(median - image)[shadows].mean() for image in (reference_luminance, raw,
                                                                 denoised)]
        worse = 100 * (denoised_error > raw_error)[shadows].mean()
        print(f"| {spp} | {raw_error[bars].mean():.4f} | {denoised_error[bars].mean():.4f} | "
              f"{raw_error[shadows].mean():.4f} | {denoised_error[shadows].mean():.4f} | "
              f"{worse:.0f} % | {raw_error[rest].mean():.4f} | "
              f"{denoised_error[rest].mean():.4f} | "
              f"{depth[0]:.3f} / {depth[1]:.3f} / {depth[2]:.3f} |")


if __name__ == "__main__":
    main()
