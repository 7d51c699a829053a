#!/usr/bin/python3
"""Writes the per-pixel sections of docs/ACCURACY.md from what tools/per-pixel-report.sh
rendered (issues 13 and 20).

    /usr/bin/python3 tools/per_pixel_report.py CACHE MARKDOWN IMAGE_DIR --size W H
        --exact-spp N --settings-spp N --command TEXT

CACHE holds NAME-VARIANT-sSEED-SPP.exr renders (VARIANT: sobol, independent, exact, or a
setting such as hittolerance=0.5) and flat-plane-SAMPLER-SPP.png. The sections replace
what lies between the markers <!-- per-pixel:begin --> and <!-- per-pixel:end --> in
MARKDOWN (appended when there are none); images go to IMAGE_DIR, linked relative to MARKDOWN.

Every error is a relative RMSE, sqrt(mean((x - ref)^2)) / mean(ref) over all pixels and
channels of the linear image, as issue 13 defines it. Two renders of independent seeds give
everything that is noise: the mean of their squared difference is twice one render's
variance, and the mean of the product of their differences from two independent reference
renders estimates the squared bias without bias of its own. Needs numpy, matplotlib and
oiiotool (openimageio-tools).
"""

import argparse
import glob
import math
import os
import re
import shutil
import subprocess
import tempfile

import matplotlib

matplotlib.use("Agg")  # files only, no display
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

BEGIN = "<!-- per-pixel:begin -->"
END = "<!-- per-pixel:end -->"
CREASES_BEGIN = "<!-- per-pixel-creases:begin -->"
CREASES_END = "<!-- per-pixel-creases:end -->"
LADDER = [4, 16, 64, 256, 1024]
# A bias estimate under this many of its standard errors is reported as within noise.
BIAS_SIGMAS = 2.0
# Signed error images span +-this fraction of the reference's mean.
ERROR_IMAGE_SPAN = 0.25
SETTING_NAMES = {"hittolerance": "--hit-tolerance", "maxsteps": "--max-steps",
                 "overrelaxation": "--over-relaxation"}
SETTING_DEFAULTS = {"hittolerance": "0.25", "maxsteps": "512", "overrelaxation": "1.2"}


class Render:
    """One EXR: its linear RGB (rows top first) and the seconds it took to render."""

    def __init__(self, path):
        self.path = path
        self.rgb = read_exr_rgb(path)
        info = subprocess.run(["oiiotool", "--info", "-v", path], check=True,
                              capture_output=True, text=True).stdout
        match = re.search(r'raytracer:renderSeconds: "([0-9.eE+-]+)"', info)
        self.seconds = float(match.group(1)) if match else float("nan")


def read_exr_rgb(path):
    """R, G, B of an EXR as float64, rows top first. oiiotool rewrites the file without
    compression (this OpenImageIO writes no float format numpy reads), whose scanlines are
    then read here; the result is kept beside the EXR as .npy."""
    cached = path + ".rgb.npy"
    if os.path.exists(cached) and os.path.getmtime(cached) >= os.path.getmtime(path):
        return np.load(cached)
    with tempfile.TemporaryDirectory() as folder:
        plain = os.path.join(folder, "plain.exr")
        subprocess.run(["oiiotool", path, "--ch", "R,G,B", "-d", "float", "--compression",
                        "none", "-o", plain], check=True)
        data = open(plain, "rb").read()
    at, channels, window = 8, [], None
    while data[at] != 0:  # header attributes: name, type, size, value
        name_end = data.index(b"\0", at)
        type_end = data.index(b"\0", name_end + 1)
        name, kind = data[at:name_end].decode(), data[name_end + 1:type_end].decode()
        size = int.from_bytes(data[type_end + 1:type_end + 5], "little")
        value = data[type_end + 5:type_end + 5 + size]
        if name == "channels":
            offset = 0
            while value[offset] != 0:
                end = value.index(b"\0", offset)
                channels.append((value[offset:end].decode(),
                                 int.from_bytes(value[end + 1:end + 5], "little")))
                offset = end + 17
        elif name == "dataWindow":
            window = np.frombuffer(value, "<i4")
        at = type_end + 5 + size
    at += 1
    width, height = window[2] - window[0] + 1, window[3] - window[1] + 1
    if any(kind != 2 for _, kind in channels):
        raise ValueError(f"{path}: expected float channels")
    offsets = np.frombuffer(data, "<u8", count=height, offset=at)
    order = [name for name, _ in channels]
    image = np.empty((height, width, 3))
    for offset in (int(o) for o in offsets):
        y = int.from_bytes(data[offset:offset + 4], "little", signed=True) - window[1]
        line = np.frombuffer(data, "<f4", count=width * len(order),
                             offset=offset + 8).reshape(len(order), width)
        for c, name in enumerate("RGB"):
            image[y, :, c] = line[order.index(name)]
    np.save(cached, image)
    return image


