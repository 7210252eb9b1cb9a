#!/usr/bin/env bash
# A sweep through a real Slurm: starts munged and a single-node Slurm (slurmctld, slurmd) on
# localhost from Debian's packages, in a scratch folder, submits a small analytic-plant sweep
# with slurm/submit_sweep.sh (its shards as a job array, the merge depending on them), waits,
# and compares the merged directory byte for byte with a single-process run. It stops the
# daemons it started, by their pid files, however it ends.
#   test_slurm_sweep.sh BUILD_DIR     (needs root: munged runs as the munge user)
set -euo pipefail
build="$(cd "$1" && pwd)"
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cbbg="$build/apps/cbbg"
if [[ "$(id -u)" -ne 0 ]]; then
  echo "test_slurm_sweep: needs root to run munged as the munge user; skipped"
  exit 77
fi
for tool in munged slurmctld slurmd sbatch squeue sinfo; do
  command -v "$tool" >/dev/null || { echo "test_slurm_sweep: $tool is missing (scripts/setup.sh installs it)" >&2; exit 1; }
done

scratch="$(mktemp -d /tmp/cbbg-slurm.XXXXXX)"
chmod 0755 "$scratch"
stop() {
  for pid_file in "$scratch/slurmd.pid" "$scratch/slurmctld.pid" "$scratch/munge/munged.pid"; do
    if [[ -s "$pid_file" ]]; then
      kill "$(cat "$pid_file")" 2>/dev/null || true
    fi
  done
  sleep 1
  for pid_file in "$scratch/slurmd.pid" "$scratch/slurmctld.pid" "$scratch/munge/munged.pid"; do
    if [[ -s "$pid_file" ]] && kill -0 "$(cat "$pid_file")" 2>/dev/null; then
      kill -9 "$(cat "$pid_file")" 2>/dev/null || true
    fi
  done
  rm -rf "$scratch"
}
trap stop EXIT

# munged, as the munge user, with its own key, socket and pid file.
install -d -o munge -g munge -m 0755 "$scratch/munge"  # its socket needs o+x
dd if=/dev/urandom of="$scratch/munge/munge.key" bs=1024 count=1 status=none
chown munge:munge "$scratch/munge/munge.key"
chmod 0400 "$scratch/munge/munge.key"
runuser -u munge -- munged --key-file="$scratch/munge/munge.key" \
  --socket="$scratch/munge/munge.socket" --pid-file="$scratch/munge/munged.pid" \
  --log-file="$scratch/munge/munged.log" --seed-file="$scratch/munge/munged.seed"

# A single-node cluster: no accounting, no cgroups, no systemd.
host="$(hostname -s)"
port=$((20000 + RANDOM % 20000))
mkdir -p "$scratch/state" "$scratch/spool"
cat > "$scratch/slurm.conf" <<CONF
ClusterName=cbbgtest
SlurmctldHost=$host(127.0.0.1)
SlurmctldPort=$port
SlurmdPort=$((port + 1))
SlurmUser=root
AuthType=auth/munge
AuthInfo=socket=$scratch/munge/munge.socket
StateSaveLocation=$scratch/state
SlurmdSpoolDir=$scratch/spool
SlurmctldPidFile=$scratch/slurmctld.pid
SlurmdPidFile=$scratch/slurmd.pid
SlurmctldLogFile=$scratch/slurmctld.log
SlurmdLogFile=$scratch/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
SchedulerType=sched/backfill
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
MpiDefault=none
ReturnToService=2
NodeName=$host NodeAddr=127.0.0.1 CPUs=$(nproc) State=UNKNOWN
PartitionName=cbbg Nodes=$host Default=YES MaxTime=INFINITE State=UP
CONF
export SLURM_CONF="$scratch/slurm.conf"
slurmctld -f "$SLURM_CONF"
slurmd -f "$SLURM_CONF"
for _ in $(seq 60); do
  if sinfo -h -o %t 2>/dev/null | grep -qx idle; then break; fi
  sleep 1
done
sinfo -h -o %t | grep -qx idle || { echo "test_slurm_sweep: the node never became idle" >&2; cat "$scratch"/slurm*.log >&2; exit 1; }

sweep=(--set plant.kind=analytic --seeds 3 --no-figures --grid actor.alpha=0.1,0.2
       --grid critic.beta=0.05,0.1)
"$cbbg" run "${sweep[@]}" --out "$scratch/single" >/dev/null 2>&1
cd "$scratch"
CBBG="$cbbg" "$root/scripts/slurm/submit_sweep.sh" 3 "$scratch/slurm-out" "${sweep[@]}"
for _ in $(seq 300); do
  if [[ -z "$(squeue -h -o %i)" ]]; then break; fi
  sleep 1
done
if ! diff -r "$scratch/single" "$scratch/slurm-out"; then
  echo "test_slurm_sweep: the Slurm sweep differs from the single-process run" >&2
  cat "$scratch"/cbbg-*.out >&2 || true
  exit 1
fi
echo "test_slurm_sweep: a 3-shard job array and its merge gave the bytes of a single-process run"
