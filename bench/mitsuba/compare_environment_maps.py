#!/usr/bin/env python3
"""Environment-map lighting against an independent renderer, Mitsuba 3, pixel by pixel.

    /work/venvs/mitsuba/bin/python bench/mitsuba/compare_environment_maps.py \\
        --raytracer build/raytracer [--size 96 72] [--spp 1024] [--chunks 8] [--out DIR]

Needs Mitsuba 3 in the Python that runs it (`python3 -m venv /work/venvs/mitsuba;
/work/venvs/mitsuba/bin/pip install mitsuba`; the scalar_rgb variant is used) and
OpenImageIO's `oiiotool` on the PATH. Mitsuba is not part of the project: only this script is.

Each scene is described once here and written both ways: as a scene file for our renderer and
as a Mitsuba scene dictionary (spheres, a cube and a ground plane, Lambertian, mirror and glass
surfaces, under an environment map). Both render `--spp` samples per pixel in `--chunks` runs
of their own seeds; from the chunks each pixel's mean and its standard error follow, for both
renderers alike. Per pixel and channel, z = (ours - Mitsuba) / sqrt(se_ours^2 + se_mitsuba^2):
without bias z is noise alone (each standard error estimated from 8 chunks, so z spreads
somewhat wider than a normal variable: mean z^2 about 1.2 to 1.5, |z| > 4 in about 0.5 % of
pixels); a bias shows as a mean z^2 well above that, concentrated where the bias is. Pixels
that see the map directly have almost no noise and are judged by their relative difference. Prints a Markdown table
(docs/ACCURACY.md, "Environment maps") and writes, per scene, both images and a map of z
(red: ours brighter, blue: darker, full at |z| = 5) into --out, to look at, with the
means and standard errors as NumPy arrays (.npz).

Conventions, so that both renderers see the same light:
- Orientation. Mitsuba's envmap puts the map's left edge (u = 0) at -z, ours its middle
  (docs/SCENE_FORMAT.md); otherwise the same (top row +y, u growing towards +x). So Mitsuba's
  map is turned a further 180 degrees about +y.
- Filtering. Both interpolate bilinearly, with texel centres at (i + 1/2) / W across; but down
  the map Mitsuba puts its rows' values at v = j / (H - 1), from pole to pole, and ours at
  (j + 1/2) / H. Mitsuba is given a map of 2H + 1 rows: ours at its odd rows, the midpoints of
  ours between them, our top and bottom rows at the poles. Its linear interpolation down
  that map is then exactly ours.
- Units: both take the map's values as radiance, times the intensity (Mitsuba's `scale`).
- Light transport: our paths scatter at most 16 times, so Mitsuba's max_depth is 17;
  Russian roulette is unbiased in both. Our glass uses the exact Fresnel equations
  (`--fresnel exact`), as Mitsuba's dielectric does. Pixels are box-filtered in both.
- The ground: our plane is infinite, Mitsuba's a square 2 x 10^4 wide (larger, its shadow
  rays lose precision: at 2 x 10^6 the shadows' edges moved). From the camera its far edge lies
  0.01 degrees under the horizon, and between the two Mitsuba sees the map: a strip of 1.6 %
  of the pixel row that holds the horizon, which makes that row differ by 1 to 5 %. That row is
  left out of the statistics (and its difference printed apart).
"""
import argparse
import os
import subprocess
import sys
import tempfile

import numpy as np

import mitsuba as mi

mi.set_variant("scalar_rgb")

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
BLENDER_WORLDS = "/usr/share/blender/datafiles/studiolights/world"

# --- the scenes, described once --------------------------------------------------------

GROUND = ("plane", (0.5, 0.5, 0.5), "diffuse")
GROUND_HALF_WIDTH = 1e4  # Mitsuba's ground square's (ours is infinite)


def sphere(center, radius, colour, finish):
    return ("sphere", colour, finish, center, radius)


def cube(center, half, colour, finish):
    return ("cube", colour, finish, center, half)


