#!/bin/sh
# Runs a window test (its GoogleTest executable and arguments) under a virtual X server of
# its own. Without Xvfb (Debian package xvfb), or without xdotool when `--needs-xdotool`
# comes first, the test cannot run here: say why and exit 77, which ctest reports as skipped.
#
# The server is started with -displayfd, which picks a free display number and reports it:
# tests running at once each get their own (xvfb-run --auto-servernum can pick the same one
# for two servers started together).
if [ "$1" = "--needs-xdotool" ]; then
    shift
    if ! command -v xdotool >/dev/null 2>&1; then
        echo "SKIPPED: xdotool is not installed (Debian package xdotool), so no input can be sent"
        exit 77
    fi
fi
if ! command -v Xvfb >/dev/null 2>&1; then
    echo "SKIPPED: Xvfb is not installed (Debian package xvfb), so no window can be opened"
    exit 77
fi
display_file=$(mktemp)
Xvfb -displayfd 9 -screen 0 320x240x24 -nolisten tcp 9>"$display_file" 2>/dev/null &
server=$!
trap 'kill $server 2>/dev/null; rm -f "$display_file"' EXIT
waited=0
while [ ! -s "$display_file" ]; do
    if ! kill -0 $server 2>/dev/null || [ $waited -ge 100 ]; then
        echo "Xvfb did not start"
        exit 1
    fi
    sleep 0.1
    waited=$((waited + 1))
done
DISPLAY=":$(head -n 1 "$display_file")"
export DISPLAY
"$@"
