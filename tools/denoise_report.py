"""Measures what Open Image Denoise does to the renderer's images and writes the "Denoising"
section of docs/ACCURACY.md (issue 34), its error images and the gallery triple.

    ~/.local/share/raytracer/oidn-venv/bin/python tools/denoise_report.py [options]

(tools/denoise-report.sh runs it with that interpreter, which holds numpy and
flip-evaluator; tools/install-dependencies.sh makes it.) For each scene it renders, at
160x120 by default: a reference of 1024 spp (seed 1000), then 4, 16, 64 and 256 spp (seed 1)
with --denoise, and measures raw and denoised against the reference: the relative RMSE of
docs/ACCURACY.md ("How it is measured": sqrt(mean (x - ref)^2) / mean ref, linear radiance)
and FLIP (Andersson et al. 2020, the `flip-evaluator` package) on the pictures as the
program tone-maps them (exposure 4, Hable's curve, gamma 2.2; film/ToneCurve.h). Then it
times `raytracer denoise` at 800x600 and 1920x1080. Renders are cached in the work folder
(build-denoise/ by default) and reused while the scene file and size are unchanged.
"""

import argparse
import os
import re
import statistics
import subprocess
import sys

import numpy as np

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
BEGIN, END = "<!-- denoising:begin -->", "<!-- denoising:end -->"

# film/ToneCurve.h
A, B, C, D, E, F = 0.15, 0.50, 0.10, 0.20, 0.02, 0.30
WHITE, GAMMA, EXPOSURE = 11.2, 2.2, 4.0


def hable(x):
    return ((x * (A * x + C * B) + D * E) / (x * (A * x + B) + D * F)) - E / F


def display(radiance):
    mapped = hable(EXPOSURE * np.maximum(radiance, 0.0)) / hable(WHITE)
    return np.clip(mapped, 0.0, 1.0) ** (1.0 / GAMMA)


def read_pfm(path):
    with open(path, "rb") as f:
        kind = f.readline().strip()
        width, height = map(int, f.readline().split())
        scale = float(f.readline())
        channels = 3 if kind == b"PF" else 1
        data = np.frombuffer(f.read(), dtype="<f4" if scale < 0 else ">f4")
    # PFM rows run bottom first.
    return data.reshape(height, width, channels)[::-1].astype(np.float64)


def write_png(path, picture):
    """`picture`: display values in [0, 1], HxWx3; through a PPM and oiiotool."""
    ppm = path[:-4] + ".ppm"
    height, width, _ = picture.shape
    with open(ppm, "wb") as f:
        f.write(b"P6\n%d %d\n255\n" % (width, height))
        f.write((np.clip(picture, 0, 1) * 255 + 0.5).astype(np.uint8).tobytes())
    subprocess.run(["oiiotool", ppm, "-o", path], check=True)
    os.remove(ppm)


def relative_rmse(image, reference):
    return float(np.sqrt(np.mean((image - reference) ** 2)) / np.mean(reference))


def brightest_share(image, reference):
    """The share of the image's squared error in the brightest 1 % of the reference's pixels
    (lights seen directly, caustics): where the relative RMSE is decided."""
    luminance = reference.mean(axis=2)
    brightest = luminance >= np.quantile(luminance, 0.99)
    squared = ((image - reference) ** 2).sum(axis=2)
    return float(squared[brightest].sum() / squared.sum())


def flip(image, reference):
    import flip_evaluator
    error_map, mean, _ = flip_evaluator.evaluate(
        display(reference).astype(np.float32), display(image).astype(np.float32), "LDR")
    return float(mean), error_map


def render(raytracer, scene, size, spp, seed, output, extra=()):
    """Renders unless `output` is newer than the scene file; returns the summary line."""
    log = output + ".log"
    if (os.path.exists(output) and os.path.exists(log)
            and os.path.getmtime(output) > os.path.getmtime(scene)):
        return open(log).read()
    command = [raytracer, scene, str(size[0]), str(size[1]), "--spp", str(spp), "--seed",
               str(seed), "--headless", "--quiet", "-o", output, *extra]
    print(" ".join(command), file=sys.stderr, flush=True)
    result = subprocess.run(command, capture_output=True, text=True)
    if result.returncode != 0:
        sys.exit(f"denoise-report: {' '.join(command)} failed: {result.stderr.strip()}")
    line = result.stdout
    open(log, "w").write(line)
    return line


def denoise_seconds(line):
    match = re.search(r"denoised in ([0-9.]+) s", line)
    return float(match.group(1)) if match else float("nan")


