#!/bin/bash
# Throughput of the standard benchmark from CPU time, robust to other processes sharing the machine:
# the difference of user + sys between a long and a short run (start-up, file reading and warm-up
# cancel out), the minimum of 3 rounds, the binaries interleaved so that all see the same load.
#
# usage: bench/cpu-time.sh WIDTH THREADS BINARY...   (WIDTH 0.1: N = 19928, 0.4: N = 80560, 1.5: N = 298920)
# e.g.   bench/cpu-time.sh 0.1 1 build-bench/bench/standard build-perf/bench/standard
# Prints per binary the CPU-time rate N * steps / (CPU seconds / THREADS) and the wall-clock rate.
# With 2 threads the CPU time includes OpenMP's spinning at barriers; on a busy machine neither
# number is parallel scaling data.
set -euo pipefail
W=$1; T=$2; shift 2
DATA=${DATA:-$(dirname "$0")/../build-bench/bench-data}
case "$W" in
  0.1) D=$DATA/pack_W0.1.data; N=19928; S=500; L=3500 ;;
  0.4) D=$DATA/pack_W0.4.data; N=80560; S=200; L=1200 ;;
  1.5) D=$DATA/pack_W1.5.data; N=298920; S=60; L=360 ;;
  *) echo "cpu-time.sh: WIDTH is 0.1, 0.4 or 1.5" >&2; exit 2 ;;
esac
declare -A best
run() { OMP_PROC_BIND=true /usr/bin/time -f "%U %S %e" "$1" --data "$D" --width "$W" --steps "$2" --threads "$T" \
          --warmup 100 2>&1 >/dev/null | tail -1 | awk '{print $1 + $2, $3}'; }
lower() { python3 -c "import sys; sys.exit(0 if $1 < $2 else 1)"; }
for round in 1 2 3; do
  for b in "$@"; do
    for steps in $S $L; do
      r=($(run "$b" $steps))
      k="$b $steps"; if [ -z "${best[$k]:-}" ] || lower "${r[0]}" "${best[$k]}"; then best[$k]=${r[0]}; fi
      k="$b $steps wall"; if [ -z "${best[$k]:-}" ] || lower "${r[1]}" "${best[$k]}"; then best[$k]=${r[1]}; fi
    done
  done
done
for b in "$@"; do
  python3 -c "print('%-45s N=$N threads=$T cpu-rate %.2f wall-rate %.2f Mpsteps/s' % ('$b',
    $N * ($L - $S) / ((${best[$b $L]} - ${best[$b $S]}) / $T) / 1e6,
    $N * ($L - $S) / (${best[$b $L wall]} - ${best[$b $S wall]}) / 1e6))"
done