SCENES = [
    {
        "name": "sky-sun-diffuse",
        "what": "the project's sky with a sun; Lambertian spheres, a cube and the ground",
        "map": os.path.join(ROOT, "textures", "sky-sun.hdr"),
        "intensity": 0.5,
        "rotate": 0.0,
        "camera": ((0, 1.6, 6.5), (0, 0.7, 0), 40),
        "objects": [GROUND,
                    sphere((-1.3, 1.0, 0.0), 1.0, (0.75, 0.3, 0.2), "diffuse"),
                    sphere((1.2, 0.8, -0.6), 0.8, (0.3, 0.5, 0.75), "diffuse"),
                    cube((0.2, 0.35, 1.4), 0.35, (0.8, 0.8, 0.7), "diffuse")],
    },
    {
        "name": "sky-sun-turned-mirror-glass",
        "what": "the same sky turned 60 degrees; a mirror sphere and a glass sphere (index 1.5)",
        "map": os.path.join(ROOT, "textures", "sky-sun.hdr"),
        "intensity": 0.5,
        "rotate": 60.0,
        "camera": ((0, 1.6, 6.5), (0, 0.7, 0), 40),
        "objects": [GROUND,
                    sphere((-1.3, 1.0, 0.0), 1.0, (1, 1, 1), "mirror"),
                    sphere((1.2, 0.8, 0.2), 0.8, (1, 1, 1), "glass")],
    },
    {
        "name": "courtyard-diffuse-mirror",
        "what": "Blender's courtyard map (a real place, 1024 x 512), turned -30 degrees; a "
                "Lambertian and a mirror sphere",
        "map": os.path.join(BLENDER_WORLDS, "courtyard.exr"),
        "intensity": 1.0,
        "rotate": -30.0,
        "camera": ((0, 1.6, 6.5), (0, 0.7, 0), 40),
        "objects": [GROUND,
                    sphere((-1.3, 1.0, 0.0), 1.0, (0.8, 0.8, 0.8), "diffuse"),
                    sphere((1.2, 0.8, -0.6), 0.8, (1, 1, 1), "mirror")],
    },
]

FINISHES = {"diffuse": "0 0 0  0 0 0 1", "mirror": "0 0 0  0 1 0 1", "glass": "0 0 0  0 0 1 1.5"}


def our_scene_text(scene):
    eye, target, fov = scene["camera"]
    lines = ["environment map %s intensity %g rotate %g" % (scene["map"], scene["intensity"],
                                                              scene["rotate"]),
             "%g %g %g" % eye, "%g %g %g" % target, "0 1 0", "%g" % fov, "0"]
    objects = scene["objects"]
    lines.append(str(len(objects)))
    lines += ["solid %g %g %g" % o[1] for o in objects]
    lines.append(str(len(objects)))
    lines += [FINISHES[o[2]] for o in objects]
    lines.append(str(len(objects)))
    for i, o in enumerate(objects):
        if o[0] == "plane":
            lines.append("%d %d polyhedron 1  0 1 0 0" % (i, i))
        elif o[0] == "sphere":
            lines.append("%d %d sphere %g %g %g %g" % ((i, i) + tuple(o[3]) + (o[4],)))
        else:
            lines.append("%d %d box %g %g %g %g %g %g" % ((i, i) + tuple(o[3]) + (o[4],) * 3))
    return "\n".join(lines) + "\n"


def mitsuba_bsdf(colour, finish):
    if finish == "diffuse":
        return {"type": "diffuse", "reflectance": {"type": "rgb", "value": list(colour)}}
    if finish == "mirror":
        return {"type": "conductor", "material": "none"}  # reflects all, at every angle
    return {"type": "dielectric", "int_ior": 1.5, "ext_ior": 1.0}


def mitsuba_map(path, folder):
    """Our map, resampled so that Mitsuba's interpolation is ours (see the module's text)."""
    converted = os.path.join(folder, "ours.exr")
    subprocess.run(["oiiotool", path, "--ch", "R,G,B", "-d", "float", "-o", converted],
                   check=True)
    ours = np.array(mi.Bitmap(converted), dtype=np.float64)[:, :, :3]
    ours = np.maximum(ours, 0.0)  # as ours reads it (render/EnvironmentMap.h)
    height = ours.shape[0]
    rows = [ours[0]]
    for j in range(height):
        rows.append(ours[j])
        rows.append(0.5 * (ours[j] + ours[j + 1]) if j + 1 < height else ours[j])
    resampled = os.path.join(folder, "for-mitsuba.exr")
    mi.Bitmap(np.ascontiguousarray(np.array(rows, dtype=np.float32))).write(resampled)
    return resampled


