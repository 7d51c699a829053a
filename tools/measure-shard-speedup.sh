#!/usr/bin/env bash
# Times tools/render-shards.sh with 1, 2 and 4 shards, with llvmpipe's own threads and with
# one thread per shard, on a machine shared with other jobs (docs/SCALE_OUT.md, "Speed-up on
# this machine"): each run starts once the processor has been 97 % idle for 3 s, and a run
# during which other processes used more than 0.5 processor-seconds (from /proc/stat, less
# the run's own time) is thrown away and done again, at most 8 times.
#
#   tools/measure-shard-speedup.sh [SCENE WIDTH HEIGHT SPP]   (default scenes/scene3.in 320 240 64)
#
# Prints one line per run kept (and each one thrown away, marked REJECTED).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
scene=${1:-$root/scenes/scene3.in} width=${2:-320} height=${3:-240} spp=${4:-64}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

busy() { awk '/^cpu / {print $2 + $3 + $4 + $7 + $8 + $9}' /proc/stat; }
idle_percent() {
    local a b
    a=$(awk '/^cpu / {print $5 + $6, $2 + $3 + $4 + $5 + $6 + $7 + $8 + $9}' /proc/stat)
    sleep 3
    b=$(awk '/^cpu / {print $5 + $6, $2 + $3 + $4 + $5 + $6 + $7 + $8 + $9}' /proc/stat)
    echo "$a $b" | awk '{printf "%.0f", 100 * ($3 - $1) / ($4 - $2)}'
}
ticks=$(getconf CLK_TCK)

echo "$(nproc) processors, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //'); $scene ${width}x$height, $spp samples per pixel in all"
for threads in default 1; do
    for shards in 1 2 4; do
        options=()
        [ "$threads" = 1 ] && options=(--threads 1)
        for try in $(seq 8); do
            for _ in $(seq 600); do [ "$(idle_percent)" -ge 97 ] && break; done
            before=$(busy)
            /usr/bin/time -f "%U %S %e" -o "$work/time" "$root/tools/render-shards.sh" "$scene" \
                "$width" "$height" "$spp" "$shards" "${options[@]}" --output "$work/m.exr" \
                > "$work/run" 2>&1
            after=$(busy)
            read -r user system wall < "$work/time"
            others=$(awk -v a="$before" -v b="$after" -v u="$user" -v s="$system" -v t="$ticks" \
                'BEGIN { printf "%.2f", (b - a) / t - u - s }')
            line="threads $threads, shards $shards: $(grep 'in all' "$work/run" |
                sed 's/.*rendered in/rendered in/; s/ -> .*//'); processor time $(awk -v u="$user" \
                -v s="$system" 'BEGIN { printf "%.2f", u + s }') s in $wall s; others $others s"
            if awk -v o="$others" 'BEGIN { exit !(o < 0.5) }'; then
                echo "$line"
                break
            fi
            echo "REJECTED $line"
        done
    done
done
