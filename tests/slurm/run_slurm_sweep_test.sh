#!/bin/bash
# The sweep on a real Slurm (docs/sweeps.md, "On a cluster"): starts munge and a one-node
# Slurm (slurmctld + slurmd on localhost, 2 CPUs, a slurm.conf of its own in WORK), submits
# SPEC with scripts/slurm/submit as a 4-task job array plus the dependent merge job, waits,
# and demands that the merged results equal, byte for byte, those of one unsharded run.
# Stops every daemon it started (by pid), whatever happens.
#
#   run_slurm_sweep_test.sh SCATTERLAB SPEC WORK
#
# Needs root (the daemons run as root, as on a CI machine) and Debian's slurm-wlm and munge
# (scripts/setup installs them).
set -euo pipefail
scatterlab=$(realpath "$1") spec=$(realpath "$2") work=$3
here=$(cd "$(dirname "$0")" && pwd)
submit="$here/../../scripts/slurm/submit"

fail() { echo "slurm sweep test: FAIL: $*" >&2; exit 1; }
[ "$(id -u)" -eq 0 ] || fail "must run as root to start munged, slurmctld and slurmd"
for tool in munged munge unmunge slurmctld slurmd sbatch sinfo; do
  command -v "$tool" >/dev/null || fail "$tool is missing: run scripts/setup (Debian's slurm-wlm and munge)"
done

rm -rf "$work"
mkdir -p "$work/state" "$work/spool"
started=()
stop_daemons() {
  for pid in "${started[@]}"; do kill "$pid" 2>/dev/null || true; done
  for pid in "${started[@]}"; do
    for _ in $(seq 50); do kill -0 "$pid" 2>/dev/null || break; sleep 0.1; done
    kill -9 "$pid" 2>/dev/null || true
  done
}
trap stop_daemons EXIT

# munge: a daemon of our own on a socket in WORK, with a fresh key (munged runs as root only
# with --force; its files are ours).
dd if=/dev/urandom of="$work/munge.key" bs=1024 count=1 status=none
chmod 400 "$work/munge.key"
munge_socket="$work/munge.socket"
munged --force --key-file="$work/munge.key" --socket="$munge_socket" --pid-file="$work/munged.pid" \
  --log-file="$work/munged.log" --seed-file="$work/munged.seed" --foreground 2>>"$work/munged.stderr" &
started+=($!)
for _ in $(seq 50); do [ -S "$munge_socket" ] && break; sleep 0.1; done
munge -S "$munge_socket" -n | unmunge -S "$munge_socket" >/dev/null || fail "munge does not work (see $work/munged.log)"

# A one-node cluster: no cgroups, no accounting, ports of its own.
host=$(hostname)
port=$((20000 + RANDOM % 20000))
export SLURM_CONF="$work/slurm.conf"
cat >"$SLURM_CONF" <<CONF
ClusterName=scatterlab-test
SlurmctldHost=$host
SlurmctldPort=$port
SlurmdPort=$((port + 1))
AuthType=auth/munge
AuthInfo=socket=$munge_socket
CredType=cred/munge
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SlurmUser=root
SlurmdUser=root
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
ReturnToService=2
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
MpiDefault=none
StateSaveLocation=$work/state
SlurmdSpoolDir=$work/spool
SlurmctldPidFile=$work/slurmctld.pid
SlurmdPidFile=$work/slurmd.pid
SlurmctldLogFile=$work/slurmctld.log
SlurmdLogFile=$work/slurmd.log
NodeName=$host CPUs=2 State=UNKNOWN
PartitionName=debug Nodes=$host Default=YES MaxTime=INFINITE State=UP
CONF
slurmctld -D -i -f "$SLURM_CONF" 2>>"$work/slurmctld.stderr" &
started+=($!)
slurmd -D -f "$SLURM_CONF" -N "$host" 2>>"$work/slurmd.stderr" &
started+=($!)
for _ in $(seq 120); do
  sinfo -h -o '%t' 2>/dev/null | grep -qx idle && break
  sleep 0.5
done
sinfo -h -o '%t' | grep -qx idle || fail "the node did not become idle (see $work/slurmctld.log, $work/slurmd.log)"

# The reference: one machine, one shard.
"$scatterlab" sweep "$spec" --out "$work/unsharded" 2>"$work/unsharded.log"
"$scatterlab" merge "$work/unsharded" --out "$work/merged-unsharded" 2>>"$work/unsharded.log"

# The cluster: a 4-task array and the merge job; --wait returns the merge job's exit code.
timeout 900 "$submit" "$spec" "$work/slurm" "$work/merged-slurm" --shards 4 --scatterlab "$scatterlab" --wait \
  || fail "the Slurm sweep or its merge failed (logs in $work/slurm.logs)"
for k in 1 2 3 4; do
  grep -q "shard $k/4" "$work/slurm.logs/shard-$k.log" || fail "array task $k did not run shard $k/4"
done
for file in results.json results.csv summary.html; do
  cmp "$work/merged-unsharded/$file" "$work/merged-slurm/$file" || fail "$file differs between 1 and 4 shards"
done
tasks=$(grep -c '"index"' "$work/merged-slurm/timings.json")
echo "slurm sweep test: 4-shard Slurm array and unsharded run merge to identical results ($tasks tasks)"
