#!/usr/bin/env bash
# Starts a real single-node Slurm cluster on this machine (munged, slurmctld and slurmd, on
# localhost, configured in a temporary folder), renders a scene as a job array with a merge
# job depending on it (tools/slurm/submit.sh), checks the merged image, and shuts the cluster
# down again, whatever happened (docs/SCALE_OUT.md shows a run).
#
#   tools/slurm/local-cluster-run.sh [SCENE WIDTH HEIGHT SPP SHARDS]
#
# Defaults: scenes/scene1.in 64 48 32 4. Needs Debian's slurm-wlm and munge (slurmctld,
# slurmd, sbatch, munged) and root (slurmd starts the jobs). Exit status: 0 the merged image
# is right, 1 it is not or a step failed (the daemons' logs are printed), 77 Slurm or munge
# is not installed here (said on standard error). KEEP=1 keeps the temporary folder.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
scene=${1:-$root/scenes/scene1.in} width=${2:-64} height=${3:-48} spp=${4:-32} shards=${5:-4}
raytracer=${RAYTRACER:-$root/build/raytracer}
say() { echo "slurm-run: $*"; }

missing=()
for tool in munged slurmctld slurmd sbatch squeue scontrol sinfo; do
    command -v "$tool" >/dev/null 2>&1 || missing+=("$tool")
