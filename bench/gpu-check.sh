#!/usr/bin/env bash
# The check to run on a machine with a GPU (issue 31), in one go: builds the program and the
# image regression tests, runs the regression tests through EGL (so on the GPU, not on
# llvmpipe), then measures, for the seven classic scenes at 800x600 (the seed's resolution),
# million paths per second for the fragment and the compute kernel, the two alternating, and
# prints a table naming GL_RENDERER with the seed's own figures beside ours (from its report:
# another machine, so never a ratio). Meant to finish in under 5 minutes on a GPU; so far it
# has run only on llvmpipe (docs/PERFORMANCE.md).
#
#   bench/gpu-check.sh [--gl-device N] [--rounds N] [--spp N] [--size W H] [--build-dir DIR]
#                      [--skip-build] [--skip-tests]
#
# --gl-device N: the Nth GPU EGL lists (default: EGL's choice, the first GPU; the regression
# tests always take that one). --rounds: measuring rounds (default 3); --spp: samples per
# pixel each render traces (default 256: 123 million paths, a fraction of a second to a few
# seconds on a GPU; every render stops at 30 s whatever it holds). Both kernels trace the
# same samples, so their ratio is of equal work. On a software rasteriser (llvmpipe) it says
# so and runs reduced: the regression tests of the classic scenes only, 2 samples per pixel
# per render (a few seconds each) and 2 rounds; the table is then llvmpipe's. --size: another
# image size than 800 x 600 (with --skip-build --skip-tests: only the kernels' comparison).
# The ratio column is the median of the rounds' ratios, each of a fragment and a compute
# render run one after the other, with the smallest and largest in brackets.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="$root/build-gpu-check"
device=() rounds="" spp="" width=800 height=600 build_it=1 test_it=1
while [ $# -gt 0 ]; do
  case "$1" in
    --gl-device) device=(--gl-device "$2"); shift 2 ;;
    --rounds) rounds="$2"; shift 2 ;;
    --spp) spp="$2"; shift 2 ;;
    --size) width="$2"; height="$3"; shift 3 ;;
    --build-dir) build="$(readlink -f "$2")"; shift 2 ;;
    --skip-build) build_it=0; shift ;;
    --skip-tests) test_it=0; shift ;;
    *) echo "usage: gpu-check.sh [--gl-device N] [--rounds N] [--spp N] [--size W H] [--build-dir DIR]" \
            "[--skip-build] [--skip-tests]" >&2; exit 2 ;;
  esac
done
start=$SECONDS
elapsed() { echo "$((SECONDS - start)) s"; }
raytracer="$build/raytracer"

echo "== gpu-check: $(date -u '+%F %H:%M UTC'), commit" \
     "$(git -C "$root" rev-parse --short HEAD 2>/dev/null || echo unknown)"
echo "machine: $(lscpu | sed -n 's/^Model name: *//p' | head -1), $(nproc) cores," \
     "$(awk '/MemTotal/ {printf "%.0f GiB", $2 / 1048576}' /proc/meminfo)"
if command -v nvidia-smi >/dev/null 2>&1; then
  echo "nvidia-smi: $(nvidia-smi --query-gpu=index,name,driver_version --format=csv,noheader |
                       paste -sd ';' -)"
fi

if [ "$build_it" = 1 ]; then
  echo "== building in $build ($(elapsed))"
  launcher=()
  command -v ccache >/dev/null 2>&1 && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
  cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release \
    -DRAYTRACER_BUILD_BENCHMARKS=OFF "${launcher[@]}" >/dev/null
  cmake --build "$build" --parallel "$(nproc)" --target raytracer regression_tests >/dev/null
fi
[ -x "$raytracer" ] || { echo "gpu-check.sh: no program at $raytracer" >&2; exit 2; }

# The renderer EGL gives (what the measurements run on), from --features.
features="$(env -u DISPLAY -u WAYLAND_DISPLAY "$raytracer" "$root/scenes/scene1.in" --features \
            --gl egl "${device[@]}" 2>&1)" || { echo "$features" >&2; exit 1; }
opengl="$(echo "$features" | sed -n 's/^OpenGL: *//p')"
# "KIND: RENDERER, OpenGL VERSION"
context="${opengl%%: *}" renderer="${opengl#*: }"
version="${renderer##*, OpenGL }" renderer="${renderer%, OpenGL *}"
auto_kernel="$(echo "$features" | sed -n 's/^kernel: *//p')"
echo "OpenGL (EGL): $opengl"
echo "--kernel auto here: $auto_kernel"
reduced=0
case "$opengl" in
  *llvmpipe*|*softpipe*|*swrast*|*"software device"*)
    reduced=1
    echo "NOTE: this is a software rasteriser on the processor, not a GPU: reduced run (the" \
         "classic scenes' regression tests only; by default 2 samples per pixel per render," \
         "2 rounds)" ;;
esac
[ -n "$rounds" ] || rounds=$([ "$reduced" = 1 ] && echo 2 || echo 3)
[ -n "$spp" ] || spp=$([ "$reduced" = 1 ] && echo 2 || echo 256)

