# Shared by bench/run-bench.sh and bench/run-peers.sh (sourced, not run).
# Sets BUILD (absolute), DATA (packing cache), PEERS (the peers' benchmark scripts) and
# provides make_packings, which builds the LAMMPS packings exactly as the peers' run_all.sh
# phase (a) does (lammps/in.pack, 2 MPI ranks), once; later runs reuse them. The paper-scale bed
# (W = 1.5, N = 298 920) is 15 copies of the W = 0.1 bed side by side, settled by trapdem for
# 20 000 steps (bench/standard.cpp says why), written as a LAMMPS data file that every code reads.
set -euo pipefail
BENCH_DIR=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
ROOT=$(cd "$BENCH_DIR/.." && pwd)
BUILD=${1:-build}
case "$BUILD" in /*) ;; *) BUILD="$ROOT/$BUILD" ;; esac
DATA=${BENCH_DATA:-$BUILD/bench-data}
PEERS=${PEERS:-$(cd "$ROOT/../shared/peers" 2>/dev/null && pwd || echo /work/shared/peers)}
SIZES=${SIZES:-"0.1 0.4 1.5"}
MPIRUN="mpirun --allow-run-as-root --oversubscribe"

make_packings() {
  mkdir -p "$DATA"
  local W NF NV NR
  for W in $SIZES; do
    [ -f "$DATA/pack_W$W.data" ] && continue
    if [ "$W" = 1.5 ]; then
      SIZES=0.1 make_packings
      [ -x "$BUILD/bench/standard" ] || { echo "bench: $BUILD/bench/standard not built" >&2; exit 1; }
      echo "bench: making the packing W=1.5 (15 copies of W=0.1 settled by trapdem; ~15 min) in $DATA" >&2
      OMP_PROC_BIND=true "$BUILD/bench/standard" --data "$DATA/pack_W0.1.data" --width 0.1 --tile 15 --warmup 19900 \
        --steps 100 --threads 2 --write "$DATA/pack_W1.5.tmp" > "$DATA/pack_W1.5.log" && mv "$DATA/pack_W1.5.tmp" "$DATA/pack_W1.5.data"
      continue
    fi
    command -v lmp > /dev/null || { echo "bench: lmp (LAMMPS) not found; run scripts/install-deps --peers" >&2; exit 1; }
    [ -f "$PEERS/lammps/in.pack" ] || { echo "bench: $PEERS/lammps/in.pack not found; set PEERS=" >&2; exit 1; }
    if [ "$W" = 0.1 ]; then NF=30000; NV=10000; NR=5000; else NF=28000; NV=6000; NR=2000; fi
    echo "bench: making the packing W=$W (LAMMPS, 2 ranks; a few minutes) in $DATA" >&2
    (cd "$DATA" && /usr/bin/time -f "packing W=$W wall %e s" $MPIRUN -np 2 lmp -in "$PEERS/lammps/in.pack" \
       -var W $W -var OUT pack_W$W.tmp -var NFALL $NF -var NVISC $NV -var NRELAX $NR -log pack_W$W.log > /dev/null \
     && mv pack_W$W.tmp.restart pack_W$W.restart && mv pack_W$W.tmp.data pack_W$W.data)
  done
}

steps_for() { case "$1" in 0.1) echo "${STEPS_S:-5000}" ;; 1.5) echo "${STEPS_XL:-400}" ;; *) echo "${STEPS_L:-1250}" ;; esac; }
