#!/usr/bin/env bash
# Time to a target error (--target-error), uniform against adaptive sampling, and how good
# the program's prediction of that time is (issue 19). For each scene and target it renders
# with adaptive sampling (seeds 1 and 2: their difference measures the error reached, with no
# reference and no estimate involved) and with uniform sampling (seed 1), alternately, each
# under a time limit; the progress line (read through a pseudo-terminal, as a user sees it)
# gives the predictions. Prints a table and writes the section "Rendering to a target error"
# of docs/ACCURACY.md, its CSV and the sample-count image (tools/../bench/target_error.py).
#
#   bench/target-error.sh [SCENE.in ...]      (default: scenes/scene1.in ... scene7.in)
#
# Variables: TARGET_SIZE ("48 36"), TARGET_ERRORS ("0.02 0.01"), TARGET_LIMIT (seconds per
# render, 60: a render still short of its target then has its time extrapolated, and says
# so), TARGET_DIR (renders and logs; default build-accuracy/target-error, which git ignores).
# A benchmark: run it alone on the machine.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
size="${TARGET_SIZE:-48 36}"
targets="${TARGET_ERRORS:-0.02 0.01}"
limit="${TARGET_LIMIT:-60}"
dir="${TARGET_DIR:-$root/build-accuracy/target-error}"
command -v script >/dev/null || { echo "needs script(1) (util-linux)" >&2; exit 1; }
"$root/tools/install-dependencies.sh" python3-matplotlib >/dev/null
"$root/tools/build.sh" >/dev/null
mkdir -p "$dir"
if [ $# -gt 0 ]; then scenes=("$@"); else scenes=("$root"/scenes/scene[1-7].in); fi

# One render; its terminal output (progress lines and summary) goes to NAME.log.
render() {
    local scene="$1" name="$2"; shift 2
    script -qec "stty cols 250; '$root/build/raytracer' '$scene' $size $limit --headless \
        --output '$dir/$name.pfm' --stats-output '$dir/$name-stats.pfm' $*" /dev/null \
        > "$dir/$name.log"
    tr '\r' '\n' < "$dir/$name.log" | grep -a ' -> ' | sed 's/\x1b\[K//g; s/ -> [^;]*//'
}

for scene in "${scenes[@]}"; do
    name="$(basename "$scene" .in)"
    for target in $targets; do
        echo "$name, target $target:"
        render "$scene" "$name-$target-adaptive-s1" --target-error "$target" --seed 1
        render "$scene" "$name-$target-uniform-s1" --target-error "$target" --seed 1 --uniform-sampling
        render "$scene" "$name-$target-adaptive-s2" --target-error "$target" --seed 2
    done
done
# -s: Debian's numpy, the one its matplotlib was built for, not a pip-installed one in ~/.local
/usr/bin/python3 -s "$root/bench/target_error.py" "$dir" --size $size --limit "${TARGET_LIMIT_TEXT:-$limit}" \
    --markdown "$root/docs/ACCURACY.md" --image-dir "$root/docs/accuracy"
