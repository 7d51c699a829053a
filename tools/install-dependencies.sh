#!/usr/bin/env bash
# Installs the Debian packages the project needs, only those missing. Idempotent.
#   tools/install-dependencies.sh [--program] [extra-package ...]
# --program: only what building and running the program takes (tools/render-demo.sh), not
# the tests' and the scale-out tools' (GoogleTest, Xvfb, xdotool, GNU parallel, Slurm, munge,
# OpenImageIO's tools, Python).
set -euo pipefail

program_only=0
if [ "${1:-}" = --program ]; then
  program_only=1
  shift
fi

# The program: the compiler and build tools, and the libraries it links (CMakeLists.txt).
packages=(
  cmake ninja-build g++ pkg-config
  libglfw3-dev libglew-dev libglm-dev libosmesa6-dev libegl-dev libegl-mesa0
  libopenimageio-dev libopenexr-dev
  libimgui-dev libx11-dev
  libssl-dev
)
if [ "$program_only" = 0 ]; then
  packages+=(
    openimageio-tools
    parallel slurm-wlm munge
    libgtest-dev
    xvfb xauth xdotool
    python3 python3-numpy
  )
fi
packages+=("$@")

missing=()
for package in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$package")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  exit 0
fi

run_as_root=()
if [ "$(id -u)" -ne 0 ]; then
  if command -v sudo >/dev/null 2>&1; then
    run_as_root=(sudo)
  else
    echo "install-dependencies: need root (or sudo) to install: ${missing[*]}" >&2
    exit 1
  fi
fi

echo "install-dependencies: installing ${missing[*]}" >&2
export DEBIAN_FRONTEND=noninteractive
"${run_as_root[@]}" apt-get update -qq
"${run_as_root[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
