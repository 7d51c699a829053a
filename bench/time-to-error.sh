#!/usr/bin/env bash
# Time to a given error, ours against the original program, side by side on this machine:
# for the original's scenes that the exact-intersection reference can render (scene1,
# scene2, scene7, and since 2026-12-03 scene3, whose torus is met as a quartic, and scene5,
# whose csg declares its intersection: for those two shapes the reference and our default
# share the intersection code, which tests/render/ExactShapesTest.cpp judges instead), both
# programs render 16, 64, 256 and 1024 spp at 160x120, alternating,
# and each image's relative RMSE against the exact reference (this program with
# --exact-geometry, seeds 11 and 12, 1024 spp each) is set against its render time. Speed
# bought with bias shows here as an error that stops falling.
#
#   bench/time-to-error.sh [RAYTRACER=build/raytracer]
#
# SCENES names the scenes (default: scene1 scene2 scene3 scene5 scene7).
# Prints the machine and a Markdown table per scene, then the time each program needs to
# reach 5 %, 2 % and 1 % (interpolated on its measured curve; "never" past its last point).
# PEER names the peer's folder (default ../shared/peers/frag-pathtracer).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
raytracer="$(readlink -f "${1:-$root/build/raytracer}")"
peer="${PEER:-$root/../shared/peers/frag-pathtracer}"
# The renders stay in TIME_TO_ERROR_DIR (default build-accuracy/time-to-error, which git
# ignores), so that bench/time_to_error.py can be run on them again.
work="${TIME_TO_ERROR_DIR:-$root/build-accuracy/time-to-error}"
rm -rf "$work"
mkdir -p "$work"
cp "$peer"/source/scenes/* "$work/"
results="$work/results.csv"
echo "scene,program,spp,seconds,image" >"$results"
for scene in ${SCENES:-scene1 scene2 scene3 scene5 scene7}; do
  for seed in 11 12; do
    (cd "$work" && "$raytracer" "$scene.in" 160 120 --spp 1024 --seed "$seed" --exact-geometry \
      --headless --quiet --output "$work/$scene-exact-$seed.pfm" >/dev/null)
  done
  for spp in 16 64 256 1024; do
    line="$("$peer/measure.sh" "$scene" 160 120 "$spp" "$work/original")"
    echo "$scene,original,$spp,$(echo "$line" | awk '{print $5}'),$work/original/${scene}_160x120_$spp.pfm" >>"$results"
    summary="$(cd "$work" && "$raytracer" "$scene.in" 160 120 --spp "$spp" --headless \
      --output "$work/$scene-ours-$spp.pfm" 2>&1)"
    seconds="$(echo "$summary" | sed -n 's/.* spp in \([0-9.]*\) s.*/\1/p')"
    echo "$scene,ours,$spp,$seconds,$work/$scene-ours-$spp.pfm" >>"$results"
  done
done
echo "machine: $(lscpu | sed -n 's/^Model name: *//p' | head -1), $(nproc) cores; date: $(date -u '+%F %H:%M UTC')"
echo "ours: commit $(git -C "$root" rev-parse --short HEAD 2>/dev/null || echo unknown)"
echo
/usr/bin/python3 "$root/bench/time_to_error.py" "$results" "$work"
