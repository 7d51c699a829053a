#!/usr/bin/env bash
# Renders the README's screenshot of the window: a classic scene converging with the
# statistics panel showing, under a virtual X server, captured from the X server.
#   tools/window-screenshot.sh [SCENE [SECONDS [OUTPUT]]]
# Defaults: scenes/scene3.in, 20 seconds, docs/window.png. Needs a build (tools/build.sh).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
scene="${1:-$root/scenes/scene3.in}"
seconds="${2:-20}"
output="${3:-$root/docs/window.png}"
display_file=$(mktemp)
Xvfb -displayfd 9 -screen 0 800x600x24 -nolisten tcp -noreset 9>"$display_file" 2>/dev/null &
server=$!
trap 'kill $server 2>/dev/null; rm -f "$display_file"' EXIT
while [ ! -s "$display_file" ]; do sleep 0.1; done
export DISPLAY=":$(head -n 1 "$display_file")"
"$root/build/raytracer" "$scene" 640 480 &
program=$!
# The panel starts hidden: Tab shows it once the window is there.
until xdotool search --name '^raytracer' >/dev/null 2>&1; do sleep 0.2; done
xdotool search --name '^raytracer' key Tab
sleep "$seconds"
"$root/build/tests/window_capture" raytracer "$output"
# Only the press: the window closes on it, and a release sent after could fail (BadWindow).
xdotool search --name '^raytracer' keydown Escape
wait $program
echo "wrote $output"
