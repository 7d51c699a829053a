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
# A server can report its number and still not answer (seen once in a CI run: "Failed to
# open display :0" at once): the test starts only when the display takes a connection, and
# a server that does not within 10 s is replaced, three times at most.
#
# -noreset: by default an X server resets itself each time its last client disconnects, and
# refuses connections while it does. The check below, the test's own reads of the window and
# the program each connect and disconnect, so the program could meet a resetting server
# ("X11: Failed to open display", CI, stop 24). Four processes connecting in a loop to a
# server without it failed 24 of 600 connections; with it, 0 of 600.
display_file=$(mktemp)
server=""
trap 'kill $server 2>/dev/null; rm -f "$display_file"' EXIT
answers() {
    [ -S "/tmp/.X11-unix/X$1" ] || return 1
    if command -v xdotool >/dev/null 2>&1; then
        DISPLAY=":$1" xdotool getdisplaygeometry >/dev/null 2>&1 || return 1
    fi
    return 0
}
attempt=0
while :; do
    attempt=$((attempt + 1))
    : >"$display_file"
    Xvfb -displayfd 9 -screen 0 320x240x24 -nolisten tcp -noreset 9>"$display_file" 2>/dev/null &
    server=$!
    waited=0
    number=""
    while [ $waited -lt 100 ] && kill -0 $server 2>/dev/null; do
        number=$(head -n 1 "$display_file")
        if [ -n "$number" ] && answers "$number"; then
            break
        fi
        number=""
        sleep 0.1
        waited=$((waited + 1))
    done
    [ -n "$number" ] && break
    kill $server 2>/dev/null
    if [ $attempt -ge 3 ]; then
        echo "Xvfb did not start (three attempts)"
        exit 1
    fi
done
DISPLAY=":$number"
export DISPLAY
"$@"