def measure_scene(args, scene):
    name = os.path.splitext(os.path.basename(scene))[0]
    work = os.path.join(args.work, name)
    os.makedirs(work, exist_ok=True)
    reference_file = os.path.join(work, f"reference-{args.reference_spp}.pfm")
    render(args.raytracer, scene, args.size, args.reference_spp, 1000, reference_file)
    reference = read_pfm(reference_file)
    rows = []
    images = {}
    for spp in args.spp:
        raw_file = os.path.join(work, f"raw-{spp}.pfm")
        line = render(args.raytracer, scene, args.size, spp, 1, raw_file, ["--denoise"])
        raw = read_pfm(raw_file)
        denoised = read_pfm(os.path.join(work, f"raw-{spp}.denoised.pfm"))
        raw_flip, raw_map = flip(raw, reference)
        denoised_flip, denoised_map = flip(denoised, reference)
        rows.append({"spp": spp, "raw_rmse": relative_rmse(raw, reference),
                     "brightest_share": brightest_share(denoised, reference),
                     "brightness": float(denoised.mean() / reference.mean()),
                     "denoised_rmse": relative_rmse(denoised, reference),
                     "raw_flip": raw_flip, "denoised_flip": denoised_flip,
                     "seconds": denoise_seconds(line)})
        images[spp] = (raw, denoised, raw_map, denoised_map)
    return name, reference, rows, images


def crossover(rows, metric):
    for row in rows:
        if row["raw_" + metric] <= row["denoised_" + metric]:
            return str(row["spp"])
    return f"none up to {rows[-1]['spp']}"


def error_image(args, name, reference, images, spp):
    """raw | denoised | reference | FLIP raw | FLIP denoised | where the denoiser is worse."""
    raw, denoised, raw_map, denoised_map = images[spp]
    # Per pixel: the denoised image's error minus the raw one's (luminance, tone-mapped):
    # red where denoising made the pixel worse (smear), blue where it helped.
    weights = np.array([0.2126, 0.7152, 0.0722])
    raw_error = np.abs(display(raw) - display(reference)) @ weights
    denoised_error = np.abs(display(denoised) - display(reference)) @ weights
    worse = np.clip((denoised_error - raw_error) * 10.0, 0, 1)
    better = np.clip((raw_error - denoised_error) * 10.0, 0, 1)
    difference = np.stack([worse, np.zeros_like(worse), better], axis=-1)
    panels = [display(raw), display(denoised), display(reference), raw_map, denoised_map,
              difference]
    gap = np.ones((reference.shape[0], 2, 3))
    row = []
    for panel in panels:
        row += [panel[..., :3], gap]
    path = os.path.join(args.images, f"{name}-{spp}spp.png")
    write_png(path, np.concatenate(row[:-1], axis=1))
    return path


def gallery(args, name, reference, images, spp):
    raw, denoised, _, _ = images[spp]
    gap = np.ones((reference.shape[0], 2, 3))
    triple = np.concatenate([display(raw), gap, display(denoised), gap, display(reference)],
                            axis=1)
    triple = triple.repeat(2, axis=0).repeat(2, axis=1)  # 2x, nearest: the pixels as rendered
    path = os.path.join(ROOT, "docs", f"denoising-{name}-{spp}spp.png")
    write_png(path, triple)
    return path


def time_denoise(args, scene, width, height):
    """`raytracer denoise` on a 1-spp render with features, the median of three."""
    work = os.path.join(args.work, "timing")
    os.makedirs(work, exist_ok=True)
    source = os.path.join(work, f"{width}x{height}.exr")
    render(args.raytracer, scene, (width, height), 1, 1, source, ["--feature-buffers"])
    seconds = []
    for _ in range(3):
        line = subprocess.run([args.raytracer, "denoise", source,
                               os.path.join(work, f"{width}x{height}-denoised.exr")],
                              check=True, capture_output=True, text=True).stdout
        seconds.append(float(re.search(r"in ([0-9.]+) s", line).group(1)))
    return statistics.median(seconds)