class Cache:
    def __init__(self, folder):
        self.folder = folder
        self.loaded = {}

    def path(self, scene, variant, seed, spp):
        return os.path.join(self.folder, f"{scene}-{variant}-s{seed}-{spp}.exr")

    def has(self, scene, variant, seed, spp):
        return os.path.exists(self.path(scene, variant, seed, spp))

    def get(self, scene, variant, seed, spp):
        path = self.path(scene, variant, seed, spp)
        if path not in self.loaded:
            self.loaded[path] = Render(path)
        return self.loaded[path]

    def scenes(self):
        names = set()
        for path in glob.glob(os.path.join(self.folder, "*-sobol-s1-*.exr")):
            names.add(re.sub(r"-sobol-s1-\d+\.exr$", "", os.path.basename(path)))
        return sorted(names, key=lambda n: (not n.startswith("scene"), n))

    def ladder(self, scene, variant):
        return [n for n in LADDER
                if self.has(scene, variant, 1, n) and self.has(scene, variant, 2, n)]

    def settings(self, scene):
        found = set()
        for path in glob.glob(os.path.join(self.folder, f"{scene}-*=*-s1-*.exr")):
            found.add(re.match(re.escape(scene) + r"-(.+=.+)-s1-\d+\.exr$",
                               os.path.basename(path)).group(1))
        return sorted(found, key=lambda v: (v.split("=")[0], float(v.split("=")[1])))


def noise_relative_mse(first, second):
    """One render's relative MSE from noise alone, from two renders of independent seeds."""
    mean = 0.5 * (first.rgb + second.rgb).mean()
    return np.mean((first.rgb - second.rgb) ** 2) / 2.0 / mean ** 2


def relative_rmse(value):
    return math.sqrt(max(value, 0.0))


def fit_slope(xs, ys):
    lx, ly = np.log(xs), np.log(ys)
    return float(np.polyfit(lx, ly, 1)[0])


def crossover(ladder, noise_mse, bias_mse):
    """The sample count at which one render's noise falls to its bias, on the log-log line
    through the measured noise (extrapolated along the last two points)."""
    if bias_mse <= 0.0:
        return None
    xs, ys = np.log(np.array(ladder, float)), np.log(np.array(noise_mse))
    target = math.log(bias_mse)
    for i in range(len(xs) - 1):
        if ys[i] >= target >= ys[i + 1]:
            t = (target - ys[i]) / (ys[i + 1] - ys[i])
            return math.exp(xs[i] + t * (xs[i + 1] - xs[i]))
    if target > ys[0]:
        return float(ladder[0])
    slope = (ys[-1] - ys[-2]) / (xs[-1] - xs[-2])
    return math.exp(xs[-1] + (target - ys[-1]) / slope)


def worst_share(per_pixel, fraction=0.01):
    flat = np.sort(per_pixel.ravel())[::-1]
    count = max(1, int(round(fraction * flat.size)))
    total = flat.sum()
    return flat[:count].sum() / total if total > 0 else float("nan")


def bias_against(cache, scene, variant, spp, reference):
    """Squared relative bias of `variant` at `spp` (seeds 1, 2) against the exact reference
    (seeds 11, 12), its standard error, and one render's relative noise MSE."""
    a1, a2 = cache.get(scene, variant, 1, spp), cache.get(scene, variant, 2, spp)
    r1, r2 = reference
    mean = 0.5 * (r1.rgb + r2.rgb).mean()
    products = ((a1.rgb - r1.rgb) * (a2.rgb - r2.rgb)).ravel() / mean ** 2
    return (products.mean(), products.std() / math.sqrt(products.size),
            noise_relative_mse(a1, a2), 0.5 * (a1.seconds + a2.seconds) / spp)


def fmt(value, digits=3):
    if value is None or (isinstance(value, float) and math.isnan(value)):
        return "n/a"
    if value == 0:
        return "0"
    if abs(value) >= 1000:
        return f"{value:,.0f}".replace(",", " ")
    return f"{value:.{digits}g}"


