#!/usr/bin/env python3
"""Time to a target error, uniform against adaptive sampling, and the prediction's quality:
reads the renders and logs of bench/target-error.sh, prints a table, and writes the section
"Rendering to a target error" of docs/ACCURACY.md (between <!-- target-error:begin --> and
<!-- target-error:end -->), docs/accuracy/target-error.csv and the sample-count image."""
import argparse
import csv
import datetime
import glob
import os
import platform
import re
import subprocess

import numpy as np

BEGIN = "<!-- target-error:begin -->"
END = "<!-- target-error:end -->"
FRACTIONS = (0.1, 0.25, 0.5)

PROGRESS = re.compile(r"([\d.]+) s elapsed\s+error ([\d.e+-]+) % \(target [\d.e+-]+ %\)"
                      r"(?:, about (\d+) s left)?")
SUMMARY = re.compile(r", (?:([\d.]+) spp on average \((\d+)-(\d+)\)|(\d+) spp) in ([\d.]+) s: "
                     r".*?; error ([\d.e+-]+) % \+- ([\d.e+-]+) % \(target ([\d.e+-]+) %, "
                     r"(\w+) sampling: ([^)]*)\)")


def read_pfm(path):
    """Rows top first, float64, 3 channels."""
    with open(path, "rb") as file:
        if file.readline().strip() != b"PF":
            raise ValueError(f"{path}: not a colour PFM")
        width, height = map(int, file.readline().split())
        scale = float(file.readline())
        data = np.frombuffer(file.read(), "<f4" if scale < 0 else ">f4")
    return data.reshape(height, width, 3)[::-1].astype(np.float64)


def read_log(path):
    text = open(path, "rb").read().decode("utf-8", "replace").replace("\x1b[K", "")
    progress, summary = [], None
    for line in re.split(r"[\r\n]+", text):
        match = PROGRESS.search(line)
        if match:
            left = float(match.group(3)) if match.group(3) else None
            progress.append((float(match.group(1)), float(match.group(2)) / 100, left))
        match = SUMMARY.search(line)
        if match:
            summary = match
    if summary is None:
        raise ValueError(f"{path}: no summary line")
    g = summary.groups()
    return {
        "mean_spp": float(g[0]) if g[0] else float(g[3]),
        "seconds": float(g[4]),
        "estimate": float(g[5]) / 100,
        "uncertainty": float(g[6]) / 100,
        "target": float(g[7]) / 100,
        "reached": g[9] == "reached",
        "progress": progress,
    }


def time_to_target(run):
    """(seconds, extrapolated?), or None where an adaptive render did not get there: the
    render's own time where it got there; for uniform sampling beyond the limit, its error at
    the limit extrapolated by error ~ time^-1/2 (the Monte Carlo rate, which uniform sampling
    follows)."""
    if run["reached"]:
        return run["seconds"], False
    if run["mode"] == "uniform":
        upper = run["estimate"] + 2 * run["uncertainty"]
        return run["seconds"] * (upper / run["target"]) ** 2, True
    return None


def predictions(run):
    """Predicted total time / actual at each fraction of the actual time (first prediction
    made at or after it)."""
    if not run["reached"]:
        return {}
    actual = run["seconds"]
    out = {}
    for fraction in FRACTIONS:
        for elapsed, _, left in run["progress"]:
            if left is not None and elapsed >= fraction * actual:
                out[fraction] = (elapsed + left) / actual
                break
    return out


def uneven(stats):
    """mean(s^2) / mean(s)^2 of the per-sample variance: how many times fewer samples ideal
    adaptive sampling needs than uniform sampling (film/AdaptiveSampling.h)."""
    variance = stats[..., 2] * stats[..., 0]
    return variance.mean() / np.sqrt(variance).mean() ** 2


def measured_error(first, second):
    """Relative RMSE of one render, from two of other seeds: E[(x1 - x2)^2] = 2 E^2 mu^2."""
    a, b = read_pfm(first), read_pfm(second)
    return np.sqrt(np.mean((a - b) ** 2) / 2) / np.mean(0.5 * (a + b))


