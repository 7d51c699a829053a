#!/usr/bin/python3
"""Writes docs/ACCURACY.md and its plots from the CSVs bench_convergence wrote (issue 7).

    /usr/bin/python3 tools/accuracy_report.py DATA_DIR MARKDOWN --configuration NAME
                                              --command TEXT [--note TEXT]

DATA_DIR holds run.csv, references.csv, convergence.csv, settings.csv and equal_time.csv
(bench/convergence.cpp documents every column); the plots are written beside them as PNG and
MARKDOWN links to them relative to its own folder. Needs matplotlib and numpy (Debian's
python3-matplotlib and python3-numpy; tools/accuracy-report.sh installs them), hence the
interpreter /usr/bin/python3 rather than whatever python3 comes first on PATH.
"""

import argparse
import csv
import math
import os
import statistics

import matplotlib

matplotlib.use("Agg")  # files only, no display
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

# An error this many times the noise of image and reference together is taken as bias.
# The noise estimates come from one render each and relative MSE is heavy-tailed (one
# firefly can double it), so a factor under 1.5 is read as "within noise".
BIAS_RATIO = 1.5
# A brightness difference beyond this many standard deviations of its noise is bias.
BRIGHTNESS_SIGMAS = 3.0
# Convergence points whose error is below this multiple of the reference's own noise are
# left out of the slope fit: there the curve flattens on the reference's noise, not on bias.
FLOOR_MARGIN = 4.0

# What each setting trades, for the reading; the renderer's sources say why (file named).
SETTING_NOTES = {
    "hit-tolerance": (
        "sphere-tracing hit tolerance, as a fraction of the pixel's ray-cone footprint "
        "(shaders/modules/sphere_tracing.glsl). Larger: fewer steps near surfaces, but hits "
        "are accepted farther from the surface, shadow and bounce rays start farther off it "
        "(twice the tolerance), and thin gaps close."),
    "max-steps": (
        "step limit of every march, camera, bounce and shadow ray alike. A ray that runs "
        "out of steps near a surface counts as a hit there, one far from everything as a "
        "miss (sphere_tracing.glsl), and a shadow ray that runs out counts as blocked "
        "(lights.glsl)."),
    "max-bounces": (
        "scattering events per path (shaders/modules/integrator.glsl). Fewer: shorter "
        "paths, the light of the longer ones is missing (1 = direct light only)."),
    "rr-depth": (
        "scattering events before Russian roulette may end a path. Unbiased at any value "
        "(survivors are reweighted); it trades time per path against noise per path."),
    "over-relaxation": (
        "Keinert et al.'s over-relaxation factor for sphere tracing; 1 is plain sphere "
        "tracing. A failed relaxed step is undone, so it should change time, not the image."),
    "step-scale": (
        "every march step multiplied by this (for user SDFs that overestimate). Below 1 the "
        "steps are shorter: slower, and with the same tolerance the same surfaces."),
    "mis": (
        "multiple importance sampling of sphere lights (power heuristic) versus light "
        "sampling alone. Unbiased either way; it changes noise, and only where sphere lights "
        "are seen by non-delta surfaces."),
    "fresnel": (
        "dielectric Fresnel term: Schlick's approximation (the seed's and the default) or "
        "the exact dielectric equations. Only scenes with glass are affected; the exact one "
        "is the physically right one, so a difference here is the default's bias."),
}


def read_csv(path):
    if not os.path.exists(path):
        return []
    with open(path, newline="") as file:
        return list(csv.DictReader(file))


def number(row, key):
    value = row.get(key, "")
    return float(value) if value not in ("", None) else math.nan


def scene_order(rows):
    names = []
    for row in rows:
        if row["scene"] not in names:
            names.append(row["scene"])
    return names


def fmt(value, digits=3):
    if value is None or (isinstance(value, float) and math.isnan(value)):
        return "–"
    if value == 0:
        return "0"
    magnitude = abs(value)
    if magnitude >= 1000 or magnitude < 0.001:
        return f"{value:.{digits - 1}e}"
    return f"{value:.{digits}g}"


def percent(value):
    return "–" if math.isnan(value) else f"{100 * value:+.1f} %"


def fit_slope(xs, ys):
    """Least-squares slope of log y against log x; None with fewer than three points."""
    if len(xs) < 3:
        return None
    slope, _ = np.polyfit(np.log(xs), np.log(ys), 1)
    return float(slope)


def colours(names):
    palette = plt.get_cmap("tab10")
    return {name: palette(i % 10) for i, name in enumerate(names)}


# ----------------------------------------------------------------------------------------
# Convergence

def convergence_summary(rows):
    """Per scene: the slope of relative MSE against time and spp, and what bends it."""
    summary = {}
    for name in scene_order(rows):
        points = [r for r in rows if r["scene"] == name]
        reference_noise = number(points[0], "reference_rel_mse_noise")
        fitted = [r for r in points
                  if int(r["spp"]) >= 2 and number(r, "rel_mse") > FLOOR_MARGIN * reference_noise]
        seconds = [number(r, "seconds") for r in fitted]
        spp = [int(r["spp"]) for r in fitted]
        error = [number(r, "rel_mse") for r in fitted]
        tone = [number(r, "tone_rmse") for r in fitted]
        # Error over the noise the two images carry: 1 when the render and the reference
        # agree but for noise (same settings, other seed), as they must.
        ratios = [number(r, "rel_mse") / (number(r, "rel_mse_noise") + reference_noise)
                  for r in points if r["rel_mse_noise"]]
        # relative MSE x spp is constant at the Monte Carlo rate; growing, it says the
        # later samples caught rare bright paths the earlier ones had not.
        per_sample = [e * s for e, s in zip(error, spp)]
        last = points[-1]
        summary[name] = {
            "points": points,
            "fit_spp": spp,
            "slope_time": fit_slope(seconds, error),
            "slope_spp": fit_slope(spp, error),
            "slope_tone_time": fit_slope(seconds, tone),
            "noise_ratio": statistics.median(ratios) if ratios else math.nan,
            "per_sample_growth": (per_sample[-1] / per_sample[0] if len(per_sample) >= 2
                                  else math.nan),
            "reference_noise": reference_noise,
            "floor_reached": len(fitted) < len([r for r in points if int(r["spp"]) >= 2]),
            "mpaths": number(last, "mpaths_per_s"),
            "cpu_per_wall": number(last, "cpu_seconds") / number(last, "seconds"),
            "compile": number(last, "compile_seconds"),
            "warmup": number(last, "warmup_seconds"),
            "first": points[0],
            "last": last,
        }
    return summary


