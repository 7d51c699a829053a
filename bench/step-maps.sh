#!/usr/bin/env bash
# Where a scene's march steps are, pixel by pixel: bench_throughput's counting shader
# (shaders/modules/work_counters.glsl) writes each pixel's camera, bounce and shadow steps per
# path, and bench/step_maps.py draws the three maps side by side. Without arguments it maps
# the original's scene 5 (the peer's own scene file).
#
#   bench/step-maps.sh [SCENE...]     (default: scene5 of the original; 200x150, 16 paths)
#
# Writes docs/performance/SCENE-steps.png and prints each map's mean and percentiles.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
peer="${PEER:-$root/../shared/peers/frag-pathtracer}"
"$root/tools/install-dependencies.sh" python3-matplotlib >/dev/null
"$root/tools/build.sh" >/dev/null
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
[ $# -gt 0 ] || set -- "$peer/source/scenes/scene5.in"
mkdir -p "$root/docs/performance"
for scene in "$@"; do
  scene="$(readlink -f "$scene")"
  name="$(basename "$scene" .in)"
  (cd "$(dirname "$scene")" && "$root/build/bench/bench_throughput" --size 200 150 --seconds 0.2 \
    --profile-spp 16 --dump "$work/steps" "$(basename "$scene")" >/dev/null)
  # -s: Debian's numpy, the one its matplotlib was built for, not a pip-installed one in ~/.local
  /usr/bin/python3 -s "$root/bench/step_maps.py" "$work/steps-$name-steps-per-path.pfm" \
    "$root/docs/performance/$name-steps.png" "$name"
done