def count_image(stats_path, picture_path, out, title):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.colors import LogNorm
    counts = read_pfm(stats_path)[..., 0]
    fig, axes = plt.subplots(1, 2, figsize=(9, 3.4))
    axes[0].imshow(np.clip(read_pfm(picture_path) / (1 + read_pfm(picture_path)), 0, 1) ** (1 / 2.2),
                   interpolation="nearest")
    axes[0].set_title("image (adaptive)")
    shown = axes[1].imshow(counts, norm=LogNorm(vmin=max(1, counts.min()), vmax=counts.max()),
                           cmap="magma", interpolation="nearest")
    axes[1].set_title("samples per pixel")
    fig.colorbar(shown, ax=axes[1])
    for axis in axes:
        axis.set_xticks([])
        axis.set_yticks([])
    fig.suptitle(title)
    fig.tight_layout()
    fig.savefig(out, dpi=110)
    plt.close(fig)


def fmt(seconds, extrapolated):
    return ("≈" if extrapolated else "") + (f"{seconds:.1f}" if seconds < 100 else f"{seconds:.0f}")


def table(header, rows):
    lines = ["| " + " | ".join(header) + " |", "|" + "---|" * len(header)]
    lines += ["| " + " | ".join(str(c) for c in row) + " |" for row in rows]
    return "\n".join(lines)


