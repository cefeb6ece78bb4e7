#!/bin/bash
# The standard benchmark on 2 MPI ranks (issue 13): per bed (N = 19928, 80560; the 298920 bed with
# SIZES="0.1 0.4 1.5"), in one run on this machine, REPS rounds of
#   trapdem 1 rank x 2 threads (bench/standard), trapdem 2 ranks x 1 thread (bench/mpi_standard),
# then LIGGGHTS and LAMMPS on 2 ranks through the peers' run_all.sh (as bench/run-peers.sh does;
# NO_PEERS=1 skips them). Prints the median line per case, each 2-rank case's halo lines (ghosts
# per step and exchange time per step per rank: the weak-scaling model's inputs, bench/RESULTS.md)
# and the ratios 2 ranks / 2 threads and trapdem / peer on 2 ranks. Records no conclusion: run it
# on a quiet host.
# Usage: bash bench/run-mpi.sh [BUILD]
# Env: REPS (3), SIZES ("0.1 0.4"), STEPS_S, STEPS_L, STEPS_XL, WARMUP (300), CODES, PEERS, BENCH_DATA, NO_PEERS,
#      PEERS_THIS_RUN (1: NO_PEERS, but the peers' 2-rank results in BENCH_DATA come from the same
#      invocation, as `make bench-peers` runs run-peers.sh first; otherwise they are not compared).
SIZES=${SIZES:-"0.1 0.4"}
source "$(dirname "$0")/common.sh"
REPS=${REPS:-3}
WARMUP=${WARMUP:-300}
export OMP_PROC_BIND=${OMP_PROC_BIND:-true}
for exe in standard mpi_standard; do
  [ -x "$BUILD/bench/$exe" ] || { echo "bench-mpi: $BUILD/bench/$exe not found (MPI build: cmake -DTRAPDEM_MPI=ON)" >&2; exit 1; }
done
make_packings
OUT="$DATA/trapdem_mpi_runs.txt"
: > "$OUT"
declare -A runs
for rep in $(seq 1 $REPS); do
  for W in $SIZES; do
    NS=$(steps_for $W)
    res=$("$BUILD/bench/standard" --data "$DATA/pack_W$W.data" --width $W --steps $NS --threads 2 --warmup $WARMUP) ||
      { echo "bench-mpi: trapdem 1x2 failed (W=$W rep=$rep)" >&2; exit 1; }
    echo "$res" | sed "s/^/W=$W rep=$rep: /" >> "$OUT"
    runs[$W,1x2]+="$(echo "$res" | sed 's/threads=2/ranks=1 threads=2/' | tr '\n' '\t')"$'\n'
    res=$(OMP_NUM_THREADS=1 $MPIRUN --bind-to core -np 2 "$BUILD/bench/mpi_standard" --data "$DATA/pack_W$W.data" --width $W \
            --steps $NS --threads 1 --warmup $WARMUP) || { echo "bench-mpi: trapdem 2x1 failed (W=$W rep=$rep)" >&2; exit 1; }
    echo "$res" | sed "s/^/W=$W rep=$rep: /" >> "$OUT"
    runs[$W,2x1]+="$(echo "$res" | tr '\n' '\t')"$'\n'
  done
done
: > "$DATA/trapdem_mpi_medians.txt"
for W in $SIZES; do
  for c in 1x2 2x1; do
    printf '%s' "${runs[$W,$c]}" | sort -t= -k5 -g | sed -n "$(( (REPS + 1) / 2 ))p" | tr '\t' '\n' | sed '/^$/d' |
      tee -a "$DATA/trapdem_mpi_medians.txt"
  done
done

if [ "${NO_PEERS:-0}" != 1 ]; then
  command -v liggghts > /dev/null && command -v lmp > /dev/null || { echo "bench-mpi: liggghts or lmp missing (NO_PEERS=1 skips them)" >&2; exit 1; }
  echo "bench-mpi: peers (${CODES:-liggghts lmp_granular}); log in $DATA/peers_mpi.out" >&2
  WORK="$DATA" INSTALL=0 CODES="${CODES:-liggghts lmp_granular}" REPS=$REPS SIZES="$SIZES" STEPS_S=$(steps_for 0.1) \
    STEPS_L=$(steps_for 0.4) bash "$PEERS/run_all.sh" > "$DATA/peers_mpi.out" 2>&1 ||
    { tail -20 "$DATA/peers_mpi.out" >&2; echo "bench-mpi: run_all.sh failed" >&2; exit 1; }
fi

PEER_RESULTS=$DATA/results.csv
[ "${NO_PEERS:-0}" = 1 ] && [ "${PEERS_THIS_RUN:-0}" != 1 ] && PEER_RESULTS=none
python3 - "$DATA" "$PEER_RESULTS" <<'PY'
import csv, os, re, statistics, sys
data, peer_results = sys.argv[1], sys.argv[2]
ours = {}
for line in open(f"{data}/trapdem_mpi_medians.txt"):
    m = re.match(r'trapdem N=(\d+) ranks=(\d+) threads=(\d+) Mpsteps/s=([0-9.eE+-]+)', line)
    if m: ours[(int(m.group(1)), m.group(2), m.group(3))] = float(m.group(4))
peer = {}
if os.path.exists(peer_results):  # a stale file from another run is not compared ("none")
    rows = [r for r in csv.DictReader(open(peer_results)) if r['np'] == '2']
    for key in {(r['code'], r['N_box_W']) for r in rows}:
        g = [r for r in rows if (r['code'], r['N_box_W']) == key]
        n = int(re.search(r'(\d+) atoms', open(f"{data}/pack_W{key[1]}.data").read()).group(1))
        peer[({"lmp_granular": "lammps"}.get(key[0], key[0]), n)] = n * int(g[0]['steps']) / statistics.median(float(r['loop_s']) for r in g) / 1e6
print("# median Mpsteps/s; trapdem R x T, peers on 2 MPI ranks")
for n in sorted({k[0] for k in ours}):
    two_ranks, two_threads = ours.get((n, '2', '1')), ours.get((n, '1', '2'))
    if two_ranks and two_threads:
        print(f"ratio trapdem 2 ranks / 2 threads N={n} = {two_ranks / two_threads:.2f}")
    for (code, m), rate in sorted(peer.items()):
        if m == n and two_ranks:
            print(f"{code} N={n} ranks=2 Mpsteps/s={rate:.3f}")
            print(f"ratio trapdem/{code} on 2 ranks N={n} = {two_ranks / rate:.2f}")
PY
