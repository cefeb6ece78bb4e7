#!/usr/bin/env bash
# A one-node Slurm cluster for the tests (issue 16): munged, slurmctld and slurmd on this host with
# a generated minimal slurm.conf and the logs in DIR; the sockets, key, state and spool in a short
# private folder of their own (mktemp -d /tmp/tdslurm.XXXXXX, its path in DIR/private), because a
# Unix socket path holds at most 107 bytes and slurmd's step sockets
# (SPOOL/NODE_JOBID.STEPID) would not fit under a deep checkout (issue 41).
#
#   tests/slurm/cluster.sh start DIR   # starts it, waits until sinfo shows the node idle and a
#                                      # job step runs on it
#   tests/slurm/cluster.sh stop DIR    # cancels its jobs, stops the three daemons, removes the
#                                      # private folder
#
# Clients then use it with SLURM_CONF=DIR/slurm.conf. The node is this host with 2 CPUs, no cgroups
# (proctrack/linuxproc, task/none), select/cons_tres by CPU, no accounting database; finished jobs
# are recorded by jobcomp/filetxt in DIR/jobcomp.txt (start and end times: the tests read them).
# Its ports are derived from DIR, so two build folders' clusters do not collide. Any failure exits
# non-zero with the reason and the end of the daemon's log: the tests that need the cluster then
# fail, they are not skipped. Needs root (the daemons run as root), Debian's slurm-wlm and munge.
set -euo pipefail

