#!/bin/bash
# Runs one suite of the MPI tests that run the experiment (ExperimentOnRanks, ResumeOnSameRanks,
# ResumeOnOtherRanks) again and again on R ranks, and tells a hang from a slow run: a
# run whose simulated time (the last "t = ... s" of the newest run.log under /tmp/trapdem-mpi-*)
# has not moved for STALL seconds is a hang; both ranks' stacks (gdb) go to DIR/stacks-I.txt and the
# loop stops with exit 1. On a loaded host the ranks poll for each other's messages and a step's
# exchanges can take 1000x their quiet time: a stack in MPI_Waitall/MPI_Allreduce alone is not a hang.
#
#   tests/mpi/repeat.sh build/tests/mpi/test_mpi 'ResumeOnSameRanks.*' [RANKS] [RUNS]
#   (environment: STALL=90 seconds, NICE=0, DIR=trapdem-mpi-repeat)
set -u
binary=${1:?usage: repeat.sh TEST_MPI FILTER [RANKS] [RUNS]}
filter=${2:?usage: repeat.sh TEST_MPI FILTER [RANKS] [RUNS]}
ranks=${3:-2}
runs=${4:-10}
stall=${STALL:-90}
dir=${DIR:-trapdem-mpi-repeat}
mkdir -p "$dir"
export OMP_NUM_THREADS=1 OMP_WAIT_POLICY=PASSIVE OMPI_MCA_mpi_yield_when_idle=1 OMPI_MCA_btl_vader_single_copy_mechanism=none
simulated_time() {
  local log
  log=$(ls -t /tmp/trapdem-mpi-*/*/run.log 2>/dev/null | head -1)
  [ -n "$log" ] && echo "$log $(grep -o 't = [0-9.]* s' "$log" | tail -1)"
}
for i in $(seq 1 "$runs"); do
  start=$(date +%s)
  nice -n "${NICE:-0}" mpiexec --allow-run-as-root --oversubscribe -n "$ranks" "$binary" --gtest_filter="$filter" \
    > "$dir/run-$i.log" 2>&1 &
  pid=$!
  last=""; moved=$(date +%s)
  while kill -0 "$pid" 2>/dev/null; do
    sleep 3
    now=$(simulated_time)
    if [ "$now" != "$last" ]; then last=$now; moved=$(date +%s); fi
    if [ $(( $(date +%s) - moved )) -gt "$stall" ]; then
      echo "run $i: no progress for $stall s at: $last; stacks in $dir/stacks-$i.txt"
      for p in $(pgrep -x "$(basename "$binary" | cut -c1-15)"); do
        echo "=== pid $p"; gdb -p "$p" -batch -ex "thread apply all bt" 2>/dev/null | grep -E "^#|^Thread"
      done > "$dir/stacks-$i.txt"
      kill "$pid"
      exit 1
    fi
  done
  wait "$pid"; rc=$?
  echo "run $i: exit $rc after $(( $(date +%s) - start )) s"
  [ "$rc" -eq 0 ] || exit "$rc"
done
