#!/usr/bin/env bash
# Renders a scene in shards on this machine with GNU parallel, one raytracer process per
# shard, each with its own seed (so their samples are independent), then merges them into
# one render of all their samples (raytracer merge; docs/SCALE_OUT.md).
#
#   tools/render-shards.sh SCENE WIDTH HEIGHT SPP SHARDS [options] [-- raytracer options]
#
# SPP is the total: shard k (from 0) renders SPP / SHARDS samples per pixel, one more for
# the first SPP % SHARDS shards, with seed FIRST_SEED + k.
#   --output FILE.exr   the merged render (default: SCENE's name .exr in the current folder)
#   --png FILE.png      the merged, tone-mapped picture too
#   --jobs N            shards rendering at once (default: all of them)
#   --first-seed S      the first shard's seed (default 1)
#   --threads N         rendering threads of each shard (Mesa llvmpipe's LP_NUM_THREADS;
#                       default: llvmpipe's own, one per processor)
#   --gpus N            the machine's N GPUs, one shard on each at a time: the shard in GNU
#                       parallel's job slot J renders on GPU (J - 1) mod N (--gl-device,
#                       through EGL; never on the processor). --jobs defaults to N
#   --keep DIR          render the shards into DIR and keep them (default: a temporary folder
#                       beside the output, removed once merged)
#   --raytracer PATH    the program (default: $RAYTRACER, else build/raytracer here)
# Options after -- go to every shard (--max-bounces 8, --sampler independent, ...). A failed
# or interrupted shard stops the others, nothing is merged, and the shards are kept (each can
# go on with raytracer SCENE --resume SHARD.exr --spp N).
set -euo pipefail

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
usage() { sed -n '2,/^set -euo/p' "${BASH_SOURCE[0]}" | sed '$d; s/^# \{0,1\}//' >&2; exit 2; }
fail() { echo "render-shards: $*" >&2; exit "${2:-1}"; }

[ $# -ge 5 ] || usage
scene=$1 width=$2 height=$3 spp=$4 shards=$5
shift 5
output="" png="" jobs="" first_seed=1 threads="" gpus="" keep="" raytracer="${RAYTRACER:-$root/build/raytracer}"
extra=()
while [ $# -gt 0 ]; do
    case "$1" in
        --output) output=${2:?--output needs a file}; shift 2 ;;
        --png) png=${2:?--png needs a file}; shift 2 ;;
        --jobs) jobs=${2:?--jobs needs a number}; shift 2 ;;
        --first-seed) first_seed=${2:?--first-seed needs a number}; shift 2 ;;
        --threads) threads=${2:?--threads needs a number}; shift 2 ;;
        --gpus) gpus=${2:?--gpus needs a number}; shift 2 ;;
        --keep) keep=${2:?--keep needs a folder}; shift 2 ;;
        --raytracer) raytracer=${2:?--raytracer needs a path}; shift 2 ;;
        --) shift; extra=("$@"); break ;;
        *) fail "unknown option '$1' (see the head of $0)" 2 ;;
    esac
done
for number in "$width" "$height" "$spp" "$shards" "$first_seed" ${jobs:+"$jobs"} ${threads:+"$threads"} ${gpus:+"$gpus"}; do
    [[ "$number" =~ ^[0-9]+$ ]] || fail "'$number' is not a whole number" 2
done
[ "$shards" -ge 1 ] || fail "SHARDS must be at least 1" 2
[ -z "$gpus" ] || [ "$gpus" -ge 1 ] || fail "--gpus must be at least 1" 2
[ "$spp" -ge "$shards" ] || fail "SPP ($spp) must be at least SHARDS ($shards): every shard renders a sample" 2

if ! command -v parallel >/dev/null 2>&1 || ! parallel --version 2>/dev/null | grep -q "GNU parallel"; then
    fail "GNU parallel is not installed (Debian package parallel; tools/install-dependencies.sh installs it)"
fi
[ -x "$raytracer" ] || fail "no raytracer program at $raytracer (build it: tools/build.sh, or give --raytracer)"
[ -f "$scene" ] || fail "no scene file $scene"

name=$(basename "$scene" .in)
output=${output:-$name.exr}
if [ -n "$keep" ]; then
    mkdir -p "$keep"
    shard_dir=$keep
else
    shard_dir=$(mktemp -d "$(dirname "$output")/.$name-shards.XXXXXX")
fi
jobs=${jobs:-${gpus:-$shards}}
# Where the shards render: headless as the program chooses (EGL on a GPU, else the CPU), or
# with --gpus each running shard on a GPU of its own: GNU parallel numbers the job slots from
# 1, and a slot runs one job at a time, so the jobs running at once hold different GPUs.
device=(--headless)
[ -n "$gpus" ] && device=(--gl-device "{=1 \$_ = (slot() - 1) % $gpus =}")

seeds=() counts=() files=()
for ((k = 0; k < shards; ++k)); do
    seeds+=($((first_seed + k)))
    counts+=($((spp / shards + (k < spp % shards ? 1 : 0))))
    files+=("$shard_dir/shard-$((first_seed + k)).exr")
done

export_threads=()
[ -n "$threads" ] && export_threads=(env "LP_NUM_THREADS=$threads")

echo "render-shards: $scene at ${width}x$height, $spp samples per pixel in $shards shards" \
     "(seeds ${seeds[0]} to ${seeds[-1]}), $jobs at a time${gpus:+ on $gpus GPUs}, into $shard_dir"
start=$(date +%s.%N)
# One job per (seed, samples) pair (--link); -q passes every argument as it is; a failure
# stops the rest at once. Each shard's summary line comes out tagged with its seed.
if ! parallel --will-cite --halt now,fail=1 --jobs "$jobs" --link -q --line-buffer \
        --tagstring "shard {1}:" \
        "${export_threads[@]}" "$raytracer" "$scene" "$width" "$height" --spp "{2}" --seed "{1}" \
        "${device[@]}" --output "$shard_dir/shard-{1}.exr" "${extra[@]}" \
        ::: "${seeds[@]}" ::: "${counts[@]}"; then
    fail "a shard failed or was interrupted: nothing merged; the shards are in $shard_dir"
fi
rendered=$(date +%s.%N)

merge=("$raytracer" merge "$output" "${files[@]}")
[ -n "$png" ] && merge+=(--png "$png")
"${merge[@]}" || fail "the merge failed: the shards are in $shard_dir"
done_at=$(date +%s.%N)
[ -n "$keep" ] || rm -rf "$shard_dir"
awk -v n="$shards" -v a="$start" -v b="$rendered" -v c="$done_at" -v out="$output" 'BEGIN {
    printf "render-shards: %d shards rendered in %.2f s, merged in %.2f s: %.2f s in all -> %s\n",
           n, b - a, c - b, c - a, out }'
