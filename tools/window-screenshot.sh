#!/usr/bin/env bash
# Renders the README's screenshot of the window: a classic scene converging with the
# statistics panel showing, under a virtual X server, captured from the X server.
#   tools/window-screenshot.sh [SCENE [SECONDS [OUTPUT [ORBIT_PIXELS]]]]
# Defaults: scenes/scene3.in, 20 seconds, docs/window.png. Needs a build (tools/build.sh).
# ORBIT_PIXELS: first a left drag that far to the right (negative: to the left) across the
# window's middle (240, half the 480-pixel height, is a quarter turn), with the panel hidden, then the panel and the
# wait. $RAYTRACER names another program to run (an older build, to compare); PANEL=0 leaves
# the statistics panel hidden.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
scene="${1:-$root/scenes/scene3.in}"
seconds="${2:-20}"
output="${3:-$root/docs/window.png}"
orbit="${4:-0}"
program_file="${RAYTRACER:-$root/build/raytracer}"
display_file=$(mktemp)
Xvfb -displayfd 9 -screen 0 800x600x24 -nolisten tcp -noreset 9>"$display_file" 2>/dev/null &
server=$!
trap 'kill $server 2>/dev/null; rm -f "$display_file"' EXIT
while [ ! -s "$display_file" ]; do sleep 0.1; done
export DISPLAY=":$(head -n 1 "$display_file")"
"$program_file" "$scene" 640 480 &
program=$!
# The panel starts hidden: Tab shows it once the window is there.
until xdotool search --name '^raytracer' >/dev/null 2>&1; do sleep 0.2; done
window=$(xdotool search --name '^raytracer' | head -n 1)
if [ "$orbit" != 0 ]; then
  sleep 2
  # From left of the centre for a drag to the right, from right of it for one to the left.
  start=$((orbit > 0 ? 200 : 440))
  xdotool mousemove --window "$window" "$start" 240 mousedown 1
  for step in 1 2 3 4 5 6 7 8; do
    sleep 0.05
    xdotool mousemove --window "$window" $((start + orbit * step / 8)) 240
  done
  xdotool mouseup 1
fi
[ "${PANEL:-1}" = 0 ] || xdotool key --window "$window" Tab
sleep "$seconds"
"$root/build/tests/window_capture" raytracer "$output"
# Only the press: the window closes on it, and a release sent after could fail (BadWindow).
xdotool search --name '^raytracer' keydown Escape
wait $program
echo "wrote $output"
