#!/usr/bin/env bash
# Do two builds render the same images, bit for bit? Each RAYTRACER renders each scene at one
# size, sample count and seed; the radiance (a PFM file: a header and raw float32 pixels, no
# metadata) is compared byte for byte, and the per-pixel statistics (an OpenEXR file: sample
# counts, discarded samples, variance of the mean) value for value (idiff, every threshold
# 0). For a change that must not change what is rendered (a refactoring): build the commit
# before it in a worktree and name both programs.
#
#   bench/same-images.sh [--size W H] [--spp N] [--seed S] [--option ARG]... OLD NEW [-- SCENE...]
#
# Defaults: 64x48, 8 spp, seed 7, the classic and figure scenes (scenes/scene*.in,
# scenes/fig*.in); --option passes an option to both programs (--option --no-specialize).
# Exits 1 when any scene differs.
set -euo pipefail
here="$(cd "$(dirname "$0")/.." && pwd)"
width=64 height=48 spp=8 seed=7
options=() programs=() scenes=()
while [ $# -gt 0 ]; do
  case "$1" in
    --size) width="$2"; height="$3"; shift 3 ;;
    --spp) spp="$2"; shift 2 ;;
    --seed) seed="$2"; shift 2 ;;
    --option) options+=("$2"); shift 2 ;;
    --) shift; scenes=("$@"); break ;;
    *) programs+=("$(readlink -f "$1")"); shift ;;
  esac
done
[ "${#programs[@]}" -eq 2 ] ||
  { echo "usage: same-images.sh [--size W H] [--spp N] [--seed S] [--option ARG]... OLD NEW [-- SCENE...]" >&2; exit 2; }
[ "${#scenes[@]}" -gt 0 ] || scenes=("$here"/scenes/scene*.in "$here"/scenes/fig*.in)
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
differing=0
for scene in "${scenes[@]}"; do
  name="$(basename "$scene" .in)"
  for i in 0 1; do
    env -u DISPLAY "${programs[$i]}" "$scene" "$width" "$height" --spp "$spp" --seed "$seed" \
      --headless --quiet "${options[@]}" --output "$work/$name.$i.pfm" \
      --stats-output "$work/$name.$i.exr" > /dev/null
  done
  if cmp -s "$work/$name.0.pfm" "$work/$name.1.pfm" &&
     idiff -fail 0 -failpercent 0 -warn 0 "$work/$name.0.exr" "$work/$name.1.exr" > "$work/idiff"; then
    echo "same       $name"
  else
    idiff -fail 0 -failpercent 0 -warn 0 -abs "$work/$name.0.pfm" "$work/$name.1.pfm" > "$work/idiff" || true
    echo "DIFFERENT  $name: radiance $(grep -E 'Mean error|Max error' "$work/idiff" | tr -s ' \n' ' ')"
    differing=1
  fi
done
echo "($width x $height, $spp spp, seed $seed${options[*]:+, ${options[*]}}; OLD ${programs[0]}, NEW ${programs[1]})"
exit "$differing"
