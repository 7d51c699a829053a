#!/usr/bin/env bash
# Where the time goes: for each scene, the renderer's own shaders against copies with one part
# of the work taken out, or done twice where taking it out would change the paths, the two
# alternating. A part's share of the time is 1 - (time without it) / (time with it), or
# (time with it twice) / (time with it) - 1, the median of PAIRS pairs. The images rendered
# without a part are wrong (that is the point); the shares only say what each part costs,
# on this machine, with llvmpipe's 8-wide lockstep included (a part that one lane of a SIMD
# group needs is paid by all eight).
#
#   bench/time-shares.sh [--pairs N] [--size W H] [--spp N] SCENE...
#
# The parts:
#   shadow rays   taken out: every light sample arrives unblocked (the paths are the same)
#   normals       twice: every marched surface's normal differenced again at a step 0.1 %
#                 shorter, the two averaged (the same normal: the paths are the same)
#   near misses   taken out: a near miss ends the search (no continuation with a finer
#                 tolerance)
#   pigments      twice: every surface colour looked up again a hair away, the two averaged
#   bounces       taken out: the camera ray's hit only (--max-bounces 0)
# Run it with nothing else on the machine; docs/PERFORMANCE.md quotes it. The machine's speed
# drifts (a share moved by 10 % between runs on the development machine): give PAIRS >= 5.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
raytracer="${RAYTRACER:-$root/build/raytracer}"
pairs=3
width=400
height=300
spp=16
scenes=()
while [ $# -gt 0 ]; do
    case "$1" in
        --pairs) pairs="$2"; shift 2 ;;
        --size) width="$2"; height="$3"; shift 3 ;;
        --spp) spp="$2"; shift 2 ;;
        -*) echo "time-shares.sh: unknown option $1" >&2; exit 2 ;;
        *) scenes+=("$1"); shift ;;
    esac
done
[ ${#scenes[@]} -gt 0 ] || { echo "usage: bench/time-shares.sh [--pairs N] [--size W H] [--spp N] SCENE..." >&2; exit 2; }
[ -x "$raytracer" ] || { echo "time-shares.sh: no program at $raytracer (tools/build.sh)" >&2; exit 2; }

work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT

# variant NAME FILE OLD NEW: a copy of the data folder (shaders, textures) with OLD replaced
# by NEW in shaders/modules/FILE; fails when OLD is not there (the shaders moved on).
variant() {
    local name="$1" file="$2" old="$3" new="$4"
    mkdir -p "$work/$name"
    cp -r "$root/shaders" "$work/$name/"
    [ -d "$root/textures" ] && ln -s "$root/textures" "$work/$name/textures"
    OLD="$old" NEW="$new" python3 - "$work/$name/shaders/modules/$file" <<'EOF'
import os, sys
path = sys.argv[1]
text = open(path).read()
old, new = os.environ["OLD"], os.environ["NEW"]
if old not in text:
    sys.exit(f"time-shares.sh: '{old}' is no longer in {path}")
open(path, "w").write(text.replace(old, new))
EOF
}
variant shadows lights.glsl \
    'vec3 transmittance = shadowTransmittance(s, wi, distance, insideSign, tolerance, target);' \
    'vec3 transmittance = vec3(1.0);'
variant normals sphere_tracing.glsl \
    'vec3 sceneGradient(vec3 p, float step)
{' \
    'vec3 sceneGradientOnce(vec3 p, float step);
vec3 sceneGradient(vec3 p, float step)
{
    return 0.5 * (sceneGradientOnce(p, step) + sceneGradientOnce(p, 0.999 * step));
}
vec3 sceneGradientOnce(vec3 p, float step)
{'
variant nearmisses ray_queries_traced.glsl \
    'const int kNearMissRetries = 3;' 'const int kNearMissRetries = 0;'
# pigmentColor is generated from the pigment table and follows pigments.glsl: the copy
# wraps it at the head of materials.glsl, the next module, and names the wrapper for the
# modules after it.
variant pigments materials.glsl \
    '// Materials (the scene format'"'"'s finishes) as BSDFs.' \
    'vec3 pigmentColorTwice(int pigment, vec3 p, vec3 n, float footprint, float offSurface)
{
    return 0.5 * (pigmentColor(pigment, p, n, footprint, offSurface) +
                  pigmentColor(pigment, p + 1e-6 * n, n, 1.001 * footprint, offSurface));
}
#define pigmentColor pigmentColorTwice
// Materials (the scene format'"'"'s finishes) as BSDFs.'

# median X...: the middle value (the mean of the two middle ones for an even count).
median() {
    printf '%s\n' "$@" | sort -g | awk '{a[NR]=$1} END {print (NR%2) ? a[(NR+1)/2] : (a[NR/2]+a[NR/2+1])/2}'
}

# seconds DATA SCENE [ARGS]: the render's own time for exactly $spp samples per pixel.
seconds() {
    local data="$1" scene="$2"
    shift 2
    (cd "$(dirname "$scene")" &&
        RAYTRACER_DATA_DIR="$data" "$raytracer" "$(basename "$scene")" "$width" "$height" \
            --spp "$spp" --quiet --headless --summary-json "$work/summary.json" \
            --output "$work/render.exr" "$@")
    sed -n 's/^  "seconds": \([0-9.e+-]*\),$/\1/p' "$work/summary.json"
}

echo "machine: $(lscpu | sed -n 's/^Model name: *//p' | head -1), $(nproc) cores; date: $(date -u '+%F %H:%M UTC')"
echo "commit: $(git -C "$root" rev-parse --short HEAD 2>/dev/null || echo unknown); $width x $height, $spp spp, median of $pairs alternating pairs"
echo
echo "| scene | shadow rays | normals | near misses | pigments | bounces (all but the camera ray's hit) | s per render |"
echo "|---|---|---|---|---|---|---|"
for scene in "${scenes[@]}"; do
    # Once each, untimed: llvmpipe generates a shader's machine code at its first draw, and
    # Mesa's shader cache keeps it for the timed runs.
    # (The same folder names as the timed runs: the shader names its user SDFs' files.)
    for data in "$root" "$work"/{shadows,normals,nearmisses,pigments}; do
        seconds "$data" "$scene" >/dev/null
    done
    seconds "$root" "$scene" --max-bounces 0 >/dev/null
    row="| $(basename "$scene" .in) |"
    base_all=()
    for part in shadows normals nearmisses pigments bounces; do
        ratios=()
        for _ in $(seq "$pairs"); do
            with=$(seconds "$root" "$scene")
            if [ "$part" = bounces ]; then
                without=$(seconds "$root" "$scene" --max-bounces 0)
            else
                without=$(seconds "$work/$part" "$scene")
            fi
            base_all+=("$with")
            case "$part" in
                normals | pigments) ratios+=("$(python3 -c "print($without / $with - 1)")") ;;
                *) ratios+=("$(python3 -c "print(1 - $without / $with)")") ;;
            esac
        done
        share=$(median "${ratios[@]}")
        row="$row $(python3 -c "print(f'{100 * $share:.0f} %')") |"
    done
    median_base=$(median "${base_all[@]}")
    echo "$row $median_base |"
    # A render of a fraction of a second is at the mercy of one stall of the machine (and of
    # the summary's 10 ms resolution): its shares mean nothing.
    if python3 -c "import sys; sys.exit(0 if $median_base < 1.0 else 1)"; then
        echo "(the row above: renders of $median_base s are too short to time; give more --spp or a larger --size)"
    fi
done
echo "(share of the render's time: saved by taking the part out, or added by doing it twice; the parts overlap and need not sum to 100 %)"