def bias_text(bias_mse, stderr):
    if bias_mse < BIAS_SIGMAS * stderr:
        return f"< {fmt(relative_rmse(BIAS_SIGMAS * stderr), 2)} (within noise)"
    return fmt(relative_rmse(bias_mse))


def table(header, rows):
    lines = ["| " + " | ".join(header) + " |", "|" + "---|" * len(header)]
    lines += ["| " + " | ".join(str(c) for c in row) + " |" for row in rows]
    return "\n".join(lines)


def signed_error_image(scene, difference, reference_mean, path, reference="exact"):
    luminance = difference @ np.array([0.2126, 0.7152, 0.0722]) / reference_mean
    figure, axes = plt.subplots(figsize=(4.2, 2.9), dpi=100)
    shown = axes.imshow(luminance, cmap="RdBu_r", vmin=-ERROR_IMAGE_SPAN, vmax=ERROR_IMAGE_SPAN,
                        interpolation="nearest")
    axes.set_title(f"{scene}: default - {reference}", fontsize=9)
    axes.axis("off")
    bar = figure.colorbar(shown, ax=axes, fraction=0.046, pad=0.03)
    bar.set_label("luminance / image mean", fontsize=8)
    bar.ax.tick_params(labelsize=7)
    figure.tight_layout()
    figure.savefig(path)
    plt.close(figure)


def exact_section(cache, scenes, image_dir, link_dir, args):
    rows, setting_rows, images = [], [], []
    for scene in scenes:
        if not (cache.has(scene, "exact", 11, args.exact_spp)
                and cache.has(scene, "exact", 12, args.exact_spp)):
            continue
        ladder = cache.ladder(scene, "sobol")
        top = ladder[-1]
        r1, r2 = (cache.get(scene, "exact", s, args.exact_spp) for s in (11, 12))
        reference = 0.5 * (r1.rgb + r2.rgb)
        mean = reference.mean()
        reference_noise = np.mean((r1.rgb - r2.rgb) ** 2) / 4.0 / mean ** 2
        bias_mse, stderr, noise_mse, _ = bias_against(cache, scene, "sobol", top, (r1, r2))
        a1, a2 = cache.get(scene, "sobol", 1, top), cache.get(scene, "sobol", 2, top)
        error_mse = np.mean((a1.rgb - reference) ** 2) / mean ** 2
        explained = math.sqrt(error_mse / (noise_mse + reference_noise))
        average = 0.5 * (a1.rgb + a2.rgb)
        worst_error = worst_share(((average - reference) ** 2).sum(axis=2))
        worst_noise = worst_share(((a1.rgb - a2.rgb) ** 2).sum(axis=2))
        noise_curve = [noise_relative_mse(cache.get(scene, "sobol", 1, n),
                                          cache.get(scene, "sobol", 2, n)) for n in ladder]
        cross = crossover(ladder, noise_curve, bias_mse) if bias_mse >= BIAS_SIGMAS * stderr \
            else None
        image = f"{scene}-signed-error.png"
        signed_error_image(scene, average - reference, mean, os.path.join(image_dir, image))
        images.append((scene, image))
        rows.append([scene, bias_text(bias_mse, stderr), fmt(relative_rmse(noise_mse)),
                     fmt(relative_rmse(error_mse)), fmt(explained, 3),
                     f"{100 * worst_error:.0f} %", f"{100 * worst_noise:.0f} %",
                     "never (no bias measured)" if cross is None else fmt(cross, 2)])
        for variant in cache.settings(scene):
            key, value = variant.split("=")
            spp = args.settings_spp
            if not cache.has(scene, variant, 2, spp):
                continue
            b, e, n, seconds = bias_against(cache, scene, variant, spp, (r1, r2))
            if key == "hittolerance" and not any(r[0] == scene and r[1].startswith(
                    "default") for r in setting_rows):
                db, de, dn, ds = bias_against(cache, scene, "sobol", spp, (r1, r2))
                setting_rows.append([scene, "default (0.25, 512, 1.2)", bias_text(db, de),
                                     fmt(relative_rmse(dn)),
                                     fmt(relative_rmse(max(db, 0)) / relative_rmse(dn), 2),
                                     "1"])
                default_seconds = ds
            setting_rows.append([scene, f"{SETTING_NAMES[key]} {value}", bias_text(b, e),
                                 fmt(relative_rmse(n)),
                                 fmt(relative_rmse(max(b, 0)) / relative_rmse(n), 2),
                                 fmt(seconds / default_seconds, 3)])
    lines = [
        "## Per pixel, against exact intersection",
        "",
        f"The reference is the program itself with `--exact-geometry`: spheres, polyhedra, "
        f"boxes, capped cylinders, disks, cones, tori no thinner than 1:10 and user SDFs that "
        f"declare an `@intersect` function met in closed form, and sharp CSG blocks of these "
        f"met by walking their leaves' crossings, with the same light transport, "
        f"so that the difference is the sphere tracer's geometry alone. Scenes with a smoothed "
        f"CSG block, a rounded box, a thinner torus or another user SDF have no such reference "
        f"and are left out. Each scene is "
        f"rendered at {args.size[0]}x{args.size[1]}: by default with seeds 1 and 2 up to "
        f"{LADDER[-1]} spp, and exactly with seeds 11 and 12 at {args.exact_spp} spp each.",
        "",
        "- **bias**: the relative RMSE of the default's expectation against the reference's: "
        "the mean over pixels and channels of the product of the two seeds' differences from "
        "the two references (an estimate of the squared bias with no bias of its own), "
        f"reported as within noise when under {BIAS_SIGMAS:g} of its standard errors;",
        "- **noise**: one default render's relative RMSE from noise alone, from the two seeds;",
        "- **error**: one default render (seed 1) against the mean of the two references, and "
        "**explained**, that error over what the render's noise and the reference's noise "
        "account for together (1 = all of it is noise);",
        "- **worst 1 %**: the share of the squared error (of the mean of both seeds) in the 1 % "
        "of pixels where it is largest, beside the same share for noise alone: where the error "
        "is concentrated far beyond noise, it is bias at edges;",
        "- **crossover**: the sample count at which one render's noise falls to its bias, "
        "interpolated on the measured noise curve (extrapolated past it along its last "
        "segment).",
        "",
        table(["scene", "bias", f"noise, {LADDER[-1]} spp", f"error, {LADDER[-1]} spp",
               "explained", "worst 1 %: error", "worst 1 %: noise", "crossover spp"], rows),
        "",
        f"Signed error of the default (mean of both seeds) against the reference, luminance "
        f"over the image's mean: red too bright, blue too dark, saturated at "
        f"+-{ERROR_IMAGE_SPAN:g}. What remains is noise of {2 * LADDER[-1]} and "
        f"{2 * args.exact_spp} samples.",
        "",
    ]
    lines += [" ".join(f"![{scene}]({link_dir}/{image})" for scene, image in images), ""]
    if setting_rows:
        lines += [
            "### The accuracy settings, judged against exact intersection",
            "",
            f"On the scenes that still march (the others meet every object exactly, so "
            f"these settings cannot change their geometry), {args.settings_spp} spp with "
            f"seeds 1 and 2 per value, against the same references. **bias / noise** is the "
            f"bias over one {args.settings_spp}-spp render's noise; **time** is the time per "
            f"sample over the default's (taken from the renders themselves, so while other "
            f"work ran: to about 10 %).",
            "",
            table(["scene", "setting", "bias", f"noise, {args.settings_spp} spp",
                   "bias / noise", "time"], setting_rows),
            "",
        ]
    return lines


