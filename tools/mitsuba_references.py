#!/usr/bin/env python3
"""The rough materials and the thin lens held to an independent renderer, Mitsuba 3.

    python3 -m venv /work/venvs/mitsuba && /work/venvs/mitsuba/bin/pip install mitsuba numpy
    /work/venvs/mitsuba/bin/python tools/mitsuba_references.py --raytracer build/raytracer \\
        [--size 160 120] [--spp 1024] [--reference-spp 4096] [--cache DIR] [--scenes a,b]
    /work/venvs/mitsuba/bin/python tools/mitsuba_references.py --metals

Each comparison scene is described once below, in plain values, and written from that
description both as one of our scene files (bench/scenes/mitsuba/NAME.in, committed) and as
a Mitsuba scene (its scalar_rgb variant, on the CPU): the same camera (look-at, vertical
field of view, box pixel filter), the same units and radiometry (a sphere light is a sphere
with an area emitter of the same radiance and a black BSDF; the environment a `constant`
emitter), spheres and planes (a half-space of ours, a large rectangle of Mitsuba's), and the
materials Mitsuba has: `diffuse`, `roughconductor` and `roughdielectric` with the GGX
distribution and visible-normal sampling, the metals by Mitsuba's own names (our table of
metals holds the RGB values Mitsuba derives for them: --metals prints them), and the
`thinlens` sensor. Mitsuba's GGX has no energy compensation, its dielectric Fresnel is the
exact one and its masking-shadowing Smith's separable G1 G1: ours renders with
--no-energy-compensation, --fresnel exact and --masking separable, the same model, and once
more with our default height-correlated masking to show what that changes. Paths: 16
scattering events after the camera ray (Mitsuba's max_depth 17).

Each renderer renders each scene twice, with independent seeds; the section between the
markers <!-- mitsuba:begin --> and <!-- mitsuba:end --> of docs/ACCURACY.md is rewritten
with the per-pixel comparison (relative RMSE of bias, noise and error, as the exact-reference
sections measure them), and docs/accuracy/mitsuba/ receives each scene's picture, both ways,
with its signed error. Renders are cached in --cache under the scene's text and the settings.
"""

import argparse
import hashlib
import math
import os
import subprocess
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.normpath(os.path.join(HERE, ".."))
SCENE_DIR = os.path.join(ROOT, "bench", "scenes", "mitsuba")
DOC = os.path.join(ROOT, "docs", "ACCURACY.md")
IMAGE_DIR = os.path.join(ROOT, "docs", "accuracy", "mitsuba")
BEGIN = "<!-- mitsuba:begin -->"
END = "<!-- mitsuba:end -->"
MAX_BOUNCES = 16
BIAS_SIGMAS = 2.0
ERROR_IMAGE_SPAN = 0.25

# Our metal words and Mitsuba's names for them (src/scene/Metals.cpp).
METALS = {"gold": "Au", "silver": "Ag", "copper": "Cu", "aluminium": "Al", "chromium": "Cr",
          "tungsten": "W", "nickel": "Ni_palik"}

FLOOR = {"shape": ("plane", 0.0), "material": ("diffuse", (0.45, 0.45, 0.45))}

SCENES = {
    # Three rough metals, sharp to matt, over a grey floor under a dim sky and one sphere light.
    "rough-metals": {
        "camera": {"eye": (0, 1.7, 6.0), "target": (0, 0.75, 0), "up": (0, 1, 0), "fovy": 34},
        "environment": (0.6, 0.6, 0.6),
        "objects": [
            FLOOR,
            {"shape": ("sphere", (-2.05, 0.9, 0), 0.9), "material": ("conductor", 0.05, "gold")},
            {"shape": ("sphere", (0, 0.9, 0), 0.9), "material": ("conductor", 0.3, "copper")},
            {"shape": ("sphere", (2.05, 0.9, 0), 0.9), "material": ("conductor", 1.0, "silver")},
            {"shape": ("sphere", (-3, 6, 5), 1.5), "light": (3, 3, 3)},
        ],
    },
    # Rough glass (index 1.5) before a coloured ball, refracting it, over the floor.
    "rough-glass": {
        "camera": {"eye": (0, 1.4, 5.5), "target": (0, 0.8, 0), "up": (0, 1, 0), "fovy": 34},
        "environment": (0.6, 0.6, 0.6),
        "objects": [
            FLOOR,
            {"shape": ("sphere", (-1.1, 0.9, 0.6), 0.9), "material": ("dielectric", 0.1, 1.5)},
            {"shape": ("sphere", (1.1, 0.9, 0.6), 0.9), "material": ("dielectric", 0.5, 1.5)},
            {"shape": ("sphere", (0, 0.7, -2.2), 0.7), "material": ("diffuse", (0.8, 0.25, 0.1))},
            {"shape": ("sphere", (2, 6, 4), 1.5), "light": (3, 3, 3)},
        ],
    },
    # Depth of field: balls at 3, 5.5 and 9 units, focused on the middle one.
    "thin-lens": {
        "camera": {"eye": (0, 1.0, 6.0), "target": (0, 0.6, 0), "up": (0, 1, 0), "fovy": 30,
                   "lens": (0.25, 5.5)},
        "environment": (0.6, 0.6, 0.6),
        "objects": [
            FLOOR,
            {"shape": ("sphere", (-1.0, 0.5, 3.0), 0.5), "material": ("diffuse", (0.8, 0.2, 0.1))},
            {"shape": ("sphere", (0.3, 0.6, 0.5), 0.6), "material": ("diffuse", (0.2, 0.7, 0.2))},
            {"shape": ("sphere", (1.6, 0.8, -3.0), 0.8), "material": ("conductor", 0.2, "gold")},
            {"shape": ("sphere", (-2, 6, 5), 1.5), "light": (3, 3, 3)},
        ],
    },
}