def plot_convergence(rows, summary, data_dir, metric, ylabel, guide_slope, filename):
    names = scene_order(rows)
    colour = colours(names)
    columns = 4
    rows_of_plots = math.ceil(len(names) / columns)
    figure, axes = plt.subplots(rows_of_plots, columns, figsize=(4 * columns, 3.4 * rows_of_plots),
                                squeeze=False)
    for index, name in enumerate(names):
        axis = axes[index // columns][index % columns]
        points = summary[name]["points"]
        seconds = np.array([number(r, "seconds") for r in points])
        values = np.array([number(r, metric) for r in points])
        axis.loglog(seconds, values, "o-", color=colour[name], label="measured")
        noise_key = metric + "_noise"
        noise = [(number(r, "seconds"), number(r, noise_key)) for r in points if r[noise_key]]
        if noise:
            axis.loglog(*zip(*noise), "x", color="grey", label="its own noise")
        # The Monte Carlo rate through the measured points' geometric centre.
        centre_x = math.exp(np.mean(np.log(seconds)))
        centre_y = math.exp(np.mean(np.log(values)))
        guide_x = np.array([seconds.min(), seconds.max()])
        axis.loglog(guide_x, centre_y * (guide_x / centre_x) ** guide_slope, "k:",
                    label=f"slope {guide_slope:g}")
        reference_noise = number(points[0], "reference_" + noise_key)
        axis.axhline(reference_noise, color="tab:red", linestyle="--", linewidth=1,
                     label="reference's noise")
        slope = summary[name]["slope_time" if metric == "rel_mse" else "slope_tone_time"]
        axis.set_title(f"{name}: slope {fmt(slope, 2)}" if slope is not None else name)
        axis.set_xlabel("render time (s)")
        axis.set_ylabel(ylabel)
        axis.grid(True, which="both", alpha=0.3)
        if index == 0:
            axis.legend(fontsize=7)
    for index in range(len(names), rows_of_plots * columns):
        axes[index // columns][index % columns].axis("off")
    figure.tight_layout()
    figure.savefig(os.path.join(data_dir, filename), dpi=100)
    plt.close(figure)


def plot_convergence_overview(rows, summary, data_dir, filename):
    names = scene_order(rows)
    colour = colours(names)
    figure, (by_time, by_spp) = plt.subplots(1, 2, figsize=(12, 4.5))
    for name in names:
        points = summary[name]["points"]
        seconds = [number(r, "seconds") for r in points]
        spp = [int(r["spp"]) for r in points]
        error = [number(r, "rel_mse") for r in points]
        by_time.loglog(seconds, error, "o-", color=colour[name], label=name, markersize=3)
        by_spp.loglog(spp, error, "o-", color=colour[name], label=name, markersize=3)
    for axis, xlabel in ((by_time, "render time (s)"), (by_spp, "samples per pixel")):
        x_low, x_high = axis.get_xlim()
        y_low, y_high = axis.get_ylim()
        # A slope -1 guide from the upper left, where it crosses the curves.
        guide_x = np.array([x_low * 1.5, x_high / 1.5])
        start_y = math.sqrt(y_low * y_high) * 10
        axis.loglog(guide_x, start_y * (guide_x / guide_x[0]) ** -1.0, "k:", label="slope -1")
        axis.set_xlabel(xlabel)
        axis.set_ylabel("relative MSE")
        axis.grid(True, which="both", alpha=0.3)
    by_time.set_title("error against render time")
    by_spp.set_title("error against samples per pixel")
    by_spp.legend(fontsize=8)
    figure.tight_layout()
    figure.savefig(os.path.join(data_dir, filename), dpi=100)
    plt.close(figure)


# ----------------------------------------------------------------------------------------
# Settings

def setting_rows(rows, setting):
    return [r for r in rows if r["setting"] == setting]


def settings_order(rows):
    names = []
    for row in rows:
        if row["setting"] not in names:
            names.append(row["setting"])
    return names


def noise_of(row):
    return number(row, "rel_mse_noise") + number(row, "reference_rel_mse_noise")


def judge(row):
    """'same', 'bias' or 'noise': what the error of a setting's render is made of."""
    if row["is_default"] != "1" and row["same_image_as_default"] == "1":
        return "same"
    ratio = number(row, "rel_mse") / noise_of(row)
    brightness = abs(number(row, "brightness_bias"))
    brightness_noise = number(row, "brightness_noise")
    if ratio >= BIAS_RATIO or brightness > BRIGHTNESS_SIGMAS * brightness_noise:
        return "bias"
    return "noise"


def default_row(rows, scene):
    for row in rows:
        if row["scene"] == scene and row["is_default"] == "1":
            return row
    return None


def plot_setting(rows, setting, data_dir):
    points = setting_rows(rows, setting)
    names = scene_order(points)
    colour = colours(scene_order(rows))
    labels = []
    for row in points:
        if row["label"] not in labels:
            labels.append(row["label"])
    numeric = all(_is_number(label) for label in labels)
    values = sorted({float(r["value"]) for r in points})
    log_axis = numeric and min(values) > 0 and max(values) / min(values) >= 8
    figure, (time_axis, error_axis, brightness_axis) = plt.subplots(1, 3, figsize=(16, 4.5))
    # Scenes side by side at each value, so that error bars do not hide one another.
    if numeric and not log_axis and len(values) >= 2:
        offset_step = 0.1 * min(b - a for a, b in zip(values, values[1:])) / max(1, len(names) - 1)
    else:
        offset_step = 0.05 if not numeric else 0.06
    for scene_index, name in enumerate(names):
        mine = [r for r in points if r["scene"] == name]
        xs = [float(r["value"]) if numeric else labels.index(r["label"]) for r in mine]
        shift = (scene_index - (len(names) - 1) / 2) * offset_step
        brightness_xs = [x * 2 ** shift if numeric and log_axis else x + shift for x in xs]
        brightness_axis.errorbar(
            brightness_xs, [100 * number(r, "brightness_bias") for r in mine],
            yerr=[100 * BRIGHTNESS_SIGMAS * number(r, "brightness_noise") for r in mine],
            fmt="o-", color=colour[name], capsize=3, label=name)
        time_axis.plot(xs, [number(r, "cpu_ms_per_spp") for r in mine], "o-",
                       color=colour[name], label=name)
        error_axis.plot(xs, [number(r, "rel_mse") for r in mine], "o-", color=colour[name],
                        label=name)
        # This scene's noise level (image and reference), under which bias cannot be seen.
        default = default_row(rows, name)
        if default is not None:
            error_axis.axhline(noise_of(default), color=colour[name], linestyle=":", linewidth=1)
        for x, row in zip(xs, mine):
            if judge(row) == "bias":
                error_axis.plot([x], [number(row, "rel_mse")], "o", markersize=11,
                                markerfacecolor="none", markeredgecolor="black")
    for axis in (time_axis, error_axis, brightness_axis):
        if numeric:
            if log_axis:
                axis.set_xscale("log", base=2)
            axis.set_xticks(values)
            axis.set_xticklabels([fmt(v) for v in values])
        else:
            axis.set_xticks(range(len(labels)))
            axis.set_xticklabels(labels)
            axis.set_xlim(-0.5, len(labels) - 0.5)
        axis.set_xlabel(setting)
        axis.grid(True, which="both", alpha=0.3)
    time_axis.set_ylabel("CPU ms per sample per pixel (whole image)")
    time_axis.set_ylim(bottom=0)
    time_axis.set_title("cost: time per sample")
    error_axis.set_yscale("log")
    error_axis.set_ylabel(f"relative MSE at {points[0]['spp']} spp")
    error_axis.set_title("error against the default reference\n"
                         "(dotted: noise level; circled: bias)", fontsize=10)
    brightness_axis.axhline(0, color="black", linewidth=0.8)
    brightness_axis.set_ylabel("image sum against the reference's (%)")
    brightness_axis.set_title(f"brightness bias (bars: ±{BRIGHTNESS_SIGMAS:g} standard deviations "
                              "of noise)", fontsize=10)
    time_axis.legend(fontsize=8)
    figure.tight_layout()
    filename = f"setting_{setting}.png"
    figure.savefig(os.path.join(data_dir, filename), dpi=100)
    plt.close(figure)
    return filename


def _is_number(text):
    try:
        float(text)
        return True
    except ValueError:
        return False


def setting_digest(rows, setting):
    """Per non-default value: median time ratio to the default and the scenes it biases."""
    digest = []
    points = setting_rows(rows, setting)
    labels = []
    for row in points:
        if row["label"] not in labels:
            labels.append(row["label"])
    for label in labels:
        mine = [r for r in points if r["label"] == label]
        if all(r["is_default"] == "1" for r in mine):
            continue
        ratios, biased, same, brightness, efficiency = [], [], [], [], []
        for row in mine:
            default = default_row(rows, row["scene"])
            ratios.append(number(row, "cpu_ms_per_spp") / number(default, "cpu_ms_per_spp"))
            verdict = judge(row)
            if verdict == "noise":
                # Efficiency: 1 / (variance x time), against the default's. Each render's
                # own noise, not its error, so the reference's noise does not blur it.
                efficiency.append(
                    number(default, "rel_mse_noise") * number(default, "cpu_ms_per_spp") /
                    (number(row, "rel_mse_noise") * number(row, "cpu_ms_per_spp")))
            if verdict == "bias":
                biased.append(row["scene"])
                brightness.append((abs(number(row, "brightness_bias")), row["scene"],
                                   number(row, "brightness_bias")))
            elif verdict == "same":
                same.append(row["scene"])
        digest.append({
            "label": label,
            "time_ratio": statistics.median(ratios),
            "time_ratio_range": (min(ratios), max(ratios)),
            "biased": biased,
            "same": same,
            "largest_brightness": max(brightness) if brightness else None,
            "efficiency": statistics.median(efficiency) if efficiency else None,
            "scenes": len(mine),
        })
    return digest


def settings_reading(rows, digests, timing_noise):
    """The reading of the settings sweep: blocks of markdown."""
    blocks = []
    spread = max((abs(1 - t) for t in timing_noise), default=0.0)
    if timing_noise:
        blocks.append(
            "**Settings.** Timing noise first: renders whose image is bit for bit the default's "
            f"took {fmt(min(timing_noise), 2)}× to {fmt(max(timing_noise), 2)}× the default's "
            f"CPU time, so time differences within about ±{100 * spread:.0f} % are the shared "
            "machine, not the setting. Efficiency below is 1 / (noise × time) against the "
            "default's, for values without visible bias: above 1, the value reaches a given "
            "error sooner. Each comes from one render per scene (a median over scenes), so "
            "differences of a few tens of percent are not resolved.")
    else:
        blocks.append("**Settings.**")
    bullets = []
    for setting, digest in digests.items():
        parts = []
        for d in digest:
            low, high = d["time_ratio_range"]
            part = (f"`{d['label']}`: {fmt(d['time_ratio'], 2)}× the time "
                    f"({fmt(low, 2)}–{fmt(high, 2)})")
            if d["biased"]:
                part += f", biased in {len(d['biased'])} of {d['scenes']} scenes"
                if d["largest_brightness"] is not None:
                    part += (f" (brightness up to {percent(d['largest_brightness'][2])} in "
                             f"{d['largest_brightness'][1]})")
            elif len(d["same"]) == d["scenes"]:
                part += ", the same image in every scene"
            else:
                part += ", no visible bias"
                if d["efficiency"] is not None:
                    part += f", efficiency {fmt(d['efficiency'], 2)}×"
            parts.append(part)
        bullets.append(f"- **{setting}**: " + "; ".join(parts) + ".")
    blocks.append("\n".join(bullets))

    # The hit tolerance's default is itself an approximation: the tighter values measure it.
    tolerance = [r for r in rows if r["setting"] == "hit-tolerance"]
    defaults = [float(r["value"]) for r in tolerance if r["is_default"] == "1"]
    if tolerance and defaults:
        tightest = min(float(r["value"]) for r in tolerance)
        tight = [r for r in tolerance if float(r["value"]) == tightest and r["is_default"] != "1"]
        if tight:
            shifts = sorted(((abs(number(r, "brightness_bias")), r["scene"],
                              number(r, "brightness_bias")) for r in tight), reverse=True)
            biased = [r["scene"] for r in tight if judge(r) == "bias"]
            blocks.append(
                f"**Tighter tolerances change the image.** Tightening the hit tolerance from "
                f"{fmt(defaults[0])} to {fmt(tightest)} footprints changes the image visibly in "
                f"{len(biased)} of {len(tight)} scenes (brightness by "
                + ", ".join(f"{percent(v)} in {n}" for _, n, v in shifts[:3])
                + "). This sweep compares every value with a reference made with the default "
                "tolerance, so it shows how far each value moves the image, not which image is "
                "right: a bias the default shares with its reference is invisible here. The "
                "section *Per pixel, against exact intersection* judges the tolerance, the step "
                "limit and over-relaxation against geometry met in closed form; where the two "
                "disagree, that section is right.")

    # A firefly in the default-settings render inflates the noise every value of its scene
    # is judged against; say so where it happened.
    inflated = []
    for scene in sorted({r["scene"] for r in rows}):
        mine = [r for r in rows if r["scene"] == scene]
        default = next((r for r in mine if r["is_default"] == "1"), None)
        others = [number(r, "rel_mse") for r in mine
                  if r["is_default"] != "1" and judge(r) == "noise"]
        if default is None or len(others) < 3:
            continue
        typical = statistics.median(others)
        if number(default, "rel_mse") > 3.0 * typical:
            inflated.append((scene, number(default, "rel_mse") / typical))
    if inflated:
        blocks.append(
            "**Fireflies in the default render.** "
            + "; ".join(f"In {scene} the default-settings render's error is "
                        f"{fmt(factor, 2)}× the median of the unbiased values'" for scene, factor
                        in inflated)
            + ": it met a rare, very bright path (one caustic sample outweighs the rest of the "
            "image), so its noise, which every value of that scene is judged against, is "
            "inflated there, and a bias of that scene's values smaller than it cannot be seen. "
            "The other values' renders, with other random streams, did not meet one; the spike "
            "at the default value in that scene's curves is this single render, not a property "
            "of the default.")

    # Recommendations, from the digests.
    free, slower_better, biased_speedups, noisy_speedups = [], [], [], []
    for setting, digest in digests.items():
        for d in digest:
            name = f"`{setting} {d['label']}`"
            faster = d["time_ratio"] < 1 - max(spread, 0.05)
            if d["biased"]:
                if faster:
                    biased_speedups.append(name)
            elif faster:
                if d["efficiency"] is not None and d["efficiency"] < 0.9:
                    noisy_speedups.append(f"{name} (efficiency {fmt(d['efficiency'], 2)}×)")
                else:
                    free.append(name + (f" ({fmt(d['time_ratio'], 2)}× the time"
                                        + (f", efficiency {fmt(d['efficiency'], 2)}×)"
                                           if d["efficiency"] is not None else ")")))
            elif d["efficiency"] is not None and d["efficiency"] > 1.25:
                slower_better.append(f"{name} ({fmt(d['time_ratio'], 2)}× the time, efficiency "
                                     f"{fmt(d['efficiency'], 2)}×)")
    advice = ["**Recommendations** (from these measurements; timing differences inside the "
              "timing noise are not counted as gains):"]
    advice.append("- Faster with no visible bias in any scene: "
                  + (", ".join(free) if free else "none beyond the timing noise") + ".")
    if noisy_speedups:
        advice.append("- Faster per sample but noisier, so no faster to a given error: "
                      + ", ".join(noisy_speedups) + ".")
    if slower_better:
        advice.append("- No faster per sample beyond the timing noise, but more efficient "
                      "(a given error sooner): " + ", ".join(slower_better) + ".")
    if biased_speedups:
        advice.append("- Faster only by giving up accuracy (visible bias): "
                      + ", ".join(biased_speedups)
                      + ". Use them for previews, not for converged images.")
    advice.append("- Unbiased settings (Russian-roulette depth, MIS, over-relaxation) should "
                  "be chosen by efficiency, not by time per sample; the others (hit tolerance, "
                  "step limit, path length, Fresnel model) by the bias they leave against the "
                  "noise a render will reach.")
    blocks.append("\n".join(advice))
    return blocks


# ----------------------------------------------------------------------------------------
# Equal time

def plot_equal_time(rows, data_dir, filename, all_names):
    names = scene_order(rows)
    colour = colours(all_names)
    figure, axis = plt.subplots(figsize=(6.5, 4.5))
    for name in names:
        mine = [r for r in rows if r["scene"] == name]
        axis.loglog([number(r, "budget_seconds") for r in mine],
                    [number(r, "rel_mse") for r in mine], "o-", color=colour[name], label=name)
    budgets = sorted({number(r, "budget_seconds") for r in rows})
    if len(budgets) >= 2:
        y_low, y_high = axis.get_ylim()
        start = math.sqrt(y_low * y_high) * 4
        axis.loglog(budgets, [start * (b / budgets[0]) ** -1 for b in budgets], "k:",
                    label="slope -1")
    axis.set_xlabel("time budget (s)")
    axis.set_ylabel("relative MSE")
    axis.set_title("error reached in equal time")
    axis.grid(True, which="both", alpha=0.3)
    axis.legend(fontsize=8)
    figure.tight_layout()
    figure.savefig(os.path.join(data_dir, filename), dpi=100)
    plt.close(figure)


def equal_time_slopes(rows):
    """A sentence on how fast the error falls from one budget to the next."""
    slopes = []
    for name in scene_order(rows):
        mine = [r for r in rows if r["scene"] == name and int(r["spp"]) > 0]
        if len(mine) >= 2:
            xs = [number(r, "seconds") for r in mine]
            ys = [number(r, "rel_mse") for r in mine]
            slopes.append(float(np.polyfit(np.log(xs), np.log(ys), 1)[0]))
    if not slopes:
        return ""
    largest = max(number(r, "budget_seconds") for r in rows)
    shares = [number(r, "reference_rel_mse_noise") / number(r, "rel_mse")
              for r in rows if number(r, "budget_seconds") == largest]
    median = statistics.median(slopes)
    text = (f" Between budgets the relative MSE falls with slope {fmt(median, 2)} against the "
            f"time used (median over scenes; {fmt(min(slopes), 2)} to {fmt(max(slopes), 2)}), "
            f"so each tenfold budget divides it by about {fmt(10 ** -median, 2)}; the Monte "
            "Carlo rate would divide it by 10.")
    if median > -0.9:
        text += (f" At {fmt(largest)} s the reference's own noise is {100 * min(shares):.0f}–"
                 f"{100 * max(shares):.0f} % of the measured error, which flattens these "
                 "slopes; the rest is the heavy tail of rare bright paths seen in the "
                 "convergence curves.")
    return text


# ----------------------------------------------------------------------------------------
# The markdown

def table(header, rows):
    lines = ["| " + " | ".join(header) + " |", "|" + "---|" * len(header)]
    lines += ["| " + " | ".join(str(cell) for cell in row) + " |" for row in rows]
    return "\n".join(lines)


def intro_section(args, run, relative_plots):
    """The title, what the page is and who made it, and the machine and run."""
    out = []
    out.append("# What accuracy costs in time\n")
    if args.note:
        out.append(f"> {args.note}\n")
    out.append(
        "Error against a converged reference, as a function of render time (convergence), "
        "of a time budget (equal time) and of every accuracy setting, for the classic scenes. "
        f"Made by `{args.command}` "
        f"(configuration **{args.configuration}**) from the CSVs beside the plots in "
        f"[`{relative_plots}/`]({relative_plots}/); the program that measures is "
        "`bench/convergence.cpp` (target `bench_convergence`), the writer of this page "
        "`tools/accuracy_report.py`.\n")
    duration = float(run.get("total_seconds", "nan"))
    out.append(table(["machine", "run"], [[
        f"{run.get('gl', '?').strip(chr(34))}, {run.get('hardware_threads', '?')} hardware threads",
        f"{run.get('started', '?')} to {run.get('finished', '?')} "
        f"({fmt(duration / 60, 3)} min); load average {run.get('load_average_at_start', '?')} "
        f"at the start, {run.get('load_average_at_end', '?')} at the end"]]))
    out.append("")
    out.append(f"Command of the measurement: `{run.get('command', '?').strip(chr(34))}`\n")
    return out


def method_section(run, references):
    """How the error, noise, brightness and time are measured."""
    out = []
    out.append("## How it is measured\n")
    eps = run.get("relative_mse_epsilon", "0.01")
    ref = references[0] if references else {}
    out.append(
        f"- **Reference**: per scene, the default settings at {ref.get('spp', '?')} samples per "
        f"pixel with seed {ref.get('seed', '?')}, cached as linear EXR outside the repository "
        "under a key made of the scene file, the shader as assembled for the scene, the numbers "
        "the host packs for it, its textures, the settings, the size, the spp and the seed. "
        "Every measured render uses another seed.\n"
        "- **Time** is wall-clock time of the frames that add samples. The shader compile and a "
        "first, warm-up frame (where llvmpipe generates the machine code) are timed apart and "
        "thrown away; reading images back and computing errors are not counted either. "
        "The process's CPU time (llvmpipe's threads included) is recorded beside it: the "
        "machine is shared, and CPU time is the steadier measure of cost, wall time what a "
        "user waits.\n"
        f"- **Relative MSE**: the mean over pixels and colour channels of "
        f"(x − ref)² / (ref² + ε), ε = {eps}, on linear radiance. ε keeps black reference "
        "pixels (a red wall's green channel) from dividing by zero and nearly black ones "
        "(shadowed corners, where a sample's relative spread is largest) from outweighing "
        "everything visible; 0.01 is the value common in the denoising literature. It makes "
        "the error absolute below a radiance of 0.1 and relative above; under the display's "
        "tone map radiance 0.1 is level 105 of 255, so the darker part of the picture counts "
        "less than relatively, and the tone RMSE below covers it. At the Monte Carlo rate the "
        "relative MSE falls as 1/spp.\n"
        "- **Relative RMSE** (rel RMSE): sqrt(mean over pixels and channels of (x − ref)²) / "
        "mean over pixels and channels of ref, on linear radiance: the metric `--target-error` "
        "aims at, and the one the independent renderers' comparisons use. Unlike the relative "
        "MSE it weighs every pixel's error in absolute terms, so the brightest and noisiest "
        "pixels (caustics, light seen through glass) dominate it; it falls as spp^−1/2. The "
        "per-pixel sections and *Rendering to a target error* below report it; the "
        "convergence, equal-time and settings sections report the relative MSE and the tone "
        "RMSE.\n"
        "- **Tone RMSE**: root mean square difference of the displayed pictures on the 0–255 "
        "scale, after the display tone map of `shaders/modules/tone_map.frag` (exposure 4, "
        "Hable's filmic curve normalised to white 11.2, gamma 2.2) computed in double and not "
        "rounded, so differences under one level show. At the Monte Carlo rate it falls as "
        "spp^−1/2.\n"
        "- **Noise of an image**, without a second render: the image at n samples, M, and the "
        "same run's image at n/2, H, give the second half's mean 2M − H, independent of H; "
        "(M − H)² then has the expectation of M's variance. Weighted like the error, it says "
        "how much of an error is noise. An image differs from the reference by its own noise, "
        "the reference's noise, and bias; **error ÷ noise** near 1 means no visible bias.\n"
        "- **Brightness**: the image's sum over all pixels and channels over the reference's, "
        "minus 1, with one standard deviation of noise from the per-pixel variances. Noise "
        "averages out of the sum, so a bias that darkens or brightens the picture (light lost "
        "by short paths, light leaking) shows there long before it shows in the relative "
        "MSE. A setting is marked as **biased** in a scene when error ÷ noise ≥ "
        f"{BIAS_RATIO} or its brightness differs by more than {BRIGHTNESS_SIGMAS:g} standard "
        "deviations.\n")

    return out


def references_section(references):
    out = []
    if references:
        out.append("### References\n")
        out.append(table(
            ["scene", "size", "spp", "render time (s)", "Mpaths/s", "noise: relative MSE",
             "noise: tone RMSE", "discarded samples", "cached"],
            [[r["scene"], f"{r['width']}x{r['height']}", r["spp"], fmt(number(r, "render_seconds")),
              fmt(number(r, "mpaths_per_s")), fmt(number(r, "rel_mse_noise")),
              fmt(number(r, "tone_rmse_noise")), r["discarded"],
              "yes" if r["cached"] == "1" else "no"] for r in references]))
        out.append("")
    return out


def convergence_section(convergence, data, image):
    """Error against render time; returns the page's lines and the reading's paragraphs."""
    out, reading = [], []
    summary = convergence_summary(convergence)
    plot_convergence(convergence, summary, data, "rel_mse", "relative MSE", -1.0,
                     "convergence_rel_mse.png")
    plot_convergence(convergence, summary, data, "tone_rmse", "tone-mapped RMSE (0-255)",
                     -0.5, "convergence_tone_rmse.png")
    plot_convergence_overview(convergence, summary, data, "convergence_overview.png")
    first = convergence[0]
    out.append("## Convergence: error against render time\n")
    out.append(
        f"Default settings, {first['width']}x{first['height']}, spp = 1, 2, 4, … "
        f"{convergence[-1]['spp']} in one progressive run. The slope is the least-squares "
        "slope of log relative MSE against log render time (and against log spp) over the "
        f"points from 2 spp on whose error is above {FLOOR_MARGIN:g}× the reference's noise; "
        "the Monte Carlo rate is −1. relMSE·spp is the relative MSE times spp at the last "
        "fitted point over that at the first: 1 at the Monte Carlo rate.\n")
    rows_out = []
    for name, s in summary.items():
        rows_out.append([
            name, fmt(s["mpaths"]), fmt(s["cpu_per_wall"], 2), fmt(s["compile"], 2),
            fmt(s["warmup"], 2), fmt(number(s["first"], "rel_mse")),
            fmt(number(s["last"], "rel_mse")), fmt(number(s["last"], "tone_rmse")),
            fmt(s["slope_time"], 2) if s["slope_time"] is not None else "–",
            fmt(s["slope_spp"], 2) if s["slope_spp"] is not None else "–",
            fmt(s["per_sample_growth"], 2), fmt(s["noise_ratio"], 2),
            fmt(s["reference_noise"])])
    out.append(table(
        ["scene", "Mpaths/s", "CPU s per wall s", "compile (s)", "warm-up frame (s)",
         "relative MSE at 1 spp", f"at {convergence[-1]['spp']} spp",
         f"tone RMSE at {convergence[-1]['spp']} spp", "slope vs time", "slope vs spp",
         "relMSE·spp growth", "error ÷ noise (median)", "reference's noise"], rows_out))
    out.append("")
    out.append("![relative MSE against time, all scenes]"
               f"({image('convergence_overview.png')})\n")
    out.append(f"![relative MSE against time per scene]({image('convergence_rel_mse.png')})\n")
    out.append("![tone-mapped RMSE against time per scene]"
               f"({image('convergence_tone_rmse.png')})\n")

    spp_values = sorted({int(r["spp"]) for r in convergence})
    names = list(summary)
    lookup = {(r["scene"], int(r["spp"])): r for r in convergence}
    out.append("Relative MSE (render seconds) at each spp:\n")
    out.append(table(["spp"] + names, [
        [str(spp)] + [
            f"{fmt(number(lookup[(n, spp)], 'rel_mse'))} "
            f"({fmt(number(lookup[(n, spp)], 'seconds'), 2)} s)"
            if (n, spp) in lookup else "–" for n in names]
        for spp in spp_values]))
    out.append("")

    at_rate = [n for n, s in summary.items()
               if s["slope_time"] is not None and -1.2 <= s["slope_time"] <= -0.8]
    off_rate = [n for n, s in summary.items()
                if s["slope_time"] is not None and not (-1.2 <= s["slope_time"] <= -0.8)]
    text = ("**Convergence.** Relative MSE falls with render time at the Monte Carlo rate "
            "(fitted slope within ±0.2 of −1) in "
            f"{', '.join(at_rate) if at_rate else 'no scene'}")
    text += "." if not off_rate else f"; not in {', '.join(off_rate)}, for the reasons below."
    slopes = [s["slope_tone_time"] for s in summary.values()
              if s["slope_tone_time"] is not None]
    if slopes:
        text += (f" The tone-mapped RMSE falls with slopes from {fmt(min(slopes), 2)} to "
                 f"{fmt(max(slopes), 2)} (the rate is −0.5).")
        shares = [number(s["last"], "reference_tone_rmse_noise") /
                  number(s["last"], "tone_rmse") for s in summary.values()]
        if min(slopes) > -0.45 or max(slopes) > -0.4:
            text += (" It is shallower for two reasons: the tone map is bounded and "
                     "compressive, so the large errors of images of a few samples are "
                     "clipped and the early points lie low (the −0.5 rate holds only once "
                     "the noise is small against the tone curve's bend); and at the last "
                     "point the reference's own tone noise is "
                     f"{100 * min(shares):.0f}–{100 * max(shares):.0f} % of the error, "
                     "adding in quadrature.")
    reading.append(text)
    bullets = []
    for name in off_rate:
        s = summary[name]
        reasons = []
        if s["per_sample_growth"] > 1.5:
            reasons.append(
                f"relMSE·spp grows {fmt(s['per_sample_growth'], 2)}× over the fit: the "
                "error is heavy-tailed, dominated by rare bright paths (fireflies) that a "
                "short run has not met yet, so the early points lie below the trend and "
                "the fitted slope is shallower than −1 although each pixel's variance "
                "still falls as 1/spp")
        elif s["per_sample_growth"] < 0.67:
            reasons.append(
                f"relMSE·spp falls {fmt(1 / s['per_sample_growth'], 2)}× over the fit: "
                "a few early fireflies dominate the first points and average away later")
        if s["floor_reached"]:
            reasons.append("the last points approach the reference's own noise and were "
                           "left out of the fit")
        ratio = number(s["last"], "seconds") / int(s["last"]["spp"])
        first_ratio = number(s["first"], "seconds") / int(s["first"]["spp"])
        steeper_in_time = (s["slope_time"] is not None and s["slope_spp"] is not None
                           and s["slope_time"] < s["slope_spp"] - 0.05)
        if first_ratio > 1.5 * ratio and steeper_in_time:
            reasons.append(
                f"the first samples cost more per sample ({fmt(1e3 * first_ratio, 3)} ms "
                f"against {fmt(1e3 * ratio, 3)} ms later): per-frame overhead or load on "
                "the shared machine, which makes the slope against time steeper than "
                "against spp")
        if not reasons:
            reasons.append("no single cause stands out; with one run per scene the "
                           "fitted slope carries the noise of the error itself")
        bullets.append(f"- {name}: slope {fmt(s['slope_time'], 2)} against time, "
                       f"{fmt(s['slope_spp'], 2)} against spp; " + "; ".join(reasons) + ".")
    heavy = [n for n, s in summary.items() if n in at_rate and s["per_sample_growth"] > 1.5]
    if heavy:
        bullets.append(
            f"- {', '.join(heavy)}: at the rate overall, but relMSE·spp still grows "
            "over the fit (rare bright paths, as above), so single points scatter about "
            "the line.")
    ratios = [s["noise_ratio"] for s in summary.values() if not math.isnan(s["noise_ratio"])]
    if ratios:
        bullets.append(
            "- The default-settings renders differ from their references by noise alone: "
            f"error ÷ noise has medians between {fmt(min(ratios), 2)} and "
            f"{fmt(max(ratios), 2)} across scenes (1 expected). With the settings that made "
            "the reference, no bias can show in this curve; it flattens only on the "
            "reference's own noise (the red line). The default settings' own bias against "
            "the true image is what the settings sweep below measures.")
    reading.append("\n".join(bullets))

    return out, reading


def equal_time_section(equal_time, data, image, all_names):
    """Error reached in each time budget; returns the page's lines and the reading's paragraphs."""
    out, reading = [], []
    plot_equal_time(equal_time, data, "equal_time.png", all_names)
    budgets = sorted({number(r, "budget_seconds") for r in equal_time})
    first = equal_time[0]
    out.append("## Equal time: error reached in a time budget\n")
    out.append(
        f"Default settings at {first['width']}x{first['height']}; one run per scene renders "
        "until each budget and is measured there (the clock pauses while it is measured). "
        "A frame still drawing when the budget runs out is dropped, so 'used' can be a "
        "little under the budget, or a little over it when a frame of one band ended just "
        "after it.\n")
    lookup = {(r["scene"], number(r, "budget_seconds")): r for r in equal_time}
    header = ["scene"]
    for b in budgets:
        header += [f"{fmt(b)} s: spp (used s)", "relative MSE", "tone RMSE"]
    body = []
    for name in scene_order(equal_time):
        row = [name]
        for b in budgets:
            r = lookup.get((name, b))
            if r is None:
                row += ["–", "–", "–"]
            else:
                row += [f"{r['spp']} ({fmt(number(r, 'seconds'), 3)})",
                        fmt(number(r, "rel_mse")), fmt(number(r, "tone_rmse"))]
        body.append(row)
    out.append(table(header, body))
    out.append("")
    out.append(f"![error reached in equal time]({image('equal_time.png')})\n")
    worst = max(scene_order(equal_time),
                key=lambda n: number(lookup[(n, budgets[-1])], "rel_mse")
                if (n, budgets[-1]) in lookup else -1)
    best = min(scene_order(equal_time),
               key=lambda n: number(lookup[(n, budgets[-1])], "rel_mse")
               if (n, budgets[-1]) in lookup else math.inf)
    reading.append(
        f"**Equal time.** After {fmt(budgets[-1])} s the cleanest scene is {best} "
        f"(relative MSE {fmt(number(lookup[(best, budgets[-1])], 'rel_mse'))}, "
        f"{lookup[(best, budgets[-1])]['spp']} spp) and the noisiest {worst} "
        f"({fmt(number(lookup[(worst, budgets[-1])], 'rel_mse'))}, "
        f"{lookup[(worst, budgets[-1])]['spp']} spp)." + equal_time_slopes(equal_time))

    return out, reading


def settings_section(settings, data, image):
    """Each accuracy setting varied alone; returns the page's lines and the reading's paragraphs."""
    out, reading = [], []
    first = settings[0]
    out.append("## Accuracy settings: what each one buys and costs\n")
    out.append(
        f"Each setting is varied alone from the defaults; every render has "
        f"{first['spp']} spp at {first['width']}x{first['height']} and is compared with the "
        "**default-settings** reference. So the error of a non-default value, where it "
        "stands above the noise, is how far that value's image is from the default's: the "
        "bias the change introduces. For settings whose default is itself an approximation "
        "(hit tolerance, Schlick's Fresnel), the value closer to exact measures the "
        "default's own bias. Time is CPU milliseconds per sample per pixel over the whole "
        "image (wall milliseconds in brackets). Marks: **bias** = visible bias (see above); "
        "**same** = the image is bit for bit the default's (the setting does nothing in "
        "this scene; its time differs from the default's only by the machine's noise).\n")
    timing_noise = []
    digests = {}
    for setting in settings_order(settings):
        points = setting_rows(settings, setting)
        filename = plot_setting(settings, setting, data)
        labels = []
        for row in points:
            if row["label"] not in labels:
                labels.append(row["label"])
        out.append(f"### {setting}\n")
        out.append(SETTING_NOTES.get(setting, "") + "\n")
        lookup = {(r["scene"], r["label"]): r for r in points}
        header = ["scene", "noise"]
        for label in labels:
            defaults = [r for r in points if r["label"] == label and r["is_default"] == "1"]
            header.append(f"{label} (default)" if defaults else label)
        time_body, error_body = [], []
        for name in scene_order(points):
            default = default_row(settings, name)
            time_row, error_row = [name, ""], [name, fmt(noise_of(default))]
            for label in labels:
                r = lookup.get((name, label))
                if r is None:
                    time_row.append("–")
                    error_row.append("–")
                    continue
                time_row.append(f"{fmt(number(r, 'cpu_ms_per_spp'))} "
                                f"({fmt(number(r, 'ms_per_spp'))})")
                verdict = judge(r)
                mark = {"bias": " **bias**", "same": " same", "noise": ""}[verdict]
                if verdict == "same":
                    error_row.append("same")
                    timing_noise.append(number(r, "cpu_ms_per_spp") /
                                        number(default, "cpu_ms_per_spp"))
                else:
                    error_row.append(
                        f"{fmt(number(r, 'rel_mse'))} "
                        f"({fmt(number(r, 'rel_mse') / noise_of(r), 2)}×; "
                        f"{percent(number(r, 'brightness_bias'))} ± "
                        f"{100 * number(r, 'brightness_noise'):.1f}){mark}")
            time_body.append(time_row)
            error_body.append(error_row)
        time_header = ["scene", ""] + header[2:]
        out.append("CPU ms per spp (wall ms per spp):\n")
        out.append(table([h for i, h in enumerate(time_header) if i != 1],
                         [[c for i, c in enumerate(row) if i != 1] for row in time_body]))
        out.append("")
        out.append("Relative MSE (error ÷ noise; brightness ± its noise); 'noise' is the "
                   "default render's noise plus the reference's:\n")
        out.append(table(header, error_body))
        out.append("")
        out.append(f"![{setting}]({image(filename)})\n")

        digests[setting] = setting_digest(settings, setting)
    reading += settings_reading(settings, digests, timing_noise)

    return out, reading


def regenerating_section():
    out = []
    out.append("## Regenerating\n")
    out.append(
        "```sh\n"
        "tools/accuracy-report.sh                       # full: 160x120 sweeps, 320x240 budgets\n"
        "ACCURACY_SCALE=quick tools/accuracy-report.sh  # minutes: 80x60, low spp\n"
        "```\n\n"
        "The script installs what is missing (python3-matplotlib among it), builds "
        "`bench_convergence` in `build-accuracy/`, keeps the references in "
        "`build-accuracy/accuracy-cache/` (reused while the scene, shaders and settings are "
        "unchanged; `ACCURACY_REFRESH=1` renders them again), writes the CSVs and plots to "
        "`docs/accuracy/` and this page. Its header documents every variable.\n")
    return out


def keep_other_tools_sections(out, markdown):
    """The summary at the top (by hand), the per-pixel sections (tools/per_pixel_report.py), the target-error section
    (bench/target_error.py), the environment maps' (bench/environment_sampling.cpp,
    bench/mitsuba/compare_environment_maps.py) and the denoising section
    (tools/denoise_report.py) are written by other tools or by hand: they are kept from the
    page as it was,
    in their order, before the convergence section. The per-pixel sections' hand-written
    reading, when there is one, ends at its own marker."""
    if os.path.exists(markdown):
        previous = open(markdown).read()
        kept = []
        for begin, end in (("<!-- per-pixel:begin -->", "<!-- per-pixel-reading:end -->"),
                           ("<!-- per-pixel:begin -->", "<!-- per-pixel:end -->"),
                           ("<!-- target-error:begin -->", "<!-- target-error:end -->"),
                           ("<!-- environment-maps:begin -->",
                            "<!-- environment-maps:end -->"),
                           ("<!-- denoising:begin -->", "<!-- denoising:end -->")):
            if begin in previous and end in previous and not any(begin in k for k in kept):
                kept.append(previous[previous.index(begin):previous.index(end) + len(end)] + "\n")
        at = next((i for i, line in enumerate(out) if line.startswith("## Convergence")),
                  len(out))
        out[at:at] = kept
        # The current answers, written by hand from every section, open the page.
        begin, end = "<!-- at-a-glance:begin -->", "<!-- at-a-glance:end -->"
        if begin in previous and end in previous:
            out[1:1] = [previous[previous.index(begin):previous.index(end) + len(end)] + "\n"]


def write_report(args):
    data = args.data_dir
    run = {r["key"]: r["value"] for r in read_csv(os.path.join(data, "run.csv"))}
    references = read_csv(os.path.join(data, "references.csv"))
    convergence = read_csv(os.path.join(data, "convergence.csv"))
    settings = read_csv(os.path.join(data, "settings.csv"))
    equal_time = read_csv(os.path.join(data, "equal_time.csv"))
    relative_plots = os.path.relpath(data, os.path.dirname(os.path.abspath(args.markdown)))
    image = lambda name: f"{relative_plots}/{name}"  # noqa: E731
    all_names = scene_order(convergence or settings or equal_time)

    out = intro_section(args, run, relative_plots)
    out += method_section(run, references)
    out += references_section(references)
    reading = []
    if convergence:
        lines, paragraphs = convergence_section(convergence, data, image)
        out += lines
        reading += paragraphs
    if equal_time:
        lines, paragraphs = equal_time_section(equal_time, data, image, all_names)
        out += lines
        reading += paragraphs
    if settings:
        lines, paragraphs = settings_section(settings, data, image)
        out += lines
        reading += paragraphs
    out.append("## Reading\n")
    out.append("\n\n".join(reading) + "\n")
    out += regenerating_section()
    keep_other_tools_sections(out, args.markdown)
    with open(args.markdown, "w") as file:
        file.write("\n".join(out))


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("data_dir")
    parser.add_argument("markdown")
    parser.add_argument("--configuration", default="full")
    parser.add_argument("--command", default="tools/accuracy-report.sh")
    parser.add_argument("--note", default="")
    write_report(parser.parse_args())


if __name__ == "__main__":
    main()