def section(args, results, timings, library, cpu):
    rel = lambda path: os.path.relpath(path, os.path.dirname(args.markdown))  # noqa: E731
    out = [BEGIN, "", "## Denoising", ""]
    out.append(
        "`--denoise` writes each output a second time, denoised by Intel Open Image Denoise "
        "(OIDN, its `RT` filter on HDR radiance, guided by the first-hit albedo and normal "
        "of `--feature-buffers`; docs/DENOISING.md), beside the raw one. A denoiser trades "
        "noise for bias: it replaces a pixel by a weighted mean of its neighbours, which is "
        "not the pixel's expectation where the image has detail the features do not show "
        "(caustics, textures seen through glass, shadows' edges, thin geometry). Here both "
        "are measured against a reference of "
        f"{args.reference_spp} spp (seed 1000) at {args.size[0]}x{args.size[1]}; raw and "
        "denoised are the same render (seed 1). The reference's own noise, about "
        f"{(args.spp[-1] / args.reference_spp) ** 0.5:.2g} times the raw error at "
        f"{args.spp[-1]} spp, is a floor under both columns at the largest counts.")
    out.append("")
    out.append(
        "- **rel RMSE**: as in \"How it is measured\", sqrt(mean (x - ref)^2) / mean ref on "
        "linear radiance: the brightest pixels (lights, caustics) dominate it.")
    out.append(
        "- **FLIP**: the mean of NVIDIA's perceptual error FLIP (LDR, the `flip-evaluator` "
        "package) between the pictures as the program tone-maps them (exposure 4, Hable's "
        "curve, gamma 2.2): what a viewer sees. 0 is identical.")
    out.append(
        "- **brightest 1 %**: the share of the denoised image's squared error that lies in "
        "the brightest 1 % of the reference's pixels (lights seen directly, caustics).")
    out.append(
        "- **mean**: the denoised image's mean radiance over the reference's (the raw "
        "image's is 1 within its noise): energy the denoiser loses or adds.")
    out.append(
        "- **overtakes at**: the first sample count whose raw image is no worse than the "
        "denoised one, by that metric.")
    out.append("")
    out.append("| scene | spp | rel RMSE raw | rel RMSE denoised | FLIP raw | FLIP denoised | "
               "brightest 1 % | mean |")
    out.append("|---|---|---|---|---|---|---|---|")
    for name, _, rows, _ in results:
        for row in rows:
            out.append(f"| {name} | {row['spp']} | {row['raw_rmse']:.4f} | "
                       f"{row['denoised_rmse']:.4f} | {row['raw_flip']:.4f} | "
                       f"{row['denoised_flip']:.4f} | {100 * row['brightest_share']:.0f} % | "
                       f"{row['brightness']:.4f} |")
    out.append("")
    out.append("| scene | raw overtakes denoised (rel RMSE) | (FLIP) |")
    out.append("|---|---|---|")
    for name, _, rows, _ in results:
        out.append(f"| {name} | {crossover(rows, 'rmse')} | {crossover(rows, 'flip')} |")
    out.append("")
    out.append("**Where it smears.** Each picture below is, left to right: the 16-spp raw "
               "render, the same denoised, the reference, FLIP's error map of the raw and of "
               "the denoised picture (magma: black none, yellow most), and where denoising "
               "made a pixel worse (red) or better (blue) than the raw one, in tone-mapped "
               "luminance, times 10.")
    out.append("")
    for name, path in args.error_images:
        out.append(f"![{name}, 16 spp: raw, denoised, reference, FLIP raw, FLIP denoised, "
                   f"worse/better]({rel(path)})")
        out.append("")
    out.append("<!-- denoising-reading:begin -->")
    out.append("<!-- denoising-reading:end -->")
    out.append("")
    out.append(f"**What a denoise costs** (`raytracer denoise`, OIDN's CPU device, {cpu}; "
               "median of three; the library from " + library + "):")
    out.append("")
    out.append("| size | seconds |")
    out.append("|---|---|")
    for (width, height), seconds in timings:
        out.append(f"| {width}x{height} | {seconds:.2f} |")
    out.append("")
    out.append("Regenerate: `tools/denoise-report.sh` (renders cached in `build-denoise/`; "
               "its header lists the options).")
    out.append("")
    out.append(END)
    return "\n".join(out) + "\n"