def fmt_vec(values):
    return " ".join("%g" % v for v in values)


# --- our scene file ------------------------------------------------------------------------

def our_scene_text(name, description):
    """The scene as our format writes it (docs/SCENE_FORMAT.md)."""
    camera = description["camera"]
    lines = ["# Made by tools/mitsuba_references.py from its description of '%s';" % name,
             "# Mitsuba 3 renders the same scene (docs/ACCURACY.md).",
             "environment " + fmt_vec(description["environment"]),
             fmt_vec(camera["eye"]), fmt_vec(camera["target"]), fmt_vec(camera["up"]),
             "%g" % camera["fovy"] + (" lens %g %g" % camera["lens"] if "lens" in camera else ""),
             "0"]
    pigments, finishes, objects = [], [], []
    for item in description["objects"]:
        if "light" in item:
            pigments.append("solid 0 0 0")
            finishes.append(fmt_vec(item["light"]) + "  0 0 0 1")
        else:
            kind = item["material"][0]
            if kind == "diffuse":
                pigments.append("solid " + fmt_vec(item["material"][1]))
                finishes.append("0 0 0  0 0 0 1")
            elif kind == "conductor":
                pigments.append("solid 1 1 1")
                finishes.append("rough_conductor %g %s" % item["material"][1:])
            else:
                pigments.append("solid 1 1 1")
                finishes.append("rough_dielectric %g %g" % item["material"][1:])
        index = len(pigments) - 1
        shape = item["shape"]
        if shape[0] == "plane":
            objects.append("%d %d polyhedron 1  0 1 0 %g" % (index, index, -shape[1]))
        else:
            objects.append("%d %d sphere %s %g" % (index, index, fmt_vec(shape[1]), shape[2]))
    lines += [str(len(pigments))] + pigments + [str(len(finishes))] + finishes
    lines += [str(len(objects))] + objects
    return "\n".join(lines) + "\n"


# --- Mitsuba's scene -----------------------------------------------------------------------

