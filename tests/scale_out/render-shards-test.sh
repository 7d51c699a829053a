#!/bin/sh
# ctest RenderShardsScriptRendersInParallelAndMerges: tools/render-shards.sh renders three
# shards of scene 1 with GNU parallel and merges them; the merged file must hold every sample
# in every pixel, of the three seeds, the picture must be written and the shards removed.
# Exit 77 (skipped) where GNU parallel is not installed.
#   render-shards-test.sh RAYTRACER
set -eu
raytracer=$1
root="$(cd "$(dirname "$0")/../.." && pwd)"
if ! parallel --version 2>/dev/null | grep -q "GNU parallel"; then
    echo "GNU parallel is not installed (Debian package parallel): skipped"
    exit 77
fi
folder=$(mktemp -d)
trap 'rm -rf "$folder"' EXIT
cd "$folder"
RAYTRACER=$raytracer "$root/tools/render-shards.sh" "$root/scenes/scene1.in" 32 24 7 3 \
    --output merged.exr --png merged.png
info=$("$raytracer" info merged.exr)
fail() { echo "FAILED: $1"; echo "$info"; exit 1; }
echo "$info" | grep -Eq '^samples +7 per pixel; every pixel holds 7 ' ||
    fail "the merged file should hold 7 samples (3 + 2 + 2) in every pixel"
echo "$info" | grep -Eq '^seeds +1-3$' || fail "the seeds should be 1 to 3"
[ -s merged.png ] || fail "no merged picture"
[ "$(ls -A)" = "$(printf 'merged.exr\nmerged.png')" ] ||
    fail "only the merged files should be left, not: $(ls -A | tr '\n' ' ')"
echo "PASS"
