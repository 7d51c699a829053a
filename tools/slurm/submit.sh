#!/usr/bin/env bash
# Submits a render split over a Slurm job array, and its merge, to the cluster that sbatch
# reaches (docs/SCALE_OUT.md):
#
#   tools/slurm/submit.sh SCENE WIDTH HEIGHT SPP SHARDS OUTPUT.exr [options] [-- sbatch options]
#
#   --png FILE.png      the merged picture too
#   --first-seed S      array task T renders with seed S + T (default 1)
#   --max-running N     at most N shards at once (sbatch --array=0-M%N)
#   --cpus N            processors per shard (default 1)
#   --gpu               each shard on a GPU: sbatch --gres=gpu:1, and the shard renders with
#                       --gl gpu (EGL on a GPU, never on the processor). Each task must see
#                       only its own GPU: Slurm's cgroup ConstrainDevices=yes (see
#                       docs/SCALE_OUT.md, "One shard per GPU")
#   --options "..."     more raytracer options for every shard ("--max-bounces 8")
#   --raytracer PATH    the program (default: $RAYTRACER, else build/raytracer here)
# Options after -- go to both sbatch calls (--partition, --time, --account ...).
#
# The shards go to OUTPUT's folder, in NAME-shards/: on a cluster, every path (the program,
# the scene and the files it uses, the output) must be on a file system all nodes share.
# Prints the two job ids: "array JOB merge JOB".
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
fail() { echo "submit: $*" >&2; exit "${2:-1}"; }
[ $# -ge 6 ] || { sed -n '2,/^set -euo/p' "${BASH_SOURCE[0]}" | sed '$d; s/^# \{0,1\}//' >&2; exit 2; }

scene=$1 width=$2 height=$3 spp=$4 shards=$5 output=$6
shift 6
png="" first_seed=1 max_running="" cpus=1 gpu=0 options="" raytracer="${RAYTRACER:-$root/build/raytracer}"
sbatch_options=()
while [ $# -gt 0 ]; do
    case "$1" in
        --png) png=${2:?}; shift 2 ;;
        --first-seed) first_seed=${2:?}; shift 2 ;;
        --max-running) max_running=${2:?}; shift 2 ;;
        --cpus) cpus=${2:?}; shift 2 ;;
        --gpu) gpu=1; shift ;;
        --options) options=${2?}; shift 2 ;;
        --raytracer) raytracer=${2:?}; shift 2 ;;
        --) shift; sbatch_options=("$@"); break ;;
        *) fail "unknown option '$1'" 2 ;;
    esac
done
for number in "$width" "$height" "$spp" "$shards" "$first_seed" "$cpus" ${max_running:+"$max_running"}; do
    [[ "$number" =~ ^[0-9]+$ ]] || fail "'$number' is not a whole number" 2
done
[ "$spp" -ge "$shards" ] || fail "SPP ($spp) must be at least SHARDS ($shards)" 2
[[ "$output" == *.exr ]] || fail "OUTPUT must be an .exr file (the merge writes OpenEXR)" 2
missing=()
for tool in sbatch squeue scontrol; do
    command -v "$tool" >/dev/null 2>&1 || missing+=("$tool")
done
[ ${#missing[@]} -eq 0 ] || fail "Slurm's ${missing[*]} not found (Debian package slurm-client)"
[ -x "$raytracer" ] || fail "no raytracer program at $raytracer (give --raytracer)"
[ -f "$scene" ] || fail "no scene file $scene"

# Jobs start in the submitting folder on whichever node runs them: absolute paths.
absolute() { realpath -m -- "$1"; }
output=$(absolute "$output")
shard_dir="${output%.exr}-shards"
mkdir -p "$shard_dir"
common="ALL,RAYTRACER=$(absolute "$raytracer"),SHARD_DIR=$shard_dir,SHARDS=$shards,FIRST_SEED=$first_seed"

gres=()
[ "$gpu" = 1 ] && gres=(--gres=gpu:1)
array=$(sbatch --parsable --array="0-$((shards - 1))${max_running:+%$max_running}" \
    --cpus-per-task="$cpus" "${gres[@]}" --output="$shard_dir/shard-%a.log" \
    --export="$common,SCENE=$(absolute "$scene"),WIDTH=$width,HEIGHT=$height,SPP=$spp,GPU=$gpu,RAYTRACER_OPTIONS=$options" \
    "${sbatch_options[@]}" "$here/render-shard.sbatch")
array=${array%%;*}
merge=$(sbatch --parsable --dependency="afterok:$array" --kill-on-invalid-dep=yes \
    --output="${output%.exr}-merge.log" \
    --export="$common,OUTPUT=$output${png:+,PNG=$(absolute "$png")}" \
    "${sbatch_options[@]}" "$here/merge.sbatch")
merge=${merge%%;*}
echo "array $array merge $merge"
echo "submit: $shards shards as job array $array (logs $shard_dir/shard-N.log), the merge as" \
     "job $merge once all succeed (log ${output%.exr}-merge.log) -> $output" >&2
