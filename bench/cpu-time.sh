#!/bin/bash
# Throughput of the standard benchmark from CPU time, robust to other processes sharing the machine:
# the difference of user + sys between a long and a short run (start-up, file reading and warm-up
# cancel out), the minimum of 3 rounds, the binaries interleaved so that all see the same load.
#
# usage: bench/cpu-time.sh WIDTH THREADS BINARY...   (WIDTH 0.1: N = 19928, 0.4: N = 80560, 1.5: N = 298920)
# e.g.   bench/cpu-time.sh 0.1 1 build-bench/bench/standard build-perf/bench/standard
# Prints per binary the CPU-time rate N * steps / (CPU seconds / THREADS) and the wall-clock rate
# from the best round, then the medians of the rounds' own rates (each round's long minus short
# run) with the CPU time per particle-step, and the load average at the end. ROUNDS=5 runs more rounds.
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
ROUNDS=${ROUNDS:-3}
declare -A best
declare -A rounds  # per binary: each round's "cpu_short cpu_long wall_short wall_long"
run() { OMP_PROC_BIND=true /usr/bin/time -f "%U %S %e" "$1" --data "$D" --width "$W" --steps "$2" --threads "$T" \
          --warmup 100 2>&1 >/dev/null | tail -1 | awk '{print $1 + $2, $3}'; }
lower() { python3 -c "import sys; sys.exit(0 if $1 < $2 else 1)"; }
for round in $(seq "$ROUNDS"); do
  for b in "$@"; do
    this=()
    for steps in $S $L; do
      r=($(run "$b" $steps))
      this+=("${r[@]}")
      k="$b $steps"; if [ -z "${best[$k]:-}" ] || lower "${r[0]}" "${best[$k]}"; then best[$k]=${r[0]}; fi
      k="$b $steps wall"; if [ -z "${best[$k]:-}" ] || lower "${r[1]}" "${best[$k]}"; then best[$k]=${r[1]}; fi
    done
    rounds[$b]="${rounds[$b]:-} ${this[0]} ${this[2]} ${this[1]} ${this[3]}"
  done
done
for b in "$@"; do
  python3 -c "print('%-45s N=$N threads=$T cpu-rate %.2f wall-rate %.2f Mpsteps/s' % ('$b',
    $N * ($L - $S) / ((${best[$b $L]} - ${best[$b $S]}) / $T) / 1e6,
    $N * ($L - $S) / (${best[$b $L wall]} - ${best[$b $S wall]}) / 1e6))"
done
for b in "$@"; do
  python3 -c "
import statistics
v = [float(x) for x in '${rounds[$b]}'.split()]
work = $N * ($L - $S)
cpu = [work / ((v[k + 1] - v[k]) / $T) / 1e6 for k in range(0, len(v), 4)]
wall = [work / (v[k + 3] - v[k + 2]) / 1e6 for k in range(0, len(v), 4)]
print('  median of %d rounds: cpu-rate %.2f Mpsteps/s (%.0f ns CPU per particle-step; rounds %s), wall-rate %.2f' % (
    len(cpu), statistics.median(cpu), 1e3 / statistics.median(cpu), ' '.join('%.2f' % c for c in cpu), statistics.median(wall)))"
done
echo "load average: $(cut -d' ' -f1-3 /proc/loadavg)"
