#!/usr/bin/env bash
# How the cost of a render grows with the scene's objects (issue 33): scenes of 10, 100,
# 1,000, 10,000 and 100,000 objects (a plane and spheres of random sizes on it, one point
# light: bench/many_spheres.py), each rendered once headless at W x H for SPP samples per
# pixel. Prints the machine and a Markdown table: objects, the shader the scene got, set-up
# time (parse to first draw), the hierarchy's build time, the scene data's GPU bytes, Mpaths/s
# and the process's peak memory (/usr/bin/time -v); writes the table as CSV and a plot
# (bench/scaling_plot.py) where OUT says (default: docs/performance/).
#
#   bench/scaling.sh [RAYTRACER=build/raytracer] [SPP=8] [W=160 H=120]
#
# MARCHED=F makes a fraction F of the balls rounded boxes, which rays march
# (many_spheres.py --marched).
# Mesa's shader cache is switched off so that every compile is real. One render per scene:
# run it with nothing else on the machine.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
raytracer="$(readlink -f "${1:-$root/build/raytracer}")"
spp="${2:-8}"
width="${3:-160}"
height="${4:-120}"
out="${OUT:-$root/docs/performance}"
[ -x "$raytracer" ] || { echo "scaling.sh: no program at $raytracer (tools/build.sh)" >&2; exit 2; }
[ -x /usr/bin/time ] || { echo "scaling.sh: needs /usr/bin/time (apt-get install time)" >&2; exit 2; }
export MESA_SHADER_CACHE_DISABLE=true
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
mkdir -p "$out"

echo "machine: $(lscpu | sed -n 's/^Model name: *//p' | head -1), $(nproc) cores; date:" \
     "$(date -u '+%F %H:%M UTC'); load before: $(cut -d' ' -f1-3 /proc/loadavg)"
echo "program: $raytracer (commit $(git -C "$root" rev-parse --short HEAD 2>/dev/null || echo ?)); ${width}x${height}, $spp spp"
echo
echo "| objects | shader | set-up (s) | hierarchy (s) | scene data (MB) | Mpaths/s | peak memory (MB) |"
echo "|---:|---|---:|---:|---:|---:|---:|"
csv="$out/scaling.csv"
echo "objects,setup_s,hierarchy_s,scene_data_mb,mpaths_per_s,peak_mb" > "$csv"
for objects in 10 100 1000 10000 100000; do
    python3 "$root/bench/many_spheres.py" "$objects" ${MARCHED:+--marched "$MARCHED"} > "$work/scene.in"
    /usr/bin/time -v -o "$work/time.txt" "$raytracer" "$work/scene.in" "$width" "$height" \
        --spp "$spp" --headless -o "$work/image.png" > "$work/summary.txt"
    summary="$(cat "$work/summary.txt")"
    seconds="$(sed -E 's/.* spp in ([0-9.]+) s:.*/\1/' <<< "$summary")"
    setup="$(sed -E 's/.*\(setup ([0-9.]+) s.*/\1/' <<< "$summary")"
    hierarchy="$(grep -oE 'hierarchy [0-9.]+ s' <<< "$summary" | grep -oE '[0-9.]+' || echo 0)"
    data="$(grep -oE 'scene data [0-9.]+ MB' <<< "$summary" | grep -oE '[0-9.]+' || echo 0)"
    shader="$([ "$data" = 0 ] && echo specialised || echo hierarchy)"
    peak="$(awk '/Maximum resident set size/ {printf "%.0f", $NF / 1024}' "$work/time.txt")"
    rate="$(awk -v w="$width" -v h="$height" -v n="$spp" -v s="$seconds" \
            'BEGIN { printf "%.4f", w * h * n / s / 1e6 }')"
    echo "| $objects | $shader | $setup | $hierarchy | $data | $rate | $peak |"
    echo "$objects,$setup,$hierarchy,$data,$rate,$peak" >> "$csv"
done
python3 "$root/bench/scaling_plot.py" "$csv" "$out/scaling.svg"
echo
echo "wrote $csv and $out/scaling.svg"
