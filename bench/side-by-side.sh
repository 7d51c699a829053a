#!/usr/bin/env bash
# Ours against the original program (../shared/peers/frag-pathtracer, a timing peer: its
# code is never copied), side by side on this machine in one run: the original's seven
# scene files at 400x300, read unchanged by both programs, the two programs alternating,
# median of ROUNDS rounds. Prints the machine, the date and both programs' versions, then
# the peer's Markdown table (docs/PERFORMANCE.md quotes it).
#
#   bench/side-by-side.sh [RAYTRACER=build/raytracer] [ROUNDS=3] [W=400 H=300]
#
# PEER names the peer's folder (default: ../shared/peers/frag-pathtracer beside the
# repository). Run it with nothing else on the machine: other work slows both programs, not
# always equally.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
raytracer="$(readlink -f "${1:-$root/build/raytracer}")"
rounds="${2:-3}"
width="${3:-400}"
height="${4:-300}"
peer="${PEER:-$root/../shared/peers/frag-pathtracer}"
[ -x "$peer/compare.sh" ] || { echo "side-by-side.sh: no peer at $peer (set PEER)" >&2; exit 2; }
[ -x "$raytracer" ] || { echo "side-by-side.sh: no program at $raytracer (tools/build.sh)" >&2; exit 2; }

commit="$(git -C "$root" rev-parse --short HEAD 2>/dev/null || echo unknown)"
dirty="$(git -C "$root" status --porcelain --untracked-files=no 2>/dev/null | head -c1)"
echo "machine: $(lscpu | sed -n 's/^Model name: *//p' | head -1), $(nproc) cores," \
     "$(awk '/MemTotal/ {printf "%.0f GiB", $2 / 1048576}' /proc/meminfo)," \
     "$(uname -r); OpenGL: Mesa $(dpkg-query -W -f '${Version}' libosmesa6 2>/dev/null ||
        echo '?') llvmpipe"
echo "date: $(date -u '+%F %H:%M UTC'); load before: $(cut -d' ' -f1-3 /proc/loadavg)"
echo "ours: $raytracer (commit $commit${dirty:+, with uncommitted changes})"
echo "peer: $peer"
echo
# The peer's compare.sh reads our Mpaths/s from the summary line of a run with --quiet, which
# prints nothing on success now (docs/USAGE.md): it runs a wrapper that drops that option.
shim="$(mktemp -d)"
trap 'rm -rf "$shim"' EXIT
cat >"$shim/raytracer" <<WRAPPER
#!/usr/bin/env bash
arguments=()
for argument in "\$@"; do [ "\$argument" = --quiet ] || arguments+=("\$argument"); done
exec "$raytracer" "\${arguments[@]}"
WRAPPER
chmod +x "$shim/raytracer"
"$peer/compare.sh" "$shim/raytracer" "$rounds" "$width" "$height"
echo "load after: $(cut -d' ' -f1-3 /proc/loadavg)"
