#!/usr/bin/env bash
# The fuzz target of the readers of the render's EXR files (tests/README.md, "Fuzzing"):
#   tools/fuzz-render-files.sh [SECONDS] [extra libFuzzer options]
#       builds render_file_fuzzer with clang (AddressSanitizer and UndefinedBehaviorSanitizer
#       on) into build-fuzz/ and runs it for SECONDS (default 60) over the seeds, the corpus
#       and the findings. The corpus it grows is kept in build-fuzz/render-file-corpus;
#       crashes go to build-fuzz/render-file-findings/. Copy a finding into
#       tests/fuzz/render-file-findings/ once fixed: render_file_fuzz_replay (a ctest test)
#       replays it.
#   tools/fuzz-render-files.sh --seeds
#       renders the seeds, tests/fuzz/render-file-seeds/, with build/raytracer: the program's
#       own files (a render, its statistics, a merge, a resumed render, an adaptive render,
#       other settings, several chunks).
#   tools/fuzz-render-files.sh --findings
#       writes tests/fuzz/render-file-findings/ from the seed render.exr: the crafted files of
#       tests/support/CraftedRenderFiles.cpp (built as make_render_file_findings in build/).
# The fuzzer needs the Debian packages clang-14 and libclang-rt-14-dev, which it installs when
# missing (through install-dependencies.sh; CI only replays). Long runs: prefix with nice -n 15.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
seeds="$root/tests/fuzz/render-file-seeds"

if [ "${1:-}" = "--seeds" ]; then
    raytracer="$root/build/raytracer"
    scene="$root/scenes/scene1.in"
    work="$(mktemp -d)"
    trap 'rm -rf "$work"' EXIT
    cd "$work"
    "$raytracer" "$scene" 8 6 --spp 4 --seed 1 --quiet --output render.exr --stats-output statistics.exr
    "$raytracer" "$scene" 8 6 --spp 4 --seed 2 --quiet --output seed2.exr
    "$raytracer" merge merged.exr render.exr seed2.exr
    "$raytracer" "$scene" --resume render.exr --spp 8 --quiet --output resumed.exr
    # Status 3: --spp came before the target, which is all the seed needs.
    "$raytracer" "$root/tests/scenes/env_none.in" 8 6 --target-error 0.1 --min-spp 4 --spp 128 \
        --quiet --output adaptive.exr || [ $? -eq 3 ]
    "$raytracer" "$root/scenes/scene3.in" 8 6 --spp 2 --max-bounces 3 --sampler independent \
        --exact-geometry --fresnel exact --quiet --output settings.exr
    "$raytracer" "$scene" 16 20 --spp 1 --quiet --output two-chunks.exr
    rm -rf "$seeds"
    mkdir -p "$seeds"
    cp render.exr statistics.exr merged.exr resumed.exr adaptive.exr settings.exr \
        two-chunks.exr "$seeds/"
    ls -l "$seeds"
    exit 0
fi

if [ "${1:-}" = "--findings" ]; then
    cmake --build "$root/build" --target make_render_file_findings
    "$root/build/tests/fuzz/make_render_file_findings" "$seeds/render.exr" \
        "$root/tests/fuzz/render-file-findings"
    exit 0
fi

"$root/tools/install-dependencies.sh" clang-14 libclang-rt-14-dev
seconds="${1:-60}"
shift || true
build="$root/build-fuzz"
(cd "$root" && cmake --preset fuzz >/dev/null)
cmake --build "$build" --target render_file_fuzzer
mkdir -p "$build/render-file-corpus" "$build/render-file-findings"
cd "$build"
# Inputs of up to 64 KB (the seeds are 2 to 20 KB); one allocation above 512 MB is a finding
# (what a 64 KB file may rightly ask is far less); 30 s for one input, as a wide image of a few
# KB (about 10 MB of pixels, allowed) takes half a second under ASan on a loaded machine and
# took 10 s when it was busiest. Each run writes its input to a file
# named .exr in a folder of its own under TMPDIR.
exec "$build/tests/fuzz/render_file_fuzzer" \
    -max_total_time="$seconds" -max_len=65536 -timeout=30 -rss_limit_mb=2048 -malloc_limit_mb=512 \
    -print_final_stats=1 -artifact_prefix="$build/render-file-findings/" "$@" \
    "$build/render-file-corpus" "$seeds" "$root/tests/fuzz/render-file-corpus" \
    "$root/tests/fuzz/render-file-findings"