def mitsuba_scene(scene, width, height, spp, seed, map_file):
    eye, target, fov = scene["camera"]
    T = mi.ScalarTransform4f
    d = {
        "type": "scene",
        "integrator": {"type": "path", "max_depth": 17},
        "sensor": {
            "type": "perspective", "fov": fov, "fov_axis": "y",
            "to_world": T().look_at(origin=list(eye), target=list(target), up=[0, 1, 0]),
            "film": {"type": "hdrfilm", "width": width, "height": height,
                     "rfilter": {"type": "box"}, "pixel_format": "rgb"},
            "sampler": {"type": "independent", "sample_count": spp, "seed": seed},
        },
        "environment": {"type": "envmap", "filename": map_file, "scale": scene["intensity"],
                        "to_world": T().rotate(axis=[0, 1, 0], angle=scene["rotate"] + 180.0)},
    }
    for i, o in enumerate(scene["objects"]):
        bsdf = mitsuba_bsdf(o[1], o[2])
        if o[0] == "plane":
            shape = {"type": "rectangle",
                     "to_world": T().rotate(axis=[1, 0, 0], angle=-90).scale(GROUND_HALF_WIDTH)}
        elif o[0] == "sphere":
            shape = {"type": "sphere", "center": list(o[3]), "radius": o[4]}
        else:
            shape = {"type": "cube", "to_world": T().translate(list(o[3])).scale(o[4])}
        shape["bsdf"] = bsdf
        d["object%d" % i] = shape
    return d


def read_pfm(path):
    with open(path, "rb") as f:
        kind = f.readline().strip()
        width, height = map(int, f.readline().split())
        scale = float(f.readline())
        data = np.fromfile(f, dtype="<f4" if scale < 0 else ">f4")
    channels = 3 if kind == b"PF" else 1
    return data.reshape(height, width, channels)[::-1].astype(np.float64)  # bottom row first


def render_ours(raytracer, scene_file, width, height, spp, seed, folder):
    out = os.path.join(folder, "ours-%d.pfm" % seed)
    subprocess.run([raytracer, scene_file, str(width), str(height), "--spp", str(spp),
                    "--seed", str(seed), "--fresnel", "exact", "--headless", "--quiet",
                    "--output", out], check=True, stdout=subprocess.DEVNULL,
                   env={**os.environ, "DISPLAY": ""})
    return read_pfm(out)


def horizon_rows(scene, width, height):
    """The pixel rows whose directions reach below the horizon no further than Mitsuba's
    ground square does: there ours sees ground and Mitsuba the map beyond the square's edge.
    The camera has no roll (up is +y), so the horizon is a row of the picture."""
    eye, target, fov = scene["camera"]
    eye = np.array(eye, dtype=float)
    forward = np.array(target, dtype=float) - eye
    forward /= np.linalg.norm(forward)
    right = np.cross(forward, [0.0, 1.0, 0.0])
    right /= np.linalg.norm(right)
    up = np.cross(right, forward)
    tan_half = np.tan(np.radians(fov) / 2.0)
    band = (-eye[1] / GROUND_HALF_WIDTH, 0.0)  # slopes (rise over run) of the strip

    def slope(picture_y):
        v = (2.0 * (height - picture_y) - height) / height * tan_half
        d = v * up + forward
        return d[1] / np.hypot(d[0], d[2])

    rows = []
    for y in range(height):
        low, high = slope(y + 1), slope(y)
        if low <= band[1] and high >= band[0]:
            rows.append(y)
    return rows


def mean_and_error(chunks):
    stack = np.array(chunks)
    n = stack.shape[0]
    return stack.mean(axis=0), stack.std(axis=0, ddof=1) / np.sqrt(n)


