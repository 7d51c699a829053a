"""Renders shadow-edge.in and room-corners.in (beside this file) with Mitsuba 3, an
independent renderer, for the comparison in docs/ACCURACY.md (issue 36: the one-pixel arc
at a small sphere's shadow edge and the lines along a room's corners). The two scenes are
written out here by hand in Mitsuba's terms: the same camera (vertical field of view), point
light (radiant intensity), Lambertian albedos and geometry (the floor and the room's walls
as rectangles), paths of up to 64 scattering events, and the pixel filter named on the
command line: `box`, the uniform jitter over the pixel that this renderer uses, or
`gaussian`, Mitsuba's default, which blurs every edge by about a pixel.

    python -m venv /work/venvs/mitsuba && /work/venvs/mitsuba/bin/pip install mitsuba
    /work/venvs/mitsuba/bin/python bench/independent/mitsuba_reference.py shadow box 4096 out.npy

writes the linear RGB image (rows top first) as a NumPy array; compare it with
`raytracer bench/independent/shadow-edge.in 160 120 --spp 2048 --max-bounces 64`.
"""
import sys, numpy as np, mitsuba as mi
mi.set_variant('scalar_rgb')
from mitsuba import ScalarTransform4f as T
which, filt, spp, out = sys.argv[1], sys.argv[2], int(sys.argv[3]), sys.argv[4]  # shadow|room, box|gaussian
def diffuse(c): return {'type': 'twosided', 'bsdf': {'type': 'diffuse', 'reflectance': {'type': 'rgb', 'value': c}}}
def rect(to_world, c): return {'type': 'rectangle', 'to_world': to_world, 'bsdf': diffuse(c)}
def sensor(eye, target, fov):
    return {'type': 'perspective', 'fov': fov, 'fov_axis': 'y',
            'to_world': T().look_at(origin=eye, target=target, up=[0, 1, 0]),
            'film': {'type': 'hdrfilm', 'width': 160, 'height': 120, 'pixel_format': 'rgb',
                     'rfilter': {'type': filt}},
            'sampler': {'type': 'independent', 'sample_count': spp}}
scene = {'type': 'scene', 'integrator': {'type': 'path', 'max_depth': 65, 'rr_depth': 5}}
if which == 'shadow':
    scene['sensor'] = sensor([0, 1.2, 3.5], [0, 0.3, 0], 40)
    # floor y = 0: a rectangle in xz, normal +y, 200 wide
    scene['floor'] = rect(T().rotate([1, 0, 0], -90).scale([100, 100, 1]), [0.8, 0.8, 0.8])
    scene['ball'] = {'type': 'sphere', 'center': [0, 0.25, 0], 'radius': 0.25, 'bsdf': diffuse([0.8, 0.3, 0.2])}
    scene['light'] = {'type': 'point', 'position': [1.5, 3, 1], 'intensity': {'type': 'rgb', 'value': [20, 20, 20]}}
else:
    scene['sensor'] = sensor([0, 0, 3.2], [0, -0.3, 0], 55)
    w, c = [0.75, 0.75, 0.75], None
    # the box x in [-1.5,1.5], y in [-1.5,1.5], z in [-1.5,3.5]: centre z 1, half 2.5
    scene['floor'] = rect(T().translate([0, -1.5, 1]).rotate([1, 0, 0], -90).scale([1.5, 2.5, 1]), w)
    scene['ceiling'] = rect(T().translate([0, 1.5, 1]).rotate([1, 0, 0], 90).scale([1.5, 2.5, 1]), w)
    scene['back'] = rect(T().translate([0, 0, -1.5]).scale([1.5, 1.5, 1]), w)
    scene['front'] = rect(T().translate([0, 0, 3.5]).rotate([0, 1, 0], 180).scale([1.5, 1.5, 1]), w)
    scene['left'] = rect(T().translate([-1.5, 0, 1]).rotate([0, 1, 0], 90).scale([2.5, 1.5, 1]), [0.75, 0.12, 0.1])
    scene['right'] = rect(T().translate([1.5, 0, 1]).rotate([0, 1, 0], -90).scale([2.5, 1.5, 1]), [0.12, 0.6, 0.15])
    scene['light'] = {'type': 'point', 'position': [0.4, 1.2, 1.0], 'intensity': {'type': 'rgb', 'value': [10, 10, 10]}}
img = mi.render(mi.load_dict(scene), seed=int(sys.argv[5]) if len(sys.argv) > 5 else 0)
np.save(out, np.array(img)[..., :3])
