#!/usr/bin/env bash
# Configures and builds the project into build/ (Release, Ninja): everything, the tests and
# benchmarks included, or with --program the program alone (build/raytracer), which is what
# tools/render-demo.sh needs. Each mode says which it wants, so the one run last decides.
#   tools/build.sh [--program]
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
if [ "${1:-}" = --program ]; then
  cmake -S "$root" -B "$root/build" -G Ninja -DCMAKE_BUILD_TYPE=Release \
    -DRAYTRACER_BUILD_TESTS=OFF -DRAYTRACER_BUILD_BENCHMARKS=OFF >/dev/null
  cmake --build "$root/build" --parallel --target raytracer
else
  cmake -S "$root" -B "$root/build" -G Ninja -DCMAKE_BUILD_TYPE=Release \
    -DRAYTRACER_BUILD_TESTS=ON -DRAYTRACER_BUILD_BENCHMARKS=ON >/dev/null
  cmake --build "$root/build" --parallel
fi
