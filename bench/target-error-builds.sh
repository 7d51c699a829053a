#!/usr/bin/env bash
# Our own builds side by side on renders to a target error (--target-error, adaptive
# sampling): each RAYTRACER renders each scene to TARGET with seeds 1 and 2, the builds in
# turn (A B C A B C ...). The table gives, per build, the mean time and samples per pixel the
# two renders took, the error they stated (the estimate, two standard deviations up, over
# the target: how close under it they stopped) and the error measured from the two seeds'
# difference (E[(x1 - x2)^2] = 2 E^2 mean^2: no reference and no estimate involved), which
# says whether the stated error was true. For "what did this change buy": build the commit
# before it in a worktree (git worktree add /tmp/before COMMIT; cmake there) and name both.
#
#   bench/target-error-builds.sh [--target E] [--size W H] [--limit S] RAYTRACER... -- SCENE...
#
# Defaults: target 0.05, 48x36, 60 s per render. A benchmark: run it alone on the machine.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
target=0.05 width=48 height=36 limit=60
programs=() scenes=()
while [ $# -gt 0 ]; do
  case "$1" in
    --target) target="$2"; shift 2 ;;
    --size) width="$2"; height="$3"; shift 3 ;;
    --limit) limit="$2"; shift 2 ;;
    --) shift; scenes=("$@"); break ;;
    *) programs+=("$(readlink -f "$1")"); shift ;;
  esac
done
[ "${#programs[@]}" -ge 1 ] && [ "${#scenes[@]}" -ge 1 ] ||
  { echo "usage: target-error-builds.sh [--target E] [--size W H] [--limit S] RAYTRACER... -- SCENE..." >&2; exit 2; }
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT

echo "machine: $(lscpu | sed -n 's/^Model name: *//p' | head -1), $(nproc) cores; date: $(date -u '+%F %H:%M UTC')"
echo "target $target, ${width}x${height}, adaptive sampling, seeds 1 and 2, limit $limit s per render"
for i in "${!programs[@]}"; do
  echo "build $((i + 1)): ${programs[$i]} ($(git -C "$(dirname "${programs[$i]}")" rev-parse --short HEAD 2>/dev/null || echo '?'))"
done
echo
for scene in "${scenes[@]}"; do
  name="$(basename "$scene" .in)"
  for seed in 1 2; do
    for i in "${!programs[@]}"; do
      (cd "$(dirname "$scene")" &&
        "${programs[$i]}" "$(basename "$scene")" "$width" "$height" "$limit" --headless \
          --target-error "$target" --seed "$seed" --output "$work/$name-$i-$seed.pfm") \
        > "$work/$name-$i-$seed.log" 2>&1 || [ $? -eq 3 ]  # 3: the limit came first
    done
  done
done

ROOT="$root" /usr/bin/python3 - "$work" "$target" "${#programs[@]}" "${scenes[@]}" <<'EOF'
import os, re, sys
sys.path.insert(0, os.path.join(os.environ.get("ROOT", "."), "bench"))
from target_error import SUMMARY, measured_error

work, target, builds, scenes = sys.argv[1], float(sys.argv[2]), int(sys.argv[3]), sys.argv[4:]
header = ["scene"]
for build in range(1, builds + 1):
    header += [f"{build}: s", f"{build}: spp", f"{build}: stated / target",
               f"{build}: measured"]
print("| " + " | ".join(header) + " |")
print("|" + "---|" * len(header))
for scene in scenes:
    name = os.path.basename(scene)[:-3]
    row = [name]
    for build in range(builds):
        seconds, spp, stated = [], [], []
        for seed in (1, 2):
            match = SUMMARY.search(open(f"{work}/{name}-{build}-{seed}.log").read())
            if not match:
                sys.exit(f"{name}, build {build + 1}, seed {seed}: no summary line")
            spp.append(float(match.group(1) or match.group(4)))
            seconds.append(float(match.group(5)))
            stated.append((float(match.group(6)) + 2 * float(match.group(7))) / 100 / target)
        measured = measured_error(f"{work}/{name}-{build}-1.pfm", f"{work}/{name}-{build}-2.pfm")
        row += [f"{sum(seconds) / 2:.2f}", f"{sum(spp) / 2:.0f}", f"{sum(stated) / 2:.2f}",
                f"{100 * measured:.2f} %"]
    print("| " + " | ".join(row) + " |")
EOF