def bias_between(a, b):
    """Squared relative bias of renders a = (a1, a2) against renders b = (b1, b2) of other
    seeds (a1 may share b1's seed: their common noise then cancels in a1 - b1), and its
    standard error: the mean of the product of the two seeds' differences."""
    mean = 0.5 * (b[0].rgb + b[1].rgb).mean()
    products = ((a[0].rgb - b[0].rgb) * (a[1].rgb - b[1].rgb)).ravel() / mean ** 2
    return products.mean(), products.std() / math.sqrt(products.size)


def creases_section(cache, image_dir, link_dir, args):
    """Marched solids where they meet other surfaces (issue 36): bench/scenes/creases/."""
    spp = args.crease_spp
    names = sorted(n for n in cache.scenes() if cache.has(n, "converged", 11, spp))
    if not names:
        return []
    rows, checks, images = [], [], []
    for scene in names:
        ladder = cache.ladder(scene, "sobol")
        top = ladder[-1]
        kind = "exact" if cache.has(scene, "exact", 11, spp) else "converged"
        r1, r2 = (cache.get(scene, kind, s, spp) for s in (11, 12))
        reference = 0.5 * (r1.rgb + r2.rgb)
        mean = reference.mean()
        reference_noise = np.mean((r1.rgb - r2.rgb) ** 2) / 4.0 / mean ** 2
        a1, a2 = cache.get(scene, "sobol", 1, top), cache.get(scene, "sobol", 2, top)
        bias_mse, stderr = bias_between((a1, a2), (r1, r2))
        noise_mse = noise_relative_mse(a1, a2)
        error_mse = np.mean((a1.rgb - reference) ** 2) / mean ** 2
        explained = math.sqrt(error_mse / (noise_mse + reference_noise))
        average = 0.5 * (a1.rgb + a2.rgb)
        worst_error = worst_share(((average - reference) ** 2).sum(axis=2))
        worst_noise = worst_share(((a1.rgb - a2.rgb) ** 2).sum(axis=2))
        noise_curve = [noise_relative_mse(cache.get(scene, "sobol", 1, n),
                                          cache.get(scene, "sobol", 2, n)) for n in ladder]
        significant = bias_mse >= BIAS_SIGMAS * stderr
        cross = crossover(ladder, noise_curve, bias_mse) if significant else None
        # One render's noise at 4096 spp, from the noise at the ladder's top.
        noise_4096 = math.sqrt(noise_mse * top / 4096.0)
        bound = relative_rmse(bias_mse if significant else BIAS_SIGMAS * stderr)
        image = f"{scene}-signed-error.png"
        signed_error_image(scene, average - reference, mean, os.path.join(image_dir, image), kind)
        images.append((scene, image))
        before = ""
        if cache.has(scene, "before", 1, spp) and cache.has(scene, "before", 2, spp):
            b1, b2 = cache.get(scene, "before", 1, spp), cache.get(scene, "before", 2, spp)
            before_bias, before_stderr = bias_between((b1, b2), (r1, r2))
            before_error = np.mean((b1.rgb - reference) ** 2) / mean ** 2
            before_worst = worst_share(((0.5 * (b1.rgb + b2.rgb) - reference) ** 2).sum(axis=2))
            before = (f"{bias_text(before_bias, before_stderr)}; explained "
                      f"{math.sqrt(before_error / (noise_relative_mse(b1, b2) + reference_noise)):.3g}"
                      f"; worst 1 % {100 * before_worst:.0f} %")
            image = f"{scene}-before-signed-error.png"
            signed_error_image(scene + " (before)", 0.5 * (b1.rgb + b2.rgb) - reference, mean,
                               os.path.join(image_dir, image), kind)
        rows.append([scene, "exact intersection" if kind == "exact" else "converged march",
                     bias_text(bias_mse, stderr), fmt(relative_rmse(noise_mse)),
                     fmt(relative_rmse(error_mse)), fmt(explained, 3),
                     f"{100 * worst_error:.0f} %", f"{100 * worst_noise:.0f} %",
                     "never (no bias measured)" if cross is None else fmt(cross, 2),
                     fmt(bound / noise_4096, 2), before or "n/a"])
        converged = tuple(cache.get(scene, "converged", s, spp) for s in (11, 12))
        judge = "exact" if kind == "exact" else "halved"
        judged = tuple(cache.get(scene, judge, s, spp) for s in (11, 12))
        check_bias, check_stderr = bias_between(converged, judged)
        check_noise = noise_relative_mse(*converged)
        checks.append([scene, "exact intersection" if judge == "exact" else
                       "itself at half the tolerance", bias_text(check_bias, check_stderr),
                       fmt(relative_rmse(check_noise)),
                       fmt(relative_rmse(max(check_bias, BIAS_SIGMAS * check_stderr)) /
                           math.sqrt(check_noise * spp / 4096.0), 2)])
    lines = [
        "## Per pixel, marched solids where they meet other surfaces",
        "",
        "Solids that every render marches, standing on a floor or against a wall "
        "(`bench/scenes/creases/`): a CSG difference and a CSG intersection on a floor in the "
        "open, a smooth union in a closed room, a user SDF against a wall. Where the solid is a "
        "sharp CSG block of shapes with a closed form, the reference is `--exact-geometry`, "
        "which walks the leaves' exact crossings (shadergen/ExactCsgIntersection.h); where it has "
        "none (smooth unions, user SDFs), the reference is the **converged march**: the default "
        "renderer at a sixteenth of the default hit tolerance (`--hit-tolerance 0.015625 "
        "--max-steps 4096`). Default renders with seeds 1 and 2 up to "
        f"{spp} spp, references with seeds 11 and 12 at {spp} spp each; columns as "
        "above, and **bias / noise at 4096 spp**, the bias (or its bound, where within noise) "
        "over one 4096-spp render's noise, which must stay under 1. **before** is the "
        "renderer before issue 36 against the same reference, at "
        f"{spp} spp.",
        "",
        table(["scene", "reference", "bias", f"noise, {spp} spp",
               f"error, {spp} spp", "explained", "worst 1 %: error",
               "worst 1 %: noise", "crossover spp", "bias / noise at 4096 spp", "before"],
              rows),
        "",
        "The converged march, judged: against exact intersection where there is one, and "
        "against itself at half its tolerance (`--hit-tolerance 0.0078125 --max-steps 8192`) "
        f"where there is none, seeds 11 and 12 at {spp} spp each.",
        "",
        table(["scene", "converged march against", "bias", f"noise, {spp} spp",
               "bias / noise at 4096 spp"], checks),
        "",
        f"Signed error of the default (mean of both seeds) against the reference, as above; "
        f"where the renderer before issue 36 was rendered, its image follows.",
        "",
    ]
    shown = []
    for scene, image in images:
        shown.append(f"![{scene}]({link_dir}/{image})")
        if os.path.exists(os.path.join(image_dir, f"{scene}-before-signed-error.png")):
            shown.append(f"![{scene}, before]({link_dir}/{scene}-before-signed-error.png)")
    lines += [" ".join(shown), ""]
    return lines