def write_png(path, rgb):
    """Linear radiance as a picture: the display's exposure and gamma, roughly."""
    folder = os.path.dirname(path)
    exr = os.path.join(folder, "tmp.exr")
    mi.Bitmap(np.ascontiguousarray(rgb.astype(np.float32))).write(exr)
    subprocess.run(["oiiotool", exr, "--tocolorspace", "sRGB", "-o", path], check=True)
    os.remove(exr)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--raytracer", default=os.path.join(ROOT, "build", "raytracer"))
    parser.add_argument("--size", nargs=2, type=int, default=[96, 72])
    parser.add_argument("--spp", type=int, default=1024)
    parser.add_argument("--chunks", type=int, default=8)
    parser.add_argument("--out", default=os.path.join(ROOT, "build", "mitsuba-comparison"))
    parser.add_argument("scenes", nargs="*", help="names of the scenes to run (default: all)")
    args = parser.parse_args()
    width, height = args.size
    per_chunk = args.spp // args.chunks
    os.makedirs(args.out, exist_ok=True)
    print("| scene | rel. difference of the means (± 1 s.e.) | rel RMSE ours vs Mitsuba | "
          "noise alone predicts | surfaces: mean z² | surfaces: \\|z\\| > 4 | surfaces: worst "
          "1 % of pixels' share of z² | background: largest rel. difference | horizon row: "
          "rel. difference |")
    print("|---|---|---|---|---|---|---|---|---|")
    for scene in SCENES:
        if args.scenes and scene["name"] not in args.scenes:
            continue
        if not os.path.exists(scene["map"]):
            print("| %s | (skipped: %s is not installed) | | | | | |" % (scene["name"],
                                                                      scene["map"]))
            continue
        with tempfile.TemporaryDirectory() as folder:
            scene_file = os.path.join(folder, scene["name"] + ".in")
            with open(scene_file, "w") as f:
                f.write(our_scene_text(scene))
            map_file = mitsuba_map(scene["map"], folder)
            ours = [render_ours(args.raytracer, scene_file, width, height, per_chunk, 1 + c,
                                folder) for c in range(args.chunks)]
            theirs = [np.array(mi.render(mi.load_dict(
                mitsuba_scene(scene, width, height, per_chunk, 1000 + c, map_file))),
                dtype=np.float64)[:, :, :3] for c in range(args.chunks)]
        a, sa = mean_and_error(ours)
        b, sb = mean_and_error(theirs)
        sigma = np.sqrt(sa ** 2 + sb ** 2) + 1e-12
        z = (a - b) / sigma
        z2 = z ** 2
        # Pixels whose camera ray escapes at once show the map itself: their only noise is the
        # pixel's jitter over the map, so a difference far below anything visible (the GL's
        # interpolation weights against Mitsuba's, about 1e-4 of the contrast between two
        # texels) is many of their standard errors. They are judged by their relative
        # difference; z is for the pixels whose paths scatter (surfaces).
        background = (sa.mean(axis=2) < 1e-3 * a.mean(axis=2) + 1e-9)
        horizon = np.zeros(background.shape, dtype=bool)
        horizon[horizon_rows(scene, width, height)] = True
        background &= ~horizon
        surfaces = ~background & ~horizon
        horizon_difference = a[horizon].sum() / b[horizon].sum() - 1.0
        per_pixel = z2.mean(axis=2)[surfaces]
        worst = np.sort(per_pixel)[::-1][: max(1, per_pixel.size // 100)].sum() / per_pixel.sum()
        kept = ~horizon
        relative = a[kept].sum() / b[kept].sum() - 1.0
        relative_se = np.sqrt((sa[kept] ** 2).sum() + (sb[kept] ** 2).sum()) / b[kept].sum()
        rmse = np.sqrt(((a - b)[kept] ** 2).mean()) / b[kept].mean()
        predicted = np.sqrt((sigma[kept] ** 2).mean()) / b[kept].mean()
        background_difference = (np.abs(a - b) / (b + 1e-6))[background].max() \
            if background.any() else 0.0
        print("| %s | %+.4f ± %.4f | %.4f | %.4f | %.2f | %.2f %% | %.1f %% | %.2g (%d pixels) "
              "| %+.3f |" % (
                  scene["name"], relative, relative_se, rmse, predicted, z2[surfaces].mean(),
                  100.0 * (np.abs(z[surfaces]) > 4).mean(), 100.0 * worst,
                  background_difference, background.sum(), horizon_difference))
        sys.stdout.flush()
        np.savez_compressed(os.path.join(args.out, scene["name"] + ".npz"), ours=a,
                            ours_error=sa, mitsuba=b, mitsuba_error=sb)
        write_png(os.path.join(args.out, scene["name"] + "-ours.png"), a)
        write_png(os.path.join(args.out, scene["name"] + "-mitsuba.png"), b)
        signed = np.clip(z.mean(axis=2) / 5.0, -1.0, 1.0)
        zmap = np.zeros(a.shape)
        zmap[:, :, 0] = np.maximum(signed, 0.0)
        zmap[:, :, 2] = np.maximum(-signed, 0.0)
        write_png(os.path.join(args.out, scene["name"] + "-z.png"), zmap)
    print("\n(%dx%d, %d spp each in %d chunks of %d; z per pixel and channel)" % (
        width, height, args.spp, args.chunks, per_chunk))


if __name__ == "__main__":
    main()
