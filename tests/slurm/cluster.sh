#!/usr/bin/env bash
# A one-node Slurm cluster for the tests (issue 16): munged, slurmctld and slurmd on this host with
# a generated minimal slurm.conf, its configuration, key, state and logs in one folder, its sockets
# (munged's, slurmd's spool where each job step gets one) in a short private folder of their own
# (mktemp -d /tmp/tdslurm.XXXXXX, named in DIR/runtime and removed by stop): a Unix socket's path
# is limited to 108 bytes, and DIR lies under the checkout, which may be anywhere.
#
#   tests/slurm/cluster.sh start DIR   # starts it, waits until sinfo shows the node idle
#   tests/slurm/cluster.sh stop DIR    # cancels its jobs, stops the three daemons
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

stop_cluster() {
  [ -d "$dir" ] || return 0
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
  if [ -f "$dir/runtime" ]; then
    local runtime
    runtime=$(cat "$dir/runtime")
    stop_daemon "$runtime/munged.pid"
    case "$runtime" in /tmp/tdslurm.*) rm -rf "$runtime" ;; esac
    rm -f "$dir/runtime"
  fi
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
rm -rf "$dir/state" "$dir/spool" "$dir/log" "$dir/jobcomp.txt"
mkdir -p "$dir/munge" "$dir/state" "$dir/log"
chmod 700 "$dir/munge"
runtime=$(mktemp -d /tmp/tdslurm.XXXXXX) || fail "cannot make a folder for the cluster's sockets under /tmp"
echo "$runtime" > "$dir/runtime"
mkdir -p "$runtime/spool"
chmod 700 "$runtime"
# The longest socket path: slurmd's step socket, spool/<node>_<job>.<step> with 10-digit numbers.
longest="$runtime/spool/${host}_4294967295.4294967295"
if [ ${#longest} -ge 108 ]; then
  rm -rf "$runtime"; rm -f "$dir/runtime"
  fail "a Unix socket path would be ${#longest} bytes (limit 108): $longest (the host name '$host' is too long)"
fi

# munge: a key of our own (made once), its socket in the folder.
key="$dir/munge/munge.key"
if [ ! -s "$key" ]; then
  if command -v mungekey > /dev/null; then
    mungekey --create --keyfile="$key" || fail "mungekey could not create $key"
  else
    dd if=/dev/urandom of="$key" bs=1024 count=1 status=none || fail "could not write $key"
  fi
fi
chmod 600 "$key"
socket="$runtime/munge.socket"
munged --force --socket="$socket" --key-file="$key" --pid-file="$runtime/munged.pid" \
  --log-file="$dir/log/munged.log" --seed-file="$dir/munge/munged.seed" \
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
StateSaveLocation=$dir/state
SlurmdSpoolDir=$runtime/spool
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
[ "$state" = "idle" ] || { stop_cluster; fail "the node did not become idle within 60 s (sinfo says '${state:-nothing}')"; }
# A node can be idle and still unable to launch a job (a step socket it cannot create, a credential it
# refuses): one short job step now, so that the tests are not the first to wait for it.
if ! timeout 60 srun -N1 -n1 -t 1 true > "$dir/log/first-step.txt" 2>&1; then
  reason=$(timeout 10 sinfo -h -n "$host" -o '%t %E' 2>/dev/null || true)
  cat "$dir/log/first-step.txt" >&2
  stop_cluster
  fail "the node is up but could not run a one-step job within 60 s (sinfo: '${reason:-nothing}')"
fi
echo "cluster.sh: one-node cluster up: SLURM_CONF=$SLURM_CONF (node $host, 2 CPUs, partition debug)"