def flat_plane_image(rgb, reference, path):
    """Writes the flat plane's noise (the render less a 1024-spp render of another seed) at
    full contrast; returns its correlation with its neighbours 1 and 2 pixels across and
    down."""
    weights = np.array([0.2126, 0.7152, 0.0722])
    residual = rgb @ weights - reference @ weights
    spread = 1.4826 * np.median(np.abs(residual - np.median(residual))) or 1.0
    plt.imsave(path, np.clip(residual / spread, -3, 3), cmap="gray", vmin=-3, vmax=3)

    def correlation(a, b):
        return float(np.corrcoef(a.ravel(), b.ravel())[0, 1])
    return (correlation(residual[:, :-1], residual[:, 1:]),
            correlation(residual[:-1, :], residual[1:, :]),
            correlation(residual[:, :-2], residual[:, 2:]),
            correlation(residual[:-2, :], residual[2:, :]))


def convergence_plot(cache, scenes, path):
    columns = 4
    rows = math.ceil(len(scenes) / columns)
    figure, grid = plt.subplots(rows, columns, figsize=(3.1 * columns, 2.5 * rows), dpi=90,
                                squeeze=False)
    for axes, scene in zip(grid.ravel(), scenes):
        for sampler, colour in (("independent", "tab:red"), ("sobol", "tab:blue")):
            ladder = [n for n in cache.ladder(scene, sampler) if n in cache.ladder(scene, "sobol")]
            values = [noise_relative_mse(cache.get(scene, sampler, 1, n),
                                         cache.get(scene, sampler, 2, n)) for n in ladder]
            axes.loglog(ladder, values, "o-", color=colour, markersize=3,
                        label=f"{sampler} ({fit_slope(ladder[-3:], values[-3:]):.2f})")
        guide = np.array([LADDER[0], LADDER[-1]], float)
        axes.loglog(guide, values[0] * guide[0] / guide * 1.0, ":", color="grey", linewidth=1)
        axes.set_title(scene, fontsize=8)
        axes.tick_params(labelsize=6)
        axes.legend(fontsize=6, loc="lower left")
    for axes in grid.ravel()[len(scenes):]:
        axes.axis("off")
    figure.suptitle("relative MSE from noise against samples per pixel (slope of the last "
                    "three points; dotted: slope -1)", fontsize=9)
    figure.tight_layout()
    figure.savefig(path)
    plt.close(figure)


