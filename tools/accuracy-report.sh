#!/usr/bin/env bash
# Regenerates docs/ACCURACY.md, docs/accuracy/*.csv and docs/accuracy/*.png: what accuracy
# costs in time (issue 7). Installs what is missing, builds bench_convergence, runs it over
# the classic scenes, then writes the page with tools/accuracy_report.py.
#
#   tools/accuracy-report.sh                       full configuration
#   ACCURACY_SCALE=quick tools/accuracy-report.sh  quick configuration, to try the pipeline
#
# The full configuration renders the convergence and settings sweeps at 160x120
# (references of 2048 spp, convergence to 512 spp, 256 spp per accuracy-setting value) and
# the equal-time view at 320x240 (budgets of 1, 10 and 60 s, against references of 2048
# spp at that size). On 2 cores with Mesa llvmpipe and nothing else running it takes about
# two hours and a half, most of it the references (scene6 alone about 40 minutes);
# ACCURACY_* below give a longer or shorter run. The quick configuration renders at 80x60
# (references of 1024 spp, convergence to 128, 128 spp per setting value, budgets of 0.5,
# 2 and 8 s) and takes about 12 minutes.
#
# Variables (each optional):
#   ACCURACY_SCALE          full (default) or quick
#   ACCURACY_SCENES         scene files, space-separated (default: scenes/scene1.in ... scene7.in)
#   ACCURACY_SIZE           "W H" of the convergence and settings renders
#   ACCURACY_REFERENCE_SPP  samples per pixel of the references
#   ACCURACY_MAX_SPP        last spp of the convergence sweep (1, 2, 4, ... this)
#   ACCURACY_SETTINGS_SPP   samples per pixel of each setting value's render
#   ACCURACY_SETTINGS       settings to sweep, comma-separated (default: all)
#   ACCURACY_BUDGETS        equal-time budgets in seconds, comma-separated
#   ACCURACY_BUDGET_SIZE    "W H" of the equal-time renders
#   ACCURACY_BUILD_DIR      build folder (default: build-accuracy/ in the repository, which
#                           git ignores)
#   ACCURACY_CACHE          reference cache (default: accuracy-cache/ in the build folder)
#   ACCURACY_REFRESH=1      render the references again even when cached
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"

scale="${ACCURACY_SCALE:-full}"
case "$scale" in
  full)
    size="160 120"; reference_spp=2048; max_spp=512; settings_spp=256
    budgets="1,10,60"; budget_size="320 240"
    ;;
  quick)
    size="80 60"; reference_spp=1024; max_spp=128; settings_spp=128
    budgets="0.5,2,8"; budget_size="80 60"
    ;;
  *)
    echo "accuracy-report: ACCURACY_SCALE must be full or quick, not '$scale'" >&2
    exit 2
    ;;
esac
size="${ACCURACY_SIZE:-$size}"
reference_spp="${ACCURACY_REFERENCE_SPP:-$reference_spp}"
max_spp="${ACCURACY_MAX_SPP:-$max_spp}"
settings_spp="${ACCURACY_SETTINGS_SPP:-$settings_spp}"
budgets="${ACCURACY_BUDGETS:-$budgets}"
budget_size="${ACCURACY_BUDGET_SIZE:-$budget_size}"
build="${ACCURACY_BUILD_DIR:-$root/build-accuracy}"
note=""
if [ "$scale" = quick ]; then
  note="**Quick configuration** (\`ACCURACY_SCALE=quick\`): ${size/ /x} pixels, references of"
  note+=" $reference_spp spp, convergence to $max_spp spp, $settings_spp spp per setting value,"
  note+=" budgets of ${budgets//,/, } s at ${budget_size/ /x}. It proves the pipeline end to"
  note+=" end; its numbers are not those of the full configuration"
  note+=" (\`tools/accuracy-report.sh\`: 160x120 sweeps and references of 2048 spp, budgets of"
  note+=" 1, 10 and 60 s at 320x240), which replaces this page when it is run. At 80x60 a"
  note+=" pixel's footprint is 2x that at 160x120, so every tolerance counted in footprints is 2x"
  note+=" larger in the scene, and each error is averaged over 4x fewer pixels."
fi
cache="${ACCURACY_CACHE:-$build/accuracy-cache}"
if [ -n "${ACCURACY_SCENES:-}" ]; then
  read -r -a scenes <<< "$ACCURACY_SCENES"
else
  scenes=("$root"/scenes/scene{1,2,3,4,5,6,7}.in)
fi

"$root/tools/install-dependencies.sh" python3-matplotlib
cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DRAYTRACER_BUILD_TESTS=OFF \
  >/dev/null
cmake --build "$build" --target bench_convergence

# Measured into a scratch folder first: a run that fails or is interrupted leaves the
# committed report as it was.
run="$build/accuracy-run"
rm -rf "$run"
mkdir -p "$run"
options=(--size $size --reference-spp "$reference_spp" --max-spp "$max_spp"
         --settings-spp "$settings_spp" --budgets "$budgets" --budget-size $budget_size
         --cache "$cache" --output "$run")
if [ -n "${ACCURACY_SETTINGS:-}" ]; then
  options+=(--settings "$ACCURACY_SETTINGS")
fi
if [ "${ACCURACY_REFRESH:-0}" = 1 ]; then
  options+=(--refresh-references)
fi
# Mesa keeps compiled shaders in an on-disk cache; with it, compile and first-draw times
# would say only whether an earlier run had seen the same shader. Off, they are what a first
# render of the scene costs. (Rendering speed is the same either way.)
export MESA_SHADER_CACHE_DISABLE=true
# The tables go to the terminal and, for the record, beside the CSVs.
"$build/bench/bench_convergence" "${options[@]}" "${scenes[@]}" | tee "$run/bench_convergence.txt"

data="$root/docs/accuracy"
mkdir -p "$data"
rm -f "$data"/*.csv "$data"/*.png "$data"/*.txt
cp "$run"/*.csv "$run"/*.txt "$data"/
command="tools/accuracy-report.sh"
if [ "$scale" = quick ]; then
  command="ACCURACY_SCALE=quick tools/accuracy-report.sh"
fi
# -s: Debian's numpy, the one its matplotlib was built for, not a pip-installed one in ~/.local
/usr/bin/python3 -s "$root/tools/accuracy_report.py" "$data" "$root/docs/ACCURACY.md" \
  --configuration "$scale" --command "$command" --note "$note"
echo "accuracy-report: wrote docs/ACCURACY.md and docs/accuracy/"
