#!/usr/bin/env bash
# The soak test (tests/README.md, "Soak"; not part of CI): long runs that must keep memory
# flat and leak no GL object.
#   tools/soak.sh [OUT_FOLDER] [FRAMES] [MAX_SECONDS] [WIDTH HEIGHT]
# defaults: soak-out/ 100000 frames, 7200 s (whichever comes first), 32x24. Runs, one after
# the other:
#   1. headless: raytracer --headless --spp FRAMES (one sample per frame, whole frames);
#   2. window:   the same in a GLFW window under xvfb-run, on a copy of the scene in OUT that
#      is edited every SOAK_EDIT_SECONDS (default 3) as an editor saves (a new file renamed
#      over the old), in turn: a colour changed (a values reload), the colour back, the file
#      touched, the file saved unchanged (neither of those two may reload), an object removed
#      (a shader rebuild), the object back (another rebuild). Reloads restart the
#      accumulation, so this run ends at MAX_SECONDS;
#   3. census:   gl_object_census (headless), which replaces the scene every 3 seconds
#      (alternating two scenes, so the shader is rebuilt each time) and counts the live GL
#      objects once a minute.
# Runs 1 and 2 have their resident memory (VmRSS) sampled every SOAK_RSS_SECONDS (default
# 60) into OUT/*-rss.csv; the census reports as often. The window's reloads are counted
# from what it prints (OUT/window.log).
# Run it under nice -n 15 on a shared machine. Needs build/ (tools/build.sh) and xvfb-run.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
out="${1:-soak-out}"
frames="${2:-100000}"
max_seconds="${3:-7200}"
width="${4:-32}"
height="${5:-24}"
rss_seconds="${SOAK_RSS_SECONDS:-60}"
edit_seconds="${SOAK_EDIT_SECONDS:-3}"
mkdir -p "$out"
out="$(cd "$out" && pwd)"
raytracer="$root/build/raytracer"
scene="$root/scenes/scene3.in"

# Runs "$@" (a command ending in the program), sampling its resident memory every
# rss_seconds.
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
        for _ in $(seq "$rss_seconds"); do
            kill -0 "$launcher" 2>/dev/null || break
            sleep 1
        done
    done
    wait "$launcher" || echo "soak: $name ended with status $?" >>"$out/$name.log"
    echo "soak: $name took $((SECONDS - start)) s; $(tail -n 1 "$out/$name.log")"
}

# Saves `text` as OUT/edited/scene.in the way editors do: a new file renamed over the old.
save_scene() {
    printf '%s\n' "$1" >"$out/edited/scene.in.new"
    mv "$out/edited/scene.in.new" "$out/edited/scene.in"
}

# Edits the window's scene every edit_seconds until killed; each edit is logged with the
# time, so that the window's log can be checked against it.
edit_scene_forever() {
    local original recoloured fewer
    original="$(cat "$scene")"
    # The first pigment ("solid 0.6 0.6 1") another colour: values only.
    recoloured="$(printf '%s\n' "$original" | sed '0,/^solid 0.6 0.6 1$/s//solid 0.2 0.9 0.3/')"
    # The last object removed and the count lowered: another shader.
    fewer="$(printf '%s\n' "$original" | sed -e 's/^6$/5/' -e '$d')"
    local step=0
    while true; do
        sleep "$edit_seconds"
        case $((step % 6)) in
            0) save_scene "$recoloured"; kind=values ;;
            1) save_scene "$original"; kind=values ;;
            2) touch "$out/edited/scene.in"; kind=touch ;;
            3) save_scene "$original"; kind=unchanged ;;
            4) save_scene "$fewer"; kind=structure ;;
            5) save_scene "$original"; kind=structure ;;
        esac
        echo "$SECONDS $kind" >>"$out/edits.log"
        step=$((step + 1))
    done
}

run=(timeout --signal=INT "$max_seconds" "$raytracer")
options=("$width" "$height" --spp "$frames" --samples-per-frame 1 --band-seconds 0 --quiet)
sample_rss headless "${run[@]}" "$scene" "${options[@]}" --headless --output "$out/headless.exr"

mkdir -p "$out/edited"
cp "$scene" "$out/edited/scene.in"
: >"$out/edits.log"
edit_scene_forever &
editor=$!
sample_rss window xvfb-run --auto-servernum --server-args="-screen 0 320x240x24 -noreset" \
    "${run[@]}" "$out/edited/scene.in" "${options[@]}" --output "$out/window.exr"
kill "$editor" 2>/dev/null || true
wait "$editor" 2>/dev/null || true
for kind in values touch unchanged structure; do
    echo "soak: window: $(grep -c " $kind$" "$out/edits.log" || true) edits of kind $kind"
done
echo "soak: window printed $(grep -c 'values only' "$out/window.log" || true) values reloads," \
    "$(grep -c 'shader rebuilt' "$out/window.log" || true) rebuilds," \
    "$(grep -c 'changes nothing' "$out/window.log" || true) reloads that changed nothing," \
    "$(grep -c 'error' "$out/window.log" || true) errors"

census_start=$SECONDS
timeout "$((max_seconds + 120))" "$root/build/tests/gl_object_census" "$scene" \
    "$root/scenes/scene1.in" "$width" "$height" "$frames" "$max_seconds" 3 "$rss_seconds" \
    >"$out/census.log" 2>&1 || echo "soak: census ended with status $?" >>"$out/census.log"
echo "soak: census took $((SECONDS - census_start)) s; $(tail -n 1 "$out/census.log")"