tests_status=0
if [ "$test_it" = 1 ]; then
  echo "== image regression through EGL ($(elapsed))"
  filter=()
  # ctest names a parameterised case "Case/...Reference/scene1  # GetParam() = scene1".
  [ "$reduced" = 1 ] && filter=(-R '/scene[1-7]( |$)')
  ctest --test-dir "$build" -L regression-egl "${filter[@]}" --parallel "$(nproc)" \
    --no-tests=error --output-on-failure > "$build/gpu-check-tests.log" 2>&1 || tests_status=$?
  grep -E '^[0-9]+% tests passed|tests failed|\(Failed\)|Not Run' "$build/gpu-check-tests.log" ||
    tail -5 "$build/gpu-check-tests.log"
fi

echo "== kernels side by side: 7 scenes x 2 kernels x $rounds rounds ($(elapsed))"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
declare -A rate last
measure() {  # scene kernel -> appends the Mpaths/s of one render to rate[scene,kernel]
  local scene="$1" kernel="$2" line
  rm -f "$work/summary.json"
  line="$(env -u DISPLAY -u WAYLAND_DISPLAY "$raytracer" "$root/scenes/$scene.in" "$width" "$height" \
          30 --spp "$spp" --gl egl "${device[@]}" --kernel "$kernel" --quiet \
          --summary-json "$work/summary.json" --output "$work/$scene-$kernel.exr" 2>&1 | tail -1)"
  local mpaths
  mpaths="$(sed -n 's/^  "megapathsPerSecond": \([0-9.e+-]*\),$/\1/p' "$work/summary.json" 2>/dev/null || true)"
  last[$kernel]=""
  [ -n "$mpaths" ] || { echo "  $scene $kernel: FAILED: $line"; return 0; }
  rate[$scene,$kernel]="${rate[$scene,$kernel]:-} $mpaths"
  last[$kernel]="$mpaths"
  echo "  round $round $scene $kernel: $mpaths Mpaths/s"
}
scenes=(scene1 scene2 scene3 scene4 scene5 scene6 scene7)
for round in $(seq "$rounds"); do
  for scene in "${scenes[@]}"; do
    # Alternating, each kernel first in every other round: neither is always the one that
    # runs on a machine just warmed (or slowed) by the other.
    if [ $((round % 2)) = 1 ]; then order=(fragment compute); else order=(compute fragment); fi
    for kernel in "${order[@]}"; do measure "$scene" "$kernel"; done
    if [ -n "${last[fragment]}" ] && [ -n "${last[compute]}" ]; then
      rate[$scene,ratio]="${rate[$scene,ratio]:-} $(awk -v c="${last[compute]}" \
                                                      -v f="${last[fragment]}" 'BEGIN{print c / f}')"
    fi
  done
done

median() { tr ' ' '\n' | grep . | sort -g |
           awk '{a[NR]=$1} END{if (NR) print (NR%2)?a[(NR+1)/2]:(a[NR/2]+a[NR/2+1])/2}'; }
# The seed's report (../shared/seed): 800x600 samples and minutes per figure, so its Mpaths/s,
# on its author's 2015 GPU (a GTX 970 per issue 31; the report names none). Classic scene 3
# has no figure of its own. Its Figure 8 (400x300: 50 samples in 5.82 s, 200 in 23.3 s) is
# the "about 1.03 Mpaths/s" quoted for it.
declare -A seed=([scene1]="1.10 (fig. 7)" [scene2]="1.19 (fig. 9)" [scene3]="-"
                 [scene4]="2.42 (fig. 11)" [scene5]="4.77 (fig. 12)" [scene6]="0.48 (fig. 14)"
                 [scene7]="1.14 (fig. 13)")
echo
echo "GL_RENDERER: $renderer"
echo "GL_VERSION: $version"
echo "context: $context"
echo
echo "| scene | fragment Mpaths/s | compute Mpaths/s | compute / fragment, pair by pair [range] | the seed's report, Mpaths/s (another machine: its 2015 GPU) |"
echo "|---|---|---|---|---|"
for scene in "${scenes[@]}"; do
  f="$(echo ${rate[$scene,fragment]:-} | median)"; c="$(echo ${rate[$scene,compute]:-} | median)"
  ratio="-"
  if [ -n "${rate[$scene,ratio]:-}" ]; then
    ratios="$(echo ${rate[$scene,ratio]} | tr ' ' '\n' | sort -g)"
    ratio="$(printf '%.2fx [%.2f-%.2f]' "$(echo $ratios | median)" "$(echo "$ratios" | head -1)" \
             "$(echo "$ratios" | tail -1)")"
  fi
  echo "| $scene | ${f:--} | ${c:--} | $ratio | ${seed[$scene]} |"
done
size="$width x $height, $spp spp per render"
echo "($size, median of $rounds alternating rounds; the seed's column is its report's," \
     "from another machine: about 1.03 Mpaths/s in its Figure 8, 400x300)"
echo "== done in $(elapsed)"
if [ "$tests_status" != 0 ]; then
  echo "gpu-check.sh: the regression tests through EGL FAILED (log: $build/gpu-check-tests.log)" >&2
  exit 1
fi
