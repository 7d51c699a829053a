#!/usr/bin/env bash
# Regenerates the "Denoising" section of docs/ACCURACY.md, its error images
# (docs/accuracy/denoising/) and the gallery triple (docs/denoising-*.png): raw and
# OIDN-denoised renders at 4, 16, 64 and 256 spp against a 1024-spp reference (issue 34).
#
#   tools/denoise-report.sh [tools/denoise_report.py options]
#
# e.g. `tools/denoise-report.sh scenes/scene1.in --size 80 60` for a quick look (that
# rewrites the section with only what was asked). Installs Open Image Denoise and
# flip-evaluator in their virtual environment if missing (tools/install-dependencies.sh),
# builds build/raytracer, then runs tools/denoise_report.py with that environment's Python.
# The renders are cached in build-denoise/ (git ignores build*), reused while the scene
# file is older than them; delete the folder to render again. The default ten scenes take
# about 15 minutes on 2 cores with Mesa llvmpipe.
set -euo pipefail
cd "$(dirname "$0")/.."
venv="${RAYTRACER_OIDN_VENV:-$HOME/.local/share/raytracer/oidn-venv}"
tools/install-dependencies.sh
if ! "$venv/bin/python" -c "import flip_evaluator, numpy" 2>/dev/null; then
  echo "denoise-report: $venv has no flip-evaluator (see the warning above)" >&2
  exit 1
fi
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build --target raytracer
exec "$venv/bin/python" tools/denoise_report.py "$@"
