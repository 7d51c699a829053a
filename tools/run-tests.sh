#!/usr/bin/env bash
# The README's second command (and CI's, through .ci/run): installs what is missing, builds,
# and runs every test through ctest.
#   tools/run-tests.sh [extra ctest arguments]
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
"$root/tools/install-dependencies.sh"
"$root/tools/build.sh"
cd "$root/build"
# ctest shows a skipped test's reason only with -V: say it here. install-dependencies.sh
# installs xvfb, so this happens only where installing it failed.
if ! command -v xvfb-run >/dev/null 2>&1; then
    echo "run-tests: xvfb-run is not installed (Debian package xvfb): the window test will be reported as skipped"
fi
ctest --output-on-failure --parallel 2 "$@"