def interpolate_log(ladder, values, x):
    lx, ly = np.log(np.array(ladder, float)), np.log(np.array(values))
    return math.exp(np.interp(math.log(x), lx, ly))


def sampler_section(cache, scenes, image_dir, link_dir, args):
    rows, time_rows, equal_time_rows, exact_rows = [], [], [], []
    ratios_256 = []
    for scene in scenes:
        ladder = [n for n in cache.ladder(scene, "sobol") if n in cache.ladder(scene,
                                                                                 "independent")]
        curves = {s: [noise_relative_mse(cache.get(scene, s, 1, n), cache.get(scene, s, 2, n))
                      for n in ladder] for s in ("independent", "sobol")}
        cells = [scene]
        for n in (16, 64, 256):
            if n in ladder:
                i = ladder.index(n)
                ind, sob = relative_rmse(curves["independent"][i]), relative_rmse(
                    curves["sobol"][i])
                cells.append(f"{fmt(ind)} / {fmt(sob)} (**{sob / ind:.2f}**)")
                if n == 256:
                    ratios_256.append(sob / ind)
            else:
                cells.append("")
        top = ladder[-1]
        seconds = {s: 0.5 * (cache.get(scene, s, 1, top).seconds +
                             cache.get(scene, s, 2, top).seconds) / top
                   for s in ("independent", "sobol")}
        slopes = {s: fit_slope(ladder[-3:], curves[s][-3:]) for s in curves}
        cells += [f"{slopes['independent']:.2f} / {slopes['sobol']:.2f}"]
        rows.append(cells)
        time_rows.append([scene, f"{1e3 * seconds['independent']:.2f}",
                          f"{1e3 * seconds['sobol']:.2f}",
                          f"{seconds['sobol'] / seconds['independent']:.3f}"])
        # Equal time: the independent sampler's time for 256 spp (or the ladder's top) spent
        # on Sobol samples, its noise read off its measured curve.
        n = 256 if 256 in ladder else top
        budget = n * seconds["independent"]
        sobol_samples = budget / seconds["sobol"]
        ind = relative_rmse(curves["independent"][ladder.index(n)])
        sob = relative_rmse(interpolate_log(ladder, curves["sobol"],
                                            min(max(sobol_samples, ladder[0]), ladder[-1])))
        equal_time_rows.append([scene, f"{budget:.2f} s", fmt(ind), f"{sobol_samples:.0f}",
                                fmt(sob), f"**{sob / ind:.2f}**"])
        if cache.has(scene, "exact", 11, args.exact_spp) and 256 in ladder:
            r1, r2 = (cache.get(scene, "exact", s, args.exact_spp) for s in (11, 12))
            reference = 0.5 * (r1.rgb + r2.rgb)
            mean = reference.mean()
            totals = {}
            for s in ("independent", "sobol"):
                errors = [np.mean((cache.get(scene, s, seed, 256).rgb - reference) ** 2)
                          for seed in (1, 2)]
                totals[s] = math.sqrt(np.mean(errors)) / mean
            exact_rows.append([scene, fmt(totals["independent"]), fmt(totals["sobol"]),
                               f"**{totals['sobol'] / totals['independent']:.2f}**"])
    plot = "sampler-convergence.png"
    convergence_plot(cache, scenes, os.path.join(image_dir, plot))
    flats, flat_rows = [], []
    flat_reference = os.path.join(cache.folder, "flat-plane-reference.exr")
    for sampler in ("sobol", "independent"):
        for spp in (1, 4):
            source = os.path.join(cache.folder, f"flat-plane-{sampler}-{spp}.exr")
            if os.path.exists(source) and os.path.exists(flat_reference):
                name = f"flat-plane-{sampler}-{spp}spp.png"
                correlations = flat_plane_image(read_exr_rgb(source),
                                                read_exr_rgb(flat_reference),
                                                os.path.join(image_dir, name))
                flats.append((f"{sampler}, {spp} spp", name))
                flat_rows.append([sampler, spp] + [f"{c:+.3f}" for c in correlations])
    geometric = math.exp(np.mean(np.log(ratios_256))) if ratios_256 else float("nan")
    lines = [
        "## Sobol points against independent samples",
        "",
        "`--sampler sobol` (the default) draws the pixel point and, for the first four "
        "bounces, every decision (light choice, light point, BSDF lobe, BSDF direction, "
        "roulette) from Owen-scrambled Sobol points (Burley 2020), one scramble per pixel "
        "and seed; `--sampler independent` draws every number from a hash-seeded random "
        "stream. The error here is noise alone, one render's relative RMSE from two seeds: "
        "both samplers share the geometry, so any bias is the same for both and would only "
        f"dilute the ratio. {args.size[0]}x{args.size[1]}, both samplers to 256 spp (Sobol "
        f"to {LADDER[-1]} where the exact reference judges it).",
        "",
        "### Equal samples",
        "",
        "Independent / Sobol relative RMSE, and **Sobol over independent** (under 1: Sobol "
        "is better; its square is the ratio of samples needed for the same error). The last "
        "column is the slope of relative MSE against samples over the last three points "
        "(-1 for independent samples).",
        "",
        table(["scene", "16 spp", "64 spp", "256 spp", "MSE slope ind / Sobol"],
              rows),
        "",
        f"Geometric mean of the 256-spp ratio over the {len(ratios_256)} scenes: "
        f"**{geometric:.2f}** ({1 / geometric ** 2:.1f}x fewer samples for the same error).",
        "",
        f"![convergence of both samplers]({link_dir}/{plot})",
        "",
        "### Against the exact reference, at 256 spp",
        "",
        "The whole error (noise and any bias) of one 256-spp render against the exact "
        "reference, where the scene has one: what a comparison with an independent renderer "
        "measures.",
        "",
        table(["scene", "independent", "Sobol", "Sobol / independent"], exact_rows),
        "",
        "### Time per sample and equal time",
        "",
        f"Milliseconds per sample per pixel at {args.size[0]}x{args.size[1]}, from the renders' "
        "own times (they ran while other work shared the machine; the side-by-side "
        "measurement is in docs/PERFORMANCE.md).",
        "",
        table(["scene", "independent ms", "Sobol ms", "Sobol / independent"], time_rows),
        "",
        "Equal time: the time the independent sampler takes for 256 spp, spent on Sobol "
        "samples, its error read off its measured curve (clamped to the curve's ends).",
        "",
        table(["scene", "budget", "independent", "Sobol spp", "Sobol", "Sobol / independent"],
              equal_time_rows),
        "",
        "### Structured artefacts",
        "",
        "A flat Lambertian floor under a sphere light and a grey sky "
        "(`bench/scenes/flat-lit-plane.in`), 320x240: each pixel integrates nearly the same "
        "function, so any pattern shared between pixels would show. Each image shows the "
        "render's luminance less that of a 1024-spp render (independent samples, another "
        "seed), over its robust spread (1.4826 median absolute deviations), saturated at +-3: noise at full "
        "contrast. The table gives the correlation of that residual between neighbours at "
        "one and two pixels' distance, across and down: for white noise they are 0 within "
        f"about +-{2 / math.sqrt(320 * 240):.3f} (two standard errors).",
        "",
    ]
    lines += [" ".join(f"![{label}]({link_dir}/{name})" for label, name in flats), "",
              "(left to right: " + ", ".join(label for label, _ in flats) + ")", "",
              table(["sampler", "spp", "1 across", "1 down", "2 across", "2 down"],
                    flat_rows), ""]
    return lines