def splice(markdown, text):
    page = open(markdown).read()
    if BEGIN in page and END in page:
        before, rest = page.split(BEGIN, 1)
        old, after = rest.split(END, 1)
        # The reading is written by hand: kept.
        rb, re_ = "<!-- denoising-reading:begin -->", "<!-- denoising-reading:end -->"
        if rb in old and re_ in old:
            reading = old[old.index(rb):old.index(re_) + len(re_)]
            text = text.replace(rb + "\n" + re_, reading)
        page = before + text.rstrip("\n") + after
    else:
        at = page.find("\n## Convergence")
        at = len(page) if at < 0 else at + 1
        page = page[:at] + text + "\n" + page[at:]
    open(markdown, "w").write(page)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("scenes", nargs="*", default=[
        f"scenes/{s}.in" for s in (
            "scene1", "scene2", "scene3", "scene4", "scene5", "scene7",
            "fig02-materials-cornell", "fig03-shadows-point-light", "fig03-shadows-sphere-light",
            "fig04-csg-solid", "fig06-triplanar-textures", "fig07-glass-textures-lights",
            "fig09-glass-mirrors-checker", "fig10-many-objects-glossy-floor", "fig11-torus-knot",
            "fig12-csg-diffuse", "fig13-glass-mirror-cornell", "fig14-smooth-csg-cornell",
            "thin-bars")])
    parser.add_argument("--raytracer", default=os.path.join(ROOT, "build", "raytracer"))
    parser.add_argument("--size", type=int, nargs=2, default=[160, 120])
    parser.add_argument("--spp", type=int, nargs="+", default=[4, 16, 64, 256])
    parser.add_argument("--reference-spp", type=int, default=1024)
    parser.add_argument("--work", default=os.path.join(ROOT, "build-denoise"))
    parser.add_argument("--markdown", default=os.path.join(ROOT, "docs", "ACCURACY.md"))
    parser.add_argument("--images", default=os.path.join(ROOT, "docs", "accuracy", "denoising"))
    parser.add_argument("--error-images", nargs="*",
                        default=["scene1", "scene7", "fig03-shadows-sphere-light",
                                 "fig06-triplanar-textures", "fig07-glass-textures-lights",
                                 "fig10-many-objects-glossy-floor", "fig11-torus-knot",
                                 "fig13-glass-mirror-cornell", "thin-bars"],
                        help="scenes whose 16-spp error image the page shows")
    parser.add_argument("--gallery", default="scene1", help="scene of docs/denoising-*.png")
    parser.add_argument("--timing-sizes", default="800x600,1920x1080")
    parser.add_argument("--no-section", action="store_true",
                        help="write the error images and print the rows, but neither time the "
                             "denoiser nor rewrite the section (a scene added to it)")
    args = parser.parse_args()
    os.makedirs(args.images, exist_ok=True)

    results = []
    for scene in args.scenes:
        results.append(measure_scene(args, os.path.join(ROOT, scene)))
        name, _, rows, _ = results[-1]
        for row in rows:
            print(name, row, file=sys.stderr, flush=True)
    shown = []
    for name, reference, _, images in results:
        if name in args.error_images and 16 in images:
            shown.append((name, error_image(args, name, reference, images, 16)))
        if name == args.gallery and 16 in images:
            gallery(args, name, reference, images, 16)
    args.error_images = shown
    if args.no_section:
        for name, _, rows, _ in results:
            for row in rows:
                print(f"| {name} | {row['spp']} | {row['raw_rmse']:.4f} | "
                      f"{row['denoised_rmse']:.4f} | {row['raw_flip']:.4f} | "
                      f"{row['denoised_flip']:.4f} | {100 * row['brightest_share']:.0f} % | "
                      f"{row['brightness']:.4f} |")
            print(f"| {name} | {crossover(rows, 'rmse')} | {crossover(rows, 'flip')} |")
        for name, path in shown:
            print(name, path)
        return

    timings = []
    for size in args.timing_sizes.split(","):
        width, height = map(int, size.split("x"))
        timings.append(((width, height),
                        time_denoise(args, os.path.join(ROOT, "scenes", "scene1.in"), width,
                                     height)))
    library = subprocess.run(
        ["sh", "-c", "ls -d ${RAYTRACER_OIDN_LIBRARY:-$HOME/.local/share/raytracer/oidn-venv/"
         "lib/python3*/site-packages/pyoidn} 2>/dev/null | head -1"],
        capture_output=True, text=True).stdout.strip()
    version = re.search(r"pyoidn[^/]*", library)
    pip = subprocess.run([sys.executable, "-m", "pip", "show", "pyoidn"], capture_output=True,
                         text=True).stdout
    pyoidn = re.search(r"Version: (\S+)", pip)
    library = f"the pyoidn {pyoidn.group(1)} wheel" if pyoidn else (version.group(0)
                                                                     if version else "?")
    cpu = subprocess.run(["sh", "-c", "nproc; grep -m1 'model name' /proc/cpuinfo"],
                         capture_output=True, text=True).stdout.split("\n")
    cpu_text = f"{cpu[0]} cores of {cpu[1].split(':', 1)[-1].strip()}" if len(cpu) > 1 else "?"
    splice(args.markdown, section(args, results, timings, library, cpu_text))


if __name__ == "__main__":
    main()
