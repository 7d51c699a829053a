#!/usr/bin/env bash
# The README's second command (and CI's, through .ci/run): installs what is missing, builds,
# and runs every test through ctest.
#   tools/run-tests.sh [extra ctest arguments]
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
"$root/tools/install-dependencies.sh"
"$root/tools/build.sh"
cd "$root/build"
ctest --output-on-failure --parallel 2 "$@"
