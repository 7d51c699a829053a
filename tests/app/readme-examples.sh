#!/usr/bin/env bash
# Runs every command of README.md's "Using it" examples as written, in order, in a folder of
# its own (where `scenes` is the project's), with `raytracer` the build's program: each must
# exit 0, and the files they name must be there at the end. The window's command (no
# SECONDS, --spp or --target-error) runs under the display run-under-xvfb.sh provides, and is
# closed with Escape once its window shows.
#   readme-examples.sh SOURCE_DIR BUILD_DIR
set -euo pipefail
source_dir="$1"
build_dir="$2"
folder=$(mktemp -d)
trap 'rm -rf "$folder"' EXIT
ln -s "$source_dir/scenes" "$folder/scenes"
cd "$folder"
raytracer() { "$build_dir/raytracer" "$@"; }

# The first fenced block after the "## Using it" heading.
mapfile -t commands < <(awk '/^## Using it/ { section = 1; next }
                             section && /^```/ { if (inside) exit; inside = 1; next }
                             inside && NF { print }' "$source_dir/README.md")
[ "${#commands[@]}" -gt 0 ] || { echo "no commands found under README.md's \"Using it\""; exit 1; }

failures=0
for line in "${commands[@]}"; do
    command="${line%%#*}"
    command="${command%"${command##*[![:space:]]}"}"
    read -r -a words <<<"$command"
    if [ "${words[0]}" != raytracer ]; then
        echo "FAILED: not a raytracer command: $line"
        failures=$((failures + 1))
        continue
    fi
    # A render with no end (no SECONDS, --spp or --target-error) is a window until closed.
    numbers=0
    for word in "${words[@]:2}"; do
        [[ "$word" =~ ^[0-9.]+$ ]] || break
        numbers=$((numbers + 1))
    done
    window=0
    if [ "${words[1]}" != merge ] && [ "${words[1]}" != info ] && [ "$numbers" -lt 3 ] &&
        [[ "$command" != *--spp* ]] && [[ "$command" != *--target-error* ]]; then
        window=1
    fi
    echo "== $command"
    start=$(date +%s)
    status=0
    if [ "$window" = 1 ]; then
        eval "$command" &
        program=$!
        shown=""
        for _ in $(seq 1 100); do
            shown=$(xdotool search --name '^raytracer' 2>/dev/null | head -n 1) || true
            [ -n "$shown" ] && break
            sleep 0.2
        done
        if [ -z "$shown" ]; then
            echo "FAILED: no window within 20 s: $line"
            kill "$program" 2>/dev/null || true
            failures=$((failures + 1))
            wait "$program" || true
            continue
        fi
        sleep 1
        # Only the press to the window: it closes on it (a release could meet it gone).
        xdotool keydown --window "$shown" Escape
        wait "$program" || status=$?
        # Released afterwards, or the held key would repeat into the next window.
        xdotool keyup Escape || true
    else
        eval "$command" || status=$?
    fi
    echo "   exit $status after $(($(date +%s) - start)) s"
    if [ "$status" != 0 ]; then
        echo "FAILED (exit $status): $line"
        failures=$((failures + 1))
    fi
done

# The files the examples name.
for file in scene3.ppm a.exr b.exr all.exr all.png; do
    if [ ! -s "$file" ]; then
        echo "FAILED: the examples should have written $file"
        failures=$((failures + 1))
    fi
done
echo "$failures failures among ${#commands[@]} commands and the 5 files they write"
[ "$failures" = 0 ]
