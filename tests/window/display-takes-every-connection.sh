#!/bin/sh
# Run under run-under-xvfb.sh: four clients connect to its display and disconnect, 150 times
# each, at once, as the program, the test and xdotool do during a window test. Every
# connection must be taken; a server that resets when its last client leaves refuses some.
failures_file=$(mktemp)
trap 'rm -f "$failures_file"' EXIT
for client in 1 2 3 4; do
    (
        failed=0
        for attempt in $(seq 150); do
            xdotool getdisplaygeometry >/dev/null 2>&1 || failed=$((failed + 1))
        done
        echo "$failed" >>"$failures_file"
    ) &
done
wait
refused=$(awk '{ total += $1 } END { print total + 0 }' "$failures_file")
echo "connections refused by $DISPLAY: $refused of 600"
[ "$refused" -eq 0 ]
