#!/bin/sh
# Runs the window test (its GoogleTest executable, $1) under a virtual X server. Without
# xvfb-run the test cannot run here: say why and exit 77, which ctest reports as skipped.
if ! command -v xvfb-run >/dev/null 2>&1; then
    echo "SKIPPED: xvfb-run is not installed (Debian package xvfb), so no window can be opened"
    exit 77
fi
exec xvfb-run --auto-servernum --server-args="-screen 0 320x240x24" "$@"
