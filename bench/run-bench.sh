#!/bin/bash
# The standard benchmark, trapdem side: the settled beds (N = 19928, 80560, 298920), 1 and 2
# OpenMP threads, REPS repetitions each; prints the median line per case:
#   trapdem N=19928 threads=1 Mpsteps/s=12.34
# Usage: bash bench/run-bench.sh [BUILD]     (make bench)
# Env: REPS (3), STEPS_S (5000, N~20k), STEPS_L (1250, N~80k), STEPS_XL (400, N~300k), WARMUP (300), THREADS ("1 2"),
#      SIZES ("0.1 0.4 1.5"), BENCH_DATA (packing cache, default BUILD/bench-data), PEERS.
source "$(dirname "$0")/common.sh"
REPS=${REPS:-3}
WARMUP=${WARMUP:-300}
THREADS=${THREADS:-"1 2"}
export OMP_PROC_BIND=${OMP_PROC_BIND:-true}   # pin threads like mpirun pins ranks
EXE="$BUILD/bench/standard"
[ -x "$EXE" ] || { echo "bench: $EXE not found; build it: cmake --build $BUILD --target standard" >&2; exit 1; }
make_packings
OUT="$DATA/trapdem_runs.txt"
: > "$OUT"
# The repetitions are the outer loop: each round runs every case once, so that a slow spell of a
# shared host falls on all cases alike instead of on one case's block of repetitions (the loss per
# particle and the thread speed-up are ratios of cases).
declare -A runs
for rep in $(seq 1 $REPS); do
  for W in $SIZES; do
    NS=$(steps_for $W)
    for T in $THREADS; do
      if ! res=$("$EXE" --data "$DATA/pack_W$W.data" --width $W --steps $NS --threads $T --warmup $WARMUP); then
        echo "bench: trapdem failed (W=$W threads=$T rep=$rep)" >&2; exit 1
      fi
      echo "$res" | sed "s/^/W=$W rep=$rep: /" >> "$OUT"
      runs[$W,$T]+="$(echo "$res" | tr '\n' '\t')"$'\n'
    done
  done
done
# Per case, the median by Mpsteps/s; print its two lines.
for W in $SIZES; do
  for T in $THREADS; do
    printf '%s' "${runs[$W,$T]}" | sort -t= -k4 -g | sed -n "$(( (REPS + 1) / 2 ))p" | tr '\t' '\n' | sed '/^$/d'
  done
done
