#!/usr/bin/env bash
# The README's first command: installs what the program needs and is missing, builds the
# program alone (no tests), and renders classic scene 3 to scene3.png (headless when there is
# no display; 400x300 for 20 seconds).
#   tools/render-demo.sh [SCENE] [SECONDS]
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
scene="${1:-$root/scenes/scene3.in}"
seconds="${2:-20}"
"$root/tools/install-dependencies.sh" --program
"$root/tools/build.sh" --program
name="$(basename "${scene%.*}")"
"$root/build/raytracer" "$scene" 400 300 "$seconds" --output "$name.png"
echo "wrote $(pwd)/$name.png"