usage() { echo "usage: $0 start|stop DIR" >&2; exit 2; }
[ $# -eq 2 ] || usage
action=$1
dir=$2
host=$(hostname -s)

fail() {
  echo "cluster.sh: $*" >&2
  for f in "$dir"/log/*.log; do
    [ -f "$f" ] && { echo "--- last lines of $f:" >&2; tail -n 15 "$f" >&2; }
  done
  # A start that failed leaves nothing running and no private folder behind.
  [ "$action" = start ] && stop_cluster
  exit 1
}

# Stops the daemon whose pid file is $1 (if it runs), waiting up to 20 s for it to go.
stop_daemon() {
  local pidfile=$1 pid
  [ -f "$pidfile" ] || return 0
  pid=$(cat "$pidfile" 2>/dev/null || true)
  if [ -n "$pid" ] && kill -0 "$pid" 2>/dev/null; then
    kill -TERM "$pid" 2>/dev/null || true
    for _ in $(seq 1 40); do kill -0 "$pid" 2>/dev/null || break; sleep 0.5; done
    kill -0 "$pid" 2>/dev/null && kill -KILL "$pid" 2>/dev/null || true
  fi
  rm -f "$pidfile"
}

# The private folder of the cluster in $dir (empty when there is none).
private_of() { [ -f "$dir/private" ] && cat "$dir/private" || true; }

stop_cluster() {
  [ -d "$dir" ] || return 0
  local private
  private=$(private_of)
  if [ -f "$dir/slurm.conf" ] && [ -f "$dir/slurmctld.pid" ]; then
    export SLURM_CONF="$dir/slurm.conf"
    # Cancel what is left (a failed test's jobs) and give their processes KillWait to end.
    jobs=$(timeout 10 squeue -h -o %A 2>/dev/null || true)
    if [ -n "$jobs" ]; then
      timeout 10 scancel $jobs 2>/dev/null || true
      for _ in $(seq 1 45); do
        [ -z "$(timeout 10 squeue -h -o %A 2>/dev/null || true)" ] && break
        sleep 1
      done
    fi
  fi
  stop_daemon "$dir/slurmd.pid"
  stop_daemon "$dir/slurmctld.pid"
  if [ -n "$private" ]; then
    stop_daemon "$private/munge/munged.pid"
    # Only a folder this script made: /tmp/tdslurm.XXXXXX.
    case "$private" in /tmp/tdslurm.*) rm -rf "$private" ;; esac
  fi
  rm -f "$dir/private"
}

case "$action" in
  stop)
    stop_cluster
    exit 0
    ;;
  start) ;;
  *) usage ;;
esac

for program in munged slurmctld slurmd sinfo; do
  command -v "$program" > /dev/null || fail "$program not found: install Debian's slurm-wlm and munge (scripts/install-deps)"
done
[ "$(id -u)" -eq 0 ] || fail "the daemons run as root here, and this is user $(id -un): run the Slurm tests as root"

mkdir -p "$dir"
dir=$(cd "$dir" && pwd)
stop_cluster  # a cluster left by an earlier run in the same folder
rm -rf "$dir/log" "$dir/jobcomp.txt"
mkdir -p "$dir/log"
private=$(mktemp -d /tmp/tdslurm.XXXXXX) || fail "could not create a private folder under /tmp"
echo "$private" > "$dir/private"
mkdir -p "$private/munge" "$private/state" "$private/spool"
chmod 700 "$private/munge"

# The longest Unix socket paths the daemons will make: munged's, and slurmd's step sockets
# SPOOL/NODE_JOBID.STEPID (job and step ids up to 10 digits each). sun_path holds 108 bytes
# with the closing NUL, so 107 characters at most.
socket="$private/munge/munge.socket"
for path in "$socket" "$private/spool/${host}_4294967295.4294967295"; do
  if [ ${#path} -gt 107 ]; then
    fail "the socket path '$path' would be ${#path} bytes, more than the 107 a Unix socket path holds (108 with its NUL): nothing started"
  fi
done

# munge: a key of our own, its socket in the private folder.
key="$private/munge/munge.key"
if command -v mungekey > /dev/null; then
  mungekey --create --keyfile="$key" || fail "mungekey could not create $key"
else
  dd if=/dev/urandom of="$key" bs=1024 count=1 status=none || fail "could not write $key"
fi
chmod 600 "$key"
munged --force --socket="$socket" --key-file="$key" --pid-file="$private/munge/munged.pid" \
  --log-file="$dir/log/munged.log" --seed-file="$private/munge/munged.seed" \
  || fail "munged did not start"
for _ in $(seq 1 20); do [ -S "$socket" ] && break; sleep 0.25; done
[ -S "$socket" ] || fail "munged started but its socket $socket did not appear"

# Ports from the folder's name: two build folders run two clusters.
hash=$(printf '%s' "$dir" | cksum | cut -d' ' -f1)
ctld_port=$((20000 + (hash % 10000) * 2))
slurmd_port=$((ctld_port + 1))

cat > "$dir/slurm.conf" <<CONF
# Generated by tests/slurm/cluster.sh: a one-node cluster for the tests.
ClusterName=trapdemtest
SlurmctldHost=$host(127.0.0.1)
SlurmctldPort=$ctld_port
SlurmdPort=$slurmd_port
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket=$socket
StateSaveLocation=$private/state
SlurmdSpoolDir=$private/spool
SlurmctldPidFile=$dir/slurmctld.pid
SlurmdPidFile=$dir/slurmd.pid
SlurmctldLogFile=$dir/log/slurmctld.log
SlurmdLogFile=$dir/log/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
SlurmdParameters=config_overrides
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
JobCompType=jobcomp/filetxt
JobCompLoc=$dir/jobcomp.txt
MpiDefault=none
ReturnToService=2
SchedulerType=sched/backfill
KillWait=30
MinJobAge=600
InactiveLimit=0
SlurmctldTimeout=30
SlurmdTimeout=60
NodeName=$host NodeAddr=127.0.0.1 CPUs=2 RealMemory=1000 State=UNKNOWN
PartitionName=debug Nodes=$host Default=YES MaxTime=INFINITE State=UP
CONF
export SLURM_CONF="$dir/slurm.conf"

slurmctld -i || fail "slurmctld did not start"
slurmd -N "$host" || fail "slurmd did not start"

# Ready when sinfo shows the node idle (60 s at most).
state=""
for _ in $(seq 1 120); do
  state=$(timeout 10 sinfo -h -n "$host" -o %t 2>/dev/null || true)
  [ "$state" = "idle" ] && break
  sleep 0.5
done
[ "$state" = "idle" ] || fail "the node did not become idle within 60 s (sinfo says '${state:-nothing}')"

# A job step must run: slurmd makes the step's socket in its spool, and a node that cannot launch
# jobs drains (the job is requeued and would wait for ever). Reported at once with sinfo's reason
# and slurmd's log (fail prints its end).
timeout 120 srun -N1 -n1 -t 1 -J cluster-probe true > "$dir/log/probe.out" 2>&1 &
probe=$!
while kill -0 "$probe" 2>/dev/null; do
  node=$(timeout 10 sinfo -h -n "$host" -o '%t|%E' 2>/dev/null || true)
  case "${node%%|*}" in
    drain*|drng*|down*|fail*)
      kill "$probe" 2>/dev/null || true
      fail "the node cannot launch jobs: sinfo says '${node%%|*}', reason '${node#*|}'" ;;
  esac
  sleep 0.5
done
wait "$probe" || fail "a one-step probe job (srun true) failed: $(cat "$dir/log/probe.out")"
echo "cluster.sh: one-node cluster up: SLURM_CONF=$SLURM_CONF (node $host, 2 CPUs, partition debug; sockets, state and spool in $private)"