def mitsuba_scene(description, width, height):
    import mitsuba as mi

    T = mi.ScalarTransform4f
    camera = description["camera"]
    to_world = T().look_at(origin=list(camera["eye"]), target=list(camera["target"]),
                           up=list(camera["up"]))
    film = {"type": "hdrfilm", "width": width, "height": height, "rfilter": {"type": "box"},
            "pixel_format": "rgb"}
    sensor = {"type": "perspective", "fov": camera["fovy"], "fov_axis": "y",
              "to_world": to_world, "film": film}
    if "lens" in camera:
        sensor.update({"type": "thinlens", "aperture_radius": camera["lens"][0],
                       "focus_distance": camera["lens"][1]})
    scene = {"type": "scene", "sensor": sensor,
             "integrator": {"type": "path", "max_depth": MAX_BOUNCES + 1},
             "environment": {"type": "constant",
                             "radiance": {"type": "rgb", "value": list(description["environment"])}}}
    for i, item in enumerate(description["objects"]):
        shape = item["shape"]
        if shape[0] == "plane":
            # A rectangle (normal +z) turned to face +y, large enough to be the half-space.
            entry = {"type": "rectangle",
                     "to_world": T().translate([0, shape[1], 0]).rotate([1, 0, 0], -90)
                     .scale([1e5, 1e5, 1])}
        else:
            entry = {"type": "sphere", "center": list(shape[1]), "radius": shape[2]}
        if "light" in item:
            entry["emitter"] = {"type": "area",
                                "radiance": {"type": "rgb", "value": list(item["light"])}}
            entry["bsdf"] = {"type": "diffuse", "reflectance": {"type": "rgb", "value": [0, 0, 0]}}
        else:
            kind = item["material"][0]
            if kind == "diffuse":
                entry["bsdf"] = {"type": "diffuse",
                                 "reflectance": {"type": "rgb", "value": list(item["material"][1])}}
            elif kind == "conductor":
                entry["bsdf"] = {"type": "roughconductor", "distribution": "ggx",
                                 "sample_visible": True, "alpha": item["material"][1],
                                 "material": METALS[item["material"][2]]}
            else:
                entry["bsdf"] = {"type": "roughdielectric", "distribution": "ggx",
                                 "sample_visible": True, "alpha": item["material"][1],
                                 "int_ior": item["material"][2], "ext_ior": 1.0}
        scene["object%d" % i] = entry
    return mi.load_dict(scene)


# --- rendering, cached ---------------------------------------------------------------------

def cache_key(*parts):
    return hashlib.sha256("\n".join(str(p) for p in parts).encode()).hexdigest()[:16]


def read_pfm(path):
    with open(path, "rb") as f:
        kind = f.readline().strip()
        width, height = map(int, f.readline().split())
        scale = float(f.readline())
        data = np.frombuffer(f.read(), dtype="<f4" if scale < 0 else ">f4")
    channels = 3 if kind == b"PF" else 1
    return data.reshape(height, width, channels)[::-1].astype(np.float64)


def shader_digest():
    """What our renders depend on besides the scene: the program's shader modules."""
    digest = hashlib.sha256()
    modules = os.path.join(ROOT, "shaders", "modules")
    for name in sorted(os.listdir(modules)):
        with open(os.path.join(modules, name), "rb") as f:
            digest.update(name.encode() + f.read())
    return digest.hexdigest()


# Our settings for the comparison: Mitsuba's model (no compensation, exact Fresnel), with its
# separable masking-shadowing or with our default height-correlated one.
VARIANTS = {
    "separable": ["--no-energy-compensation", "--fresnel", "exact", "--masking", "separable"],
    "height-correlated": ["--no-energy-compensation", "--fresnel", "exact"],
}


def render_ours(raytracer, scene_path, text, width, height, spp, seed, cache, flags):
    path = os.path.join(cache, "ours-%s.pfm" % cache_key(text, width, height, spp, seed,
                                                         os.path.getmtime(raytracer),
                                                         shader_digest(), flags))
    if not os.path.exists(path):
        subprocess.run([raytracer, scene_path, str(width), str(height), "--spp", str(spp),
                        "--seed", str(seed), "--max-bounces", str(MAX_BOUNCES)] + flags +
                       ["--headless", "--quiet", "--output", path], check=True,
                       stdout=subprocess.DEVNULL, env=dict(os.environ, DISPLAY=""))
    return read_pfm(path)


def render_mitsuba(name, description, width, height, spp, seed, cache):
    path = os.path.join(cache, "mitsuba-%s.npy" % cache_key(repr(description), width, height,
                                                            spp, seed))
    if not os.path.exists(path):
        import mitsuba as mi

        mi.set_variant("scalar_rgb")
        scene = mitsuba_scene(description, width, height)
        image = np.array(mi.render(scene, spp=spp, seed=seed), dtype=np.float64)
        np.save(path, image)
    return np.load(path)


# --- measures ------------------------------------------------------------------------------

def luminance(rgb):
    return rgb @ np.array([0.2126, 0.7152, 0.0722])


