#!/bin/sh
# ctest RenderShardsOnGpusGivesEachRunningShardAGpuOfItsOwn: tools/render-shards.sh --gpus 2
# renders four shards two at a time, each with --gl-device 0 or 1, and never two at once on
# one GPU. The machine running the test need have no GPU: the program is run through a
# wrapper that records the device each shard was given and when it ran, then renders it
# through EGL on whatever EGL offers. Exit 77 (skipped) where GNU parallel is not installed.
#   render-shards-gpus-test.sh RAYTRACER
set -eu
raytracer=$1
root="$(cd "$(dirname "$0")/../.." && pwd)"
if ! parallel --version 2>/dev/null | grep -q "GNU parallel"; then
    echo "GNU parallel is not installed (Debian package parallel): skipped"
    exit 77
fi
folder=$(mktemp -d)
trap 'rm -rf "$folder"' EXIT
cd "$folder"
cat > wrapper.sh <<WRAPPER
#!/bin/sh
# raytracer ... --gl-device N ...: logs "start end N", renders with --gl egl instead.
device="" first=1
for argument in "\$@"; do
    if [ "\$first" = 1 ]; then set --; first=0; fi
    if [ "\$device" = next ]; then device=\$argument; continue; fi
    if [ "\$argument" = --gl-device ]; then device=next; continue; fi
    set -- "\$@" "\$argument"
done
[ -z "\$device" ] && exec "$raytracer" "\$@"
start=\$(date +%s.%N)
"$raytracer" "\$@" --gl egl
status=\$?
echo "\$start \$(date +%s.%N) \$device" >> "$folder/devices.log"
exit \$status
WRAPPER
chmod +x wrapper.sh
"$root/tools/render-shards.sh" "$root/scenes/scene1.in" 32 24 8 4 --gpus 2 \
    --raytracer ./wrapper.sh --output merged.exr
fail() { echo "FAILED: $1"; cat devices.log; exit 1; }
[ "$(wc -l < devices.log)" = 4 ] || fail "four shards, each given a GPU"
awk '$3 != 0 && $3 != 1 { exit 1 }' devices.log || fail "every device is GPU 0 or 1"
# Two shards whose runs overlap in time must hold different GPUs.
awk '{ s[NR] = $1; e[NR] = $2; d[NR] = $3 }
     END { for (i = 1; i <= NR; ++i) for (j = i + 1; j <= NR; ++j)
               if (s[i] < e[j] && s[j] < e[i] && d[i] == d[j]) exit 1 }' devices.log ||
    fail "two shards ran at once on one GPU"
"$raytracer" info merged.exr | grep -Eq '^samples +8 per pixel; every pixel holds 8 ' ||
    fail "the merged file should hold 8 samples in every pixel"
echo "PASS"