def main():
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("cache")
    parser.add_argument("markdown")
    parser.add_argument("image_dir")
    parser.add_argument("--size", nargs=2, type=int, default=[160, 120])
    parser.add_argument("--exact-spp", type=int, default=2048)
    parser.add_argument("--settings-spp", type=int, default=256)
    parser.add_argument("--crease-spp", type=int, default=1024)
    parser.add_argument("--command", default="tools/per-pixel-report.sh")
    parser.add_argument("--only-creases", action="store_true",
                        help="write only the section on marched solids' creases")
    args = parser.parse_args()
    os.makedirs(args.image_dir, exist_ok=True)
    link_dir = os.path.relpath(args.image_dir, os.path.dirname(os.path.abspath(args.markdown)))
    cache = Cache(args.cache)
    scenes = [s for s in cache.scenes() if cache.ladder(s, "independent")]
    text = open(args.markdown).read() if os.path.exists(args.markdown) else ""
    if not args.only_creases:
        lines = [BEGIN, ""]
        lines += exact_section(cache, scenes, args.image_dir, link_dir, args)
        lines += sampler_section(cache, scenes, args.image_dir, link_dir, args)
        lines += [f"Regenerate these sections with `{args.command}`.", "", END]
        text = replace_block(text, BEGIN, END, "\n".join(lines))
    lines = [CREASES_BEGIN, ""]
    lines += creases_section(cache, args.image_dir, link_dir, args)
    lines += [f"Regenerate this section with `PER_PIXEL_ONLY=creases {args.command}`.", "",
              CREASES_END]
    text = replace_block(text, CREASES_BEGIN, CREASES_END, "\n".join(lines))
    with open(args.markdown, "w") as file:
        file.write(text)


def replace_block(text, begin, end, section):
    """`text` with what lies between the markers `begin` and `end` replaced by `section`
    (which holds them), or with `section` appended where they are missing."""
    if begin in text and end in text:
        return text[:text.index(begin)] + section + text[text.index(end) + len(end):]
    return text.rstrip("\n") + "\n\n" + section + "\n"


if __name__ == "__main__":
    main()