def compare(ours, theirs):
    """Relative RMSEs (over the references' mean) of two renders of ours against two of
    Mitsuba's, each pair of independent seeds."""
    a, b = ours
    ra, rb = theirs
    scale = 0.5 * (ra.mean() + rb.mean())
    noise_ours = math.sqrt(np.mean((a - b) ** 2) / 2) / scale
    noise_theirs = math.sqrt(np.mean((ra - rb) ** 2) / 2) / scale
    product = ((a - ra) * (b - rb)).ravel()
    bias2 = product.mean() / scale ** 2
    bias_stderr = product.std() / math.sqrt(product.size) / scale ** 2
    error = math.sqrt(np.mean((a - 0.5 * (ra + rb)) ** 2)) / scale
    explained = error ** 2 / (noise_ours ** 2 + noise_theirs ** 2 / 2)
    # The share of the squared error of the mean of both seeds in its worst 1 % of pixels,
    # beside the same share for the noise alone (the seeds' difference).
    per_pixel = np.sum((0.5 * (a + b) - 0.5 * (ra + rb)) ** 2, axis=-1).ravel()
    noise_pixel = np.sum((0.5 * (a - b)) ** 2 + (0.5 * (ra - rb)) ** 2, axis=-1).ravel()

    def worst(values):
        ordered = np.sort(values)[::-1]
        return ordered[: max(1, len(ordered) // 100)].sum() / max(ordered.sum(), 1e-30)

    brightness = (a.sum() + b.sum()) / (ra.sum() + rb.sum()) - 1.0
    return {"noise_ours": noise_ours, "noise_theirs": noise_theirs, "bias2": bias2,
            "bias_stderr": bias_stderr, "error": error, "explained": explained,
            "worst_error": worst(per_pixel), "worst_noise": worst(noise_pixel),
            "brightness": brightness}


def bias_text(result):
    if result["bias2"] < BIAS_SIGMAS * result["bias_stderr"]:
        bound = math.sqrt(max(result["bias2"], 0) + BIAS_SIGMAS * result["bias_stderr"])
        return "< %.3g (within noise)" % bound
    return "%.3g" % math.sqrt(result["bias2"])


def write_images(name, ours, theirs, path):
    """ours | Mitsuba | signed luminance error (red: ours brighter), side by side."""
    import mitsuba as mi

    mine = 0.5 * (ours[0] + ours[1])
    reference = 0.5 * (theirs[0] + theirs[1])

    def display(rgb):
        # The project's display tone map is for whole scenes; this one only needs to show
        # both pictures alike: x / (1 + x), then gamma 2.2.
        return np.clip(rgb / (1.0 + rgb), 0, 1) ** (1 / 2.2)

    signed = (luminance(mine) - luminance(reference)) / max(luminance(reference).mean(), 1e-12)
    t = np.clip(signed / ERROR_IMAGE_SPAN, -1, 1)[..., None]
    error = np.where(t > 0, (1 - t) * 1.0 + t * np.array([1.0, 0.1, 0.1]),
                     (1 + t) * 1.0 - t * np.array([0.1, 0.2, 1.0]))
    gap = np.ones((mine.shape[0], 4, 3))
    strip = np.concatenate([display(mine), gap, display(reference), gap, error], axis=1)
    bitmap = mi.Bitmap((strip * 255 + 0.5).astype(np.uint8), pixel_format=mi.Bitmap.PixelFormat.RGB)
    bitmap.write(path)


def section(results, arguments, version):
    lines = [BEGIN, "", "## Against an independent renderer: Mitsuba 3", "",
             "The rough conductor, the rough dielectric and the thin lens against Mitsuba %s "
             "(`scalar_rgb`: `roughconductor` and `roughdielectric` with GGX and visible-normal "
             "sampling, `thinlens`), on three scenes of spheres and a floor that both "
             "renderers have exactly, described once in `tools/mitsuba_references.py` and "
             "written as our scenes [`bench/scenes/mitsuba/`](../bench/scenes/mitsuba/). "
             "**Mitsuba's GGX has no energy compensation: ours renders with "
             "`--no-energy-compensation`** (and `--fresnel exact`, Mitsuba's Fresnel), so "
             "this compares the single-scattering models; the compensation is held to the "
             "furnace instead (above). Mitsuba's masking-shadowing is Smith's separable "
             "G1(wo) G1(wi), ours by default the height-correlated form (Heitz 2014, which "
             "the issue asks for): each rough scene is compared with ours under "
             "`--masking separable`, the same model, and under our default, to show what "
             "the masking changes (brighter rough surfaces at grazing angles, the rims). "
             "Each renderer renders each scene with two independent "
             "seeds, ours at %d spp, Mitsuba at %d, %dx%d; the columns are those of the "
             "exact-reference section above, relative RMSE over Mitsuba's mean: **bias** of "
             "our expectation against Mitsuba's (the mean product of the two seeds' "
             "differences), **noise** of one render of each, **error** of one of ours "
             "against the mean of Mitsuba's two and how much of it the two noises explain "
             "(1: all), the share of the squared error in the worst 1 %% of pixels beside the "
             "same share for noise alone, and the brightness of the whole image against "
             "Mitsuba's." % (version, arguments.spp, arguments.reference_spp,
                             arguments.size[0], arguments.size[1]), "",
             "| scene | bias | noise, ours | noise, Mitsuba | error | explained | worst 1 %: "
             "error | worst 1 %: noise | brightness |",
             "|---|---|---|---|---|---|---|---|---|"]
    for (name, variant), result in results.items():
        label = "%s, %s masking" % (name, variant) if name != "thin-lens" else name
        lines.append("| %s | %s | %.3g | %.3g | %.3g | %.3g | %.0f %% | %.0f %% | %+.2f %% |" % (
            label, bias_text(result), result["noise_ours"], result["noise_theirs"],
            result["error"], result["explained"], 100 * result["worst_error"],
            100 * result["worst_noise"], 100 * result["brightness"]))
    lines += ["", "Each scene and masking: ours (mean of both seeds) | Mitsuba (mean of both "
              "seeds) | the signed luminance error over the image's mean, red where ours is "
              "brighter, blue darker, saturated at +-%g." % ERROR_IMAGE_SPAN, ""]
    for name, variant in results:
        lines.append("![%s, %s](accuracy/mitsuba/%s-%s.png)" % (name, variant, name, variant))
    lines += ["", "Reproduce: `python3 -m venv /work/venvs/mitsuba && "
              "/work/venvs/mitsuba/bin/pip install mitsuba numpy`, then "
              "`/work/venvs/mitsuba/bin/python tools/mitsuba_references.py --raytracer "
              "build/raytracer --size %d %d --spp %d --reference-spp %d`." % (
                  arguments.size[0], arguments.size[1], arguments.spp, arguments.reference_spp),
              "", END]
    return "\n".join(lines)


def replace_section(text):
    with open(DOC) as f:
        doc = f.read()
    if BEGIN in doc and END in doc:
        doc = doc[:doc.index(BEGIN)] + text + doc[doc.index(END) + len(END):]
    else:
        doc = doc.rstrip("\n") + "\n\n" + text + "\n"
    with open(DOC, "w") as f:
        f.write(doc)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--raytracer", default=os.path.join(ROOT, "build", "raytracer"))
    parser.add_argument("--size", type=int, nargs=2, default=[160, 120])
    parser.add_argument("--spp", type=int, default=1024)
    parser.add_argument("--reference-spp", type=int, default=4096)
    parser.add_argument("--cache", default="/tmp/mitsuba-references")
    parser.add_argument("--scenes", default=",".join(SCENES))
    parser.add_argument("--metals", action="store_true",
                        help="print the RGB eta and k Mitsuba uses for our metals, and exit")
    arguments = parser.parse_args()

    if arguments.metals:
        import mitsuba as mi

        mi.set_variant("scalar_rgb")
        for word, symbol in METALS.items():
            parameters = mi.traverse(mi.load_dict({"type": "roughconductor", "material": symbol}))
            print("%-10s eta %s  k %s" % (word, fmt_vec(parameters["eta.value"]),
                                          fmt_vec(parameters["k.value"])))
        return 0

    import mitsuba as mi

    os.makedirs(arguments.cache, exist_ok=True)
    os.makedirs(SCENE_DIR, exist_ok=True)
    os.makedirs(IMAGE_DIR, exist_ok=True)
    width, height = arguments.size
    results = {}
    for name in arguments.scenes.split(","):
        description = SCENES[name]
        text = our_scene_text(name, description)
        scene_path = os.path.join(SCENE_DIR, name + ".in")
        with open(scene_path, "w") as f:
            f.write(text)
        theirs = [render_mitsuba(name, description, width, height, arguments.reference_spp,
                                 seed, arguments.cache) for seed in (11, 12)]
        # The thin-lens scene's one rough ball is no test of the masking: one variant.
        variants = ["separable"] if name == "thin-lens" else list(VARIANTS)
        for variant in variants:
            ours = [render_ours(arguments.raytracer, scene_path, text, width, height,
                                arguments.spp, seed, arguments.cache, VARIANTS[variant])
                    for seed in (1, 2)]
            result = compare(ours, theirs)
            results[(name, variant)] = result
            write_images(name, ours, theirs,
                         os.path.join(IMAGE_DIR, "%s-%s.png" % (name, variant)))
            print(name, variant, {k: round(float(v), 5) for k, v in result.items()}, flush=True)
    replace_section(section(results, arguments, mi.__version__))
    return 0


if __name__ == "__main__":
    sys.exit(main())
