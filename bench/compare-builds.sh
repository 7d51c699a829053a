#!/usr/bin/env bash
# Our own builds side by side on this machine in one run: each RAYTRACER renders each scene
# in turn (A B C A B C ...), ROUNDS rounds, and the table gives each build's median paths
# per second (from the program's own summary line: frames only, not start-up) and each
# build's ratio to the first. For "what did this change buy": build the commit before it in
# a worktree (git worktree add /tmp/before COMMIT; cmake there) and name both programs.
#
#   bench/compare-builds.sh [--rounds N] [--size W H] [--spp N] RAYTRACER... -- SCENE...
#
# Defaults: 3 rounds, 400x300, 16 spp (every build renders exactly the same samples count).
set -euo pipefail
rounds=3 width=400 height=300 spp=16
programs=() scenes=()
while [ $# -gt 0 ]; do
  case "$1" in
    --rounds) rounds="$2"; shift 2 ;;
    --size) width="$2"; height="$3"; shift 3 ;;
    --spp) spp="$2"; shift 2 ;;
    --) shift; scenes=("$@"); break ;;
    *) programs+=("$(readlink -f "$1")"); shift ;;
  esac
done
[ "${#programs[@]}" -ge 1 ] && [ "${#scenes[@]}" -ge 1 ] ||
  { echo "usage: compare-builds.sh [--rounds N] [--size W H] [--spp N] RAYTRACER... -- SCENE..." >&2; exit 2; }
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
declare -A rates
for round in $(seq "$rounds"); do
  for scene in "${scenes[@]}"; do
    for i in "${!programs[@]}"; do
      line="$(env -u DISPLAY "${programs[$i]}" "$scene" "$width" "$height" --spp "$spp" \
              --headless --output "$work/image.exr" 2>&1 | grep -o '[0-9.]* Mpaths/s' | head -1)"
      rates[$i,$scene]="${rates[$i,$scene]:-} ${line%% *}"
      echo "round $round $(basename "$scene"): build $((i + 1)) ${line}" >&2
    done
  done
done
median() { tr ' ' '\n' | grep . | sort -g | awk '{a[NR]=$1} END{print (NR%2)?a[(NR+1)/2]:(a[NR/2]+a[NR/2+1])/2}'; }
echo "machine: $(lscpu | sed -n 's/^Model name: *//p' | head -1), $(nproc) cores; $(date -u '+%F %H:%M UTC')"
for i in "${!programs[@]}"; do echo "build $((i + 1)): ${programs[$i]}"; done
echo
header="| scene |"; rule="|---|"
for i in "${!programs[@]}"; do header+=" build $((i + 1)) Mpaths/s |"; rule+="---|"; done
for i in "${!programs[@]}"; do [ "$i" -gt 0 ] && { header+=" $((i + 1)) / 1 |"; rule+="---|"; }; done
echo "$header"; echo "$rule"
for scene in "${scenes[@]}"; do
  row="| $(basename "$scene" .in) |"; first=""
  for i in "${!programs[@]}"; do
    m="$(echo ${rates[$i,$scene]} | median)"; [ -z "$first" ] && first="$m"
    row+=" $m |"
  done
  for i in "${!programs[@]}"; do
    [ "$i" -gt 0 ] || continue
    m="$(echo ${rates[$i,$scene]} | median)"
    row+=" $(printf '%.2fx' "$(echo "$m / $first" | bc -l)") |"
  done
  echo "$row"
done
echo "($width x $height, $spp spp, median of $rounds alternating rounds)"