done
if [ ${#missing[@]} -gt 0 ]; then
    echo "slurm-run: not installed: ${missing[*]} (Debian packages slurm-wlm munge;" \
         "tools/install-dependencies.sh installs them)" >&2
    exit 77
fi
[ "$(id -u)" -eq 0 ] || { echo "slurm-run: slurmd must run as root to start jobs" >&2; exit 1; }
[ -x "$raytracer" ] || { echo "slurm-run: no raytracer at $raytracer (build first)" >&2; exit 1; }

work=$(mktemp -d /tmp/raytracer-slurm.XXXXXX)
chmod 755 "$work"
mkdir -p "$work/munge" "$work/state" "$work/spool" "$work/log" "$work/render"
chmod 700 "$work/munge"
started=$(date +%s.%N)
elapsed() { awk -v a="$started" -v b="$(date +%s.%N)" 'BEGIN { printf "%.1f s", b - a }'; }

# Whatever happens from here on, the cluster goes down and nothing of it is left running.
shutdown() {
    status=$?
    set +e
    if [ -f "$work/slurm.conf" ]; then
        SLURM_CONF="$work/slurm.conf" scontrol shutdown >/dev/null 2>&1
        for pidfile in "$work/slurmd.pid" "$work/slurmctld.pid"; do
            [ -f "$pidfile" ] || continue
            pid=$(cat "$pidfile")
            for _ in $(seq 50); do kill -0 "$pid" 2>/dev/null || break; sleep 0.1; done
            kill -0 "$pid" 2>/dev/null && kill -TERM "$pid" 2>/dev/null
        done
    fi
    [ -S "$work/munge/munge.socket" ] && munged --stop --socket="$work/munge/munge.socket" >/dev/null 2>&1
    if [ "$status" -ne 0 ]; then
        for log in "$work"/log/*.log; do
            [ -f "$log" ] && { echo "--- $(basename "$log") (last 20 lines)"; tail -n 20 "$log"; }
        done
    fi
    say "cluster shut down after $(elapsed)"
    if [ "${KEEP:-0}" = 1 ]; then say "kept $work"; else rm -rf "$work"; fi
    exit "$status"
}
trap shutdown EXIT
trap 'exit 130' INT TERM

# Two free ports on the loopback for slurmctld and slurmd.
read -r ctld_port slurmd_port < <(python3 -c '
import socket
sockets = [socket.socket() for _ in range(2)]
for s in sockets: s.bind(("127.0.0.1", 0))
print(*(s.getsockname()[1] for s in sockets))')
node=$(hostname -s)

say "munged: a fresh key, its socket in $work/munge"
if command -v mungekey >/dev/null 2>&1; then
    mungekey --create --keyfile="$work/munge/munge.key" 2>/dev/null
else
    dd if=/dev/urandom of="$work/munge/munge.key" bs=1 count=1024 2>/dev/null
fi
chmod 600 "$work/munge/munge.key"
munged --force --key-file="$work/munge/munge.key" --socket="$work/munge/munge.socket" \
    --pid-file="$work/munge/munged.pid" --seed-file="$work/munge/munged.seed" \
    --log-file="$work/log/munged.log"

cat > "$work/slurm.conf" <<CONF
# A one-node cluster on localhost for tools/slurm/local-cluster-run.sh.
ClusterName=raytracer-local
SlurmctldHost=$node(127.0.0.1)
SlurmctldPort=$ctld_port
SlurmdPort=$slurmd_port
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket=$work/munge/munge.socket
SlurmUser=root
SlurmdUser=root
StateSaveLocation=$work/state
SlurmdSpoolDir=$work/spool
SlurmctldPidFile=$work/slurmctld.pid
SlurmdPidFile=$work/slurmd.pid
SlurmctldLogFile=$work/log/slurmctld.log
SlurmdLogFile=$work/log/slurmd.log
# No cgroups: processes are tracked through /proc, and nothing is confined.
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
MpiDefault=none
SwitchType=switch/none
SchedulerType=sched/backfill
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
ReturnToService=2
MinJobAge=600
NodeName=$node NodeAddr=127.0.0.1 CPUs=$(nproc) State=UNKNOWN
PartitionName=local Nodes=$node Default=YES MaxTime=INFINITE State=UP
CONF
export SLURM_CONF="$work/slurm.conf"

say "slurmctld and slurmd on $node (ports $ctld_port, $slurmd_port)"
slurmctld -c
slurmd
for _ in $(seq 100); do
    [ "$(sinfo -h -o %T 2>/dev/null)" = idle ] && break
    sleep 0.2
done
sinfo
[ "$(sinfo -h -o %T)" = idle ] || { say "the node did not come up"; exit 1; }
say "cluster up after $(elapsed)"

ids=$("$root/tools/slurm/submit.sh" "$scene" "$width" "$height" "$spp" "$shards" \
    "$work/render/merged.exr" --png "$work/render/merged.png" --raytracer "$raytracer")
read -r _ array _ merge <<< "$ids"
say "job array $array ($shards tasks) and merge job $merge submitted"
squeue

state=""
for _ in $(seq 1200); do  # four minutes at most
    state=$(scontrol show job "$merge" -o 2>/dev/null | grep -o 'JobState=[A-Z_]*' | cut -d= -f2)
    case "$state" in COMPLETED | FAILED | CANCELLED | TIMEOUT | NODE_FAIL | OUT_OF_MEMORY) break ;; esac
    sleep 0.2
done
say "merge job $merge: ${state:-unknown} after $(elapsed)"
for task in $(seq 0 $((shards - 1))); do
    line=$(scontrol show job "${array}_$task" -o 2>/dev/null | grep -o 'JobState=[A-Z_]* .*ExitCode=[0-9:]*' \
        | sed -E 's/ .*ExitCode=/, exit code /')
    say "  task $task: $line"
done
for log in "$work"/render/merged-shards/shard-*.log "$work/render/merged-merge.log"; do
    [ -f "$log" ] && { echo "--- $(basename "$log")"; cat "$log"; }
done
[ "$state" = COMPLETED ] || { say "FAILED: the merge job ended $state"; exit 1; }

# The merged image: every pixel holds SPP samples, of seeds 1 to SHARDS, and the picture.
info=$("$raytracer" info "$work/render/merged.exr")
grep -Eq "^samples +$spp per pixel; every pixel holds $spp " <<< "$info" ||
    { say "FAILED: the merged file does not hold $spp samples in every pixel"; exit 1; }
seeds=$([ "$shards" -eq 1 ] && echo 1 || { [ "$shards" -eq 2 ] && echo "1, 2" || echo "1-$shards"; })
grep -Eq "^seeds +$seeds\$" <<< "$info" ||
    { say "FAILED: the merged file's seeds are not $seeds"; exit 1; }
[ -s "$work/render/merged.png" ] || { say "FAILED: no merged picture"; exit 1; }
say "PASS: merged.exr holds $spp samples per pixel from seeds $seeds, and merged.png is written"
