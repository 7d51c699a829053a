#!/usr/bin/env bash
# The README's second command (and CI's, through .ci/run): installs what is missing, builds,
# and runs every test through ctest.
#   tools/run-tests.sh [extra ctest arguments]
# Then the GL-free tests (label unit: the scene parser and model, the output files, the shader
# generator, merging and the files' metadata, the window's parts without a window, the fuzz
# corpus replay) again in an AddressSanitizer + UndefinedBehaviorSanitizer build in
# build-sanitize/ (the "sanitize" preset); RAYTRACER_SKIP_SANITIZER=1 skips it.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
"$root/tools/install-dependencies.sh"
"$root/tools/build.sh"
cd "$root/build"
# ctest shows a skipped test's reason only with -V: say it here. install-dependencies.sh
# installs xvfb and xdotool, so this happens only where installing them failed.
if ! command -v Xvfb >/dev/null 2>&1; then
    echo "run-tests: Xvfb is not installed (Debian package xvfb): the window tests will be reported as skipped"
elif ! command -v xdotool >/dev/null 2>&1; then
    echo "run-tests: xdotool is not installed (Debian package xdotool): the interactive window tests will be reported as skipped"
fi
if ! ls "${RAYTRACER_OIDN_VENV:-$HOME/.local/share/raytracer/oidn-venv}"/lib/python3*/site-packages/pyoidn/oidn/lib/libOpenImageDenoise.so.2 >/dev/null 2>&1 \
   && [ -z "${RAYTRACER_OIDN_LIBRARY:-}" ]; then
    echo "run-tests: Open Image Denoise is not installed (see install-dependencies' warning): the tests that denoise will be skipped"
fi
ctest --output-on-failure --parallel 2 "$@"

if [ "${RAYTRACER_SKIP_SANITIZER:-0}" != 1 ]; then
    echo "run-tests: the GL-free tests again under AddressSanitizer and UndefinedBehaviorSanitizer (build-sanitize/)"
    cd "$root"
    cmake --preset sanitize >/dev/null
    cmake --build build-sanitize --parallel --target scene_tests io_tests shadergen_tests \
        film_tests interaction_tests scene_fuzz_replay render_file_fuzz_replay
    ctest --preset sanitize
fi