def machine():
    try:
        model = [l.split(":", 1)[1].strip() for l in open("/proc/cpuinfo")
                 if l.startswith("model name")][0]
    except (OSError, IndexError):
        model = platform.processor()
    return f"{model}, {os.cpu_count()} cores, Mesa llvmpipe"


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("folder")
    parser.add_argument("--size", nargs=2, type=int, default=[48, 36])
    parser.add_argument("--limit", default="60")
    parser.add_argument("--markdown")
    parser.add_argument("--image-dir")
    args = parser.parse_args()

    runs = {}
    for log in sorted(glob.glob(os.path.join(args.folder, "*.log"))):
        name = os.path.basename(log)[:-4]
        scene, target, mode, seed = re.match(r"(.+)-([\d.]+)-(adaptive|uniform)-s(\d)$",
                                             name).groups()
        run = read_log(log)
        run.update(scene=scene, mode=mode, path=os.path.join(args.folder, name))
        runs[(scene, target, mode, seed)] = run
    scenes = sorted({k[0] for k in runs})
    targets = sorted({k[1] for k in runs}, key=float, reverse=True)

    rows, csv_rows, prediction_rows, estimate_rows = [], [], [], []
    unevenness = {}
    for scene in scenes:
        for target in targets:
            uniform = runs.get((scene, target, "uniform", "1"))
            adaptive = runs.get((scene, target, "adaptive", "1"))
            second = runs.get((scene, target, "adaptive", "2"))
            if not uniform or not adaptive:
                continue
            unevenness.setdefault(scene, uneven(read_pfm(uniform["path"] + "-stats.pfm")))
            tu, xu = time_to_target(uniform)
            adaptive_time = time_to_target(adaptive)
            if adaptive_time:
                ta, xa = adaptive_time
                speedup = tu / ta
                adaptive_cell = fmt(ta, xa)
                ratio_cell = ("≈" if xu else "") + f"{speedup:.2f}x"
            else:
                ta, speedup = float("nan"), float("nan")
                adaptive_cell = f"> {adaptive['seconds']:.0f} ({100 * adaptive['estimate']:.2f} %)"
                # Neither got there: compare the errors both reached in the same time.
                ratio_cell = (f"not reached; error at the limit: uniform "
                              f"{100 * uniform['estimate']:.2f} %, adaptive "
                              f"{100 * adaptive['estimate']:.2f} %")
            rows.append([scene, f"{100 * float(target):g} %", f"{unevenness[scene]:.1f}",
                         fmt(tu, xu), f"{uniform['mean_spp']:.0f}", adaptive_cell,
                         f"{adaptive['mean_spp']:.0f}", ratio_cell])
            csv_rows.append([scene, target, f"{unevenness[scene]:.3f}", f"{tu:.3f}", int(xu),
                             f"{uniform['mean_spp']:.1f}", f"{ta:.3f}",
                             int(not adaptive["reached"]), f"{adaptive['mean_spp']:.1f}",
                             f"{speedup:.3f}"])
            for run in (uniform, adaptive):
                p = predictions(run)
                if p:
                    prediction_rows.append(
                        [scene, f"{100 * float(target):g} %", run["mode"], f"{run['seconds']:.1f}"]
                        + [f"{p[f]:.2f}" if f in p else "–" for f in FRACTIONS])
            if second and adaptive["reached"] and second["reached"]:
                measured = measured_error(adaptive["path"] + ".pfm", second["path"] + ".pfm")
                estimate_rows.append([scene, f"{100 * float(target):g} %",
                                      f"{100 * adaptive['estimate']:.2f} % ± "
                                      f"{100 * adaptive['uncertainty']:.2f}",
                                      f"{100 * second['estimate']:.2f} %",
                                      f"{100 * measured:.2f} %",
                                      f"{measured / adaptive['estimate']:.2f}"])

    header = ["scene", "target", "mean(s²)/mean(s)²", "uniform s", "uniform spp", "adaptive s",
              "adaptive spp", "uniform / adaptive"]
    print(table(header, rows))
    if args.image_dir:
        os.makedirs(args.image_dir, exist_ok=True)
        with open(os.path.join(args.image_dir, "target-error.csv"), "w", newline="") as file:
            writer = csv.writer(file)
            writer.writerow(["scene", "target", "unevenness", "uniform_seconds",
                             "uniform_extrapolated", "uniform_mean_spp", "adaptive_seconds",
                             "adaptive_not_reached", "adaptive_mean_spp", "speedup"])
            writer.writerows(csv_rows)
        most = max(unevenness, key=unevenness.get)
        target = targets[-1]
        count_image(runs[(most, target, "adaptive", "1")]["path"] + "-stats.pfm",
                    runs[(most, target, "adaptive", "1")]["path"] + ".pfm",
                    os.path.join(args.image_dir, "target-error-samples.png"),
                    f"{most}, target {100 * float(target):g} %, adaptive sampling")
    if not args.markdown:
        return
    width, height = args.size
    section = [BEGIN, "", "## Rendering to a target error", "",
               f"Measured by `bench/target-error.sh` on {datetime.date.today()} on one machine "
               f"({machine()}), {width}x{height}, each render limited to {args.limit} s. "
               "Every scene and target was rendered with adaptive sampling (the default of "
               "`--target-error`; seeds 1 and 2) and with `--uniform-sampling` (seed 1), "
               "alternately. Times are the render's own (the summary line), to the moment its "
               "estimate, two standard deviations up, reached the target. **≈**: the uniform "
               "render hit the time limit first, and its time to the target is extrapolated "
               "from its error at the limit by error ∝ time^−1/2 (the rate uniform sampling "
               "follows). Where the adaptive render hit the limit too, no time is claimed: the "
               "row gives the error each reached in that time (adaptive sampling, aiming at the "
               "final target, samples nearly every pixel until the quiet ones hold their "
               "share, so at equal time before that it is about as good as uniform). "
               "mean(s²)/mean(s)² is how uneven the noise is: the factor by which ideal "
               "per-pixel allocation cuts the samples (film/AdaptiveSampling.h); the time "
               "gain is smaller because the noisy pixels are also the slow ones (glass, "
               "caustics: the Mpaths/s of an adaptive render is 0.5–0.9x a uniform one's).", "",
               table(header, rows), "",
               "### How the error is estimated and the samples placed", "",
               "`--target-error E` stops a batch render once its estimated relative RMSE "
               "(*How it is measured*) is E. Each pixel's variance of the mean, s²/n, comes "
               "from the second moments the renderer accumulates anyway (Welford); their mean "
               "over pixels and channels, square-rooted and divided by the image's mean, is the "
               "expected rel RMSE against the converged image "
               "(`src/film/ConvergenceEstimate.h`). The estimate is itself noisy, and "
               "heavy-tailed where rare bright paths are: its standard deviation is taken from "
               "how much neighbouring pixels' s²/n differ (half their mean squared difference "
               "bounds one pixel's scatter), carried through the square root, with the mean "
               "radiance's own error added. The render stops when the estimate plus two of "
               "those standard deviations is at most E, and only once every pixel holds "
               "`--min-spp` samples (default 32). Bias is not in the estimate: the per-pixel "
               "sections above show it below the noise for the default settings. With Sobol "
               "points the estimate is an upper one (last table).", "",
               "Adaptive sampling gives pixel p a share of samples in proportion to its "
               "standard deviation, n_p = s_p · mean(s) / (E · mean radiance)², the allocation "
               "that reaches the target with the fewest samples "
               "(`src/film/AdaptiveSampling.h`). The s_p are themselves estimates: a pixel "
               "whose own samples understate its noise would stop early with an error the "
               "image's estimate, made from the same samples, does not see. So the share "
               "follows the larger of s_p and the mean s of p's 3x3 neighbourhood, with the "
               "factor recomputed so that the plan still lands on the target (independent "
               "samples, 20 seeds: the error measured against a reference was 1.21x the "
               "estimate on average without it, 1.05x with it). No share is planned before "
               "every pixel holds the minimum; then the plan is remade after every frame from "
               "the estimates so far, a pixel that holds its share returns at once in the "
               "shader, and a frame takes at most a tenth of the predicted time left (and at "
               "least 0.05 s), so that the render stops close under its target. On llvmpipe neighbouring pixels run in 8-wide lockstep, so the plan "
               "can also be made per tile (`--adaptive-tile N`: every pixel of an N x N tile "
               "takes the largest share among them, so whole lane groups stop together). "
               "Measured on scene3 at 80x60 to 10 % (one run each, same machine): uniform "
               "12.2 s, tiles of 8 7.7 s, of 4 5.9 s, of 2 4.2 s, per pixel 2.9 s (per-pixel "
               "shares mean far fewer samples, and the lanes of stopped pixels leave their "
               "group early enough): per pixel is the default. The time left is predicted from "
               "the trend of the estimate (error ∝ time^−a, a fitted on the latter half of the "
               "render so far; 1/2 until there is a trend, which is exact for uniform sampling "
               "and an overestimate for adaptive sampling, whose error falls faster as pixels "
               "stop).", "",
               "### The sample counts", "",
               "![samples per pixel](accuracy/target-error-samples.png)", "",
               "### The prediction", "",
               "The progress line's prediction (elapsed + time left) over the time the render "
               "took, read when 10 %, 25 % and 50 % of that time had passed (1.00 is exact; "
               "renders that reached their target only).", "",
               table(["scene", "target", "sampling", "took s"] +
                     [f"at {int(100 * f)} %" for f in FRACTIONS], prediction_rows), "",
               "### The estimate against the error measured", "",
               "For the adaptive renders that reached their target with both seeds: the "
               "estimate each printed, and the error measured from their difference "
               "(E[(x₁ − x₂)²] = 2E²·mean², needing no reference, no estimate and no model of "
               "the noise). With Sobol points the estimate is an upper one: their error in "
               "smooth pixels falls faster than the sample variance says.", "",
               table(["scene", "target", "seed 1 estimate", "seed 2 estimate", "measured",
                      "measured / estimate"], estimate_rows), "",
               "Regenerate with `bench/target-error.sh` (variables in its header).", "", END]
    text = open(args.markdown).read()
    block = "\n".join(section)
    if BEGIN in text and END in text:
        text = text[:text.index(BEGIN)] + block + text[text.index(END) + len(END):]
    else:
        anchor = "<!-- per-pixel-reading:end -->"
        at = text.index(anchor) + len(anchor) if anchor in text else len(text)
        text = text[:at] + "\n\n" + block + "\n" + text[at:]
    open(args.markdown, "w").write(text)


if __name__ == "__main__":
    main()
