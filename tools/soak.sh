#!/usr/bin/env bash
# The soak test (tests/README.md, "Soak"; not part of CI): long runs that must keep memory
# flat and leak no GL object.
#   tools/soak.sh [OUT_FOLDER] [FRAMES] [MAX_SECONDS] [WIDTH HEIGHT]
# defaults: soak-out/ 100000 frames, 7200 s (whichever comes first), 32x24. Runs, one after
# the other:
#   1. headless: raytracer --headless --spp FRAMES (one sample per frame, whole frames);
#   2. window:   the same in a GLFW window under xvfb-run;
#   3. census:   gl_object_census (headless), which replaces the scene every 3 seconds
#      (alternating two scenes, so the shader is rebuilt each time) and counts the live GL
#      objects once a minute.
# Runs 1 and 2 have their resident memory (VmRSS) sampled every minute into OUT/*-rss.csv.
# Run it under nice -n 15 on a shared machine. Needs build/ (tools/build.sh) and xvfb-run.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
out="${1:-soak-out}"
frames="${2:-100000}"
max_seconds="${3:-7200}"
width="${4:-32}"
height="${5:-24}"
mkdir -p "$out"
out="$(cd "$out" && pwd)"
raytracer="$root/build/raytracer"
scene="$root/scenes/scene3.in"

# Runs "$@" (a command ending in the program), sampling its resident memory every minute.
sample_rss() {
    local name="$1"
    shift
    echo "seconds,rss_kb" >"$out/$name-rss.csv"
    local start=$SECONDS
    "$@" >"$out/$name.log" 2>&1 &
    local launcher=$!
    local pid=""
    while kill -0 "$launcher" 2>/dev/null; do
        # The render's own process (xvfb-run starts it as a grandchild), known by its output.
        pid="$(pgrep -n -f "^$raytracer .*--output $out/$name" || true)"
        if [ -n "$pid" ] && [ -r "/proc/$pid/status" ]; then
            rss="$(awk '/^VmRSS:/ {print $2}' "/proc/$pid/status" 2>/dev/null || true)"
            [ -n "$rss" ] && echo "$((SECONDS - start)),$rss" >>"$out/$name-rss.csv"
        fi
        for _ in $(seq 60); do
            kill -0 "$launcher" 2>/dev/null || break
            sleep 1
        done
    done
    wait "$launcher" || echo "soak: $name ended with status $?" >>"$out/$name.log"
    echo "soak: $name took $((SECONDS - start)) s; $(tail -n 1 "$out/$name.log")"
}

run=(timeout --signal=INT "$max_seconds" "$raytracer" "$scene" "$width" "$height"
     --spp "$frames" --samples-per-frame 1 --band-seconds 0 --quiet)
sample_rss headless "${run[@]}" --headless --output "$out/headless.exr"
sample_rss window xvfb-run --auto-servernum --server-args="-screen 0 320x240x24" \
    "${run[@]}" --output "$out/window.exr"
census_start=$SECONDS
timeout "$((max_seconds + 120))" "$root/build/tests/gl_object_census" "$scene" \
    "$root/scenes/scene1.in" "$width" "$height" "$frames" "$max_seconds" 3 \
    >"$out/census.log" 2>&1 || echo "soak: census ended with status $?" >>"$out/census.log"
echo "soak: census took $((SECONDS - census_start)) s; $(tail -n 1 "$out/census.log")"
