#!/usr/bin/env bash
# Renders the image-regression references (tests/references/NAME.exr) from the regression
# list in tests/support/RegressionCases.cpp: each at its reference sample count with the
# reference seed. An existing reference is never overwritten without --force.
#
#   tools/update-references.sh [--force] [--build-dir DIR] [NAME ...]
#
#   NAME ...          the cases to render (default: every case; see --list)
#   --force           overwrite references that exist
#   --build-dir DIR   where to build the reference tool (default: build/)
#   --list            print the case names and exit
#
# Without --force, missing references are made and existing ones kept; naming an existing
# reference without --force is an error (exit status 1) after the others are done.
# Look at what you made before committing it: the tests trust it (tests/README.md).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="$root/build"
force=0
list=0
names=()
while [ $# -gt 0 ]; do
    case "$1" in
        --force) force=1 ;;
        --list) list=1 ;;
        --build-dir)
            [ $# -ge 2 ] || { echo "update-references: --build-dir needs a folder" >&2; exit 2; }
            build="$2"
            shift ;;
        -h|--help) sed -n '2,16p' "${BASH_SOURCE[0]}" | sed 's/^# \{0,1\}//'; exit 0 ;;
        -*) echo "update-references: unknown option '$1' (see --help)" >&2; exit 2 ;;
        *) names+=("$1") ;;
    esac
    shift
done

if [ ! -f "$build/CMakeCache.txt" ]; then
    cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
fi
cmake --build "$build" --target make_reference >/dev/null
tool="$build/tests/make_reference"

mapfile -t known < <("$tool" --list)
if [ "$list" -eq 1 ]; then
    printf '%s\n' "${known[@]}"
    exit 0
fi
explicit=1
if [ ${#names[@]} -eq 0 ]; then
    names=("${known[@]}")
    explicit=0
fi
# Whether $1 is one of the known case names. A loop, not `printf | grep -q`: grep -q exits at
# the first match, and printf, still writing, then dies of SIGPIPE, which pipefail reports as
# a failure of the whole check.
is_known_case() {
    local case_name
    for case_name in "${known[@]}"; do
        [ "$case_name" = "$1" ] && return 0
    done
    return 1
}
for name in "${names[@]}"; do
    if ! is_known_case "$name"; then
        echo "update-references: no regression case named '$name' (see --list)" >&2
        exit 2
    fi
done

references="$root/tests/references"
mkdir -p "$references"
refused=()
for name in "${names[@]}"; do
    target="$references/$name.exr"
    if [ -e "$target" ] && [ "$force" -eq 0 ]; then
        [ "$explicit" -eq 1 ] && echo "$name: kept $target (it exists; --force overwrites it)"
        refused+=("$name")
        continue
    fi
    # Rendered beside the target and renamed: a reference is whole or absent.
    partial="$references/.$name.partial.exr"
    if ! "$tool" "$name" "$partial"; then
        rm -f "$partial"
        echo "update-references: rendering $name failed" >&2
        exit 1
    fi
    mv -f "$partial" "$target"
done

if [ "$explicit" -eq 0 ] && [ ${#refused[@]} -gt 0 ]; then
    echo "update-references: kept ${#refused[@]} existing references (--force overwrites them)"
fi
if [ "$explicit" -eq 1 ] && [ ${#refused[@]} -gt 0 ]; then
    echo "update-references: refused to overwrite ${refused[*]} without --force" >&2
    exit 1
fi
