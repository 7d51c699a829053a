#!/usr/bin/env bash
# Builds the scene parser's libFuzzer target with clang (AddressSanitizer and
# UndefinedBehaviorSanitizer on) into build-fuzz/ and runs it (tests/README.md, "Fuzzing").
#   tools/fuzz-scene-parser.sh [SECONDS] [extra libFuzzer options]
# Seeds: every scene in the repository, plus tests/fuzz/corpus and tests/fuzz/findings. The
# corpus it grows is kept in build-fuzz/corpus; crashes go to build-fuzz/findings/. Copy a
# finding into tests/fuzz/findings/ once fixed: scene_fuzz_replay (a ctest test) replays it.
# Needs the Debian packages clang-14 and libclang-rt-14-dev, which it installs when missing
# (through install-dependencies.sh, which installs them for nothing else: CI only replays).
# Long runs: prefix with nice -n 15.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
"$root/tools/install-dependencies.sh" clang-14 libclang-rt-14-dev
seconds="${1:-60}"
shift || true
build="$root/build-fuzz"
(cd "$root" && cmake --preset fuzz >/dev/null)
cmake --build "$build" --target scene_fuzzer
seeds="$build/seeds"
rm -rf "$seeds"
mkdir -p "$seeds" "$build/corpus" "$build/findings"
# Flattened names: scenes/examples/camera.in -> scenes_examples_camera.in
(cd "$root" && git ls-files '*.in') | while read -r scene; do
    cp "$root/$scene" "$seeds/${scene//\//_}"
done
cd "$build"
exec "$build/tests/fuzz/scene_fuzzer" -dict="$root/tests/fuzz/scene.dict" \
    -max_total_time="$seconds" -max_len=8192 -timeout=10 -rss_limit_mb=2048 \
    -print_final_stats=1 -artifact_prefix="$build/findings/" "$@" \
    "$build/corpus" "$seeds" "$root/tests/fuzz/corpus" "$root/tests/fuzz/findings"
