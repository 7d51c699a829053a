#!/usr/bin/python3
"""Draws bench/step-maps.sh's maps: march steps per path by kind of ray, per pixel, and
prints each map's mean, median, 90th and 99th percentile."""

import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

from target_error import read_pfm


def main():
    source, picture, title = sys.argv[1], sys.argv[2], sys.argv[3]
    steps = read_pfm(source)
    figure, axes = plt.subplots(1, 3, figsize=(15, 4.2))
    for channel, kind in enumerate(["camera", "bounce", "shadow"]):
        values = steps[..., channel]
        print(f"{title} {kind}: mean {values.mean():.2f}, median {np.median(values):.2f}, "
              f"p90 {np.percentile(values, 90):.2f}, p99 {np.percentile(values, 99):.2f}")
        image = axes[channel].imshow(values, cmap="magma")
        axes[channel].set_title(f"{title}: {kind} steps per path (mean {values.mean():.1f})")
        axes[channel].axis("off")
        figure.colorbar(image, ax=axes[channel], fraction=0.035)
    figure.tight_layout()
    figure.savefig(picture, dpi=72)


if __name__ == "__main__":
    main()
