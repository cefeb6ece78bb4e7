# Shared by bench/run-bench.sh and bench/run-peers.sh (sourced, not run).
# Sets BUILD (absolute), DATA (packing cache), PEERS (the peers' benchmark scripts) and
# provides make_packings, which builds the LAMMPS packings exactly as the peers' run_all.sh
# phase (a) does (lammps/in.pack, 2 MPI ranks), once; later runs reuse them.
set -euo pipefail
BENCH_DIR=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
ROOT=$(cd "$BENCH_DIR/.." && pwd)
BUILD=${1:-build}
case "$BUILD" in /*) ;; *) BUILD="$ROOT/$BUILD" ;; esac
DATA=${BENCH_DATA:-$BUILD/bench-data}
PEERS=${PEERS:-$(cd "$ROOT/../shared/peers" 2>/dev/null && pwd || echo /work/shared/peers)}
SIZES=${SIZES:-"0.1 0.4"}
MPIRUN="mpirun --allow-run-as-root --oversubscribe"

make_packings() {
  mkdir -p "$DATA"
  local W NF NV NR
  for W in $SIZES; do
    [ -f "$DATA/pack_W$W.data" ] && continue
    command -v lmp > /dev/null || { echo "bench: lmp (LAMMPS) not found; run scripts/install-deps --peers" >&2; exit 1; }
    [ -f "$PEERS/lammps/in.pack" ] || { echo "bench: $PEERS/lammps/in.pack not found; set PEERS=" >&2; exit 1; }
    if [ "$W" = 0.1 ]; then NF=30000; NV=10000; NR=5000; else NF=28000; NV=6000; NR=2000; fi
    echo "bench: making the packing W=$W (LAMMPS, 2 ranks; a few minutes) in $DATA" >&2
    (cd "$DATA" && /usr/bin/time -f "packing W=$W wall %e s" $MPIRUN -np 2 lmp -in "$PEERS/lammps/in.pack" \
       -var W $W -var OUT pack_W$W.tmp -var NFALL $NF -var NVISC $NV -var NRELAX $NR -log pack_W$W.log > /dev/null \
     && mv pack_W$W.tmp.restart pack_W$W.restart && mv pack_W$W.tmp.data pack_W$W.data)
  done
}

steps_for() { if [ "$1" = 0.1 ]; then echo "${STEPS_S:-5000}"; else echo "${STEPS_L:-1250}"; fi; }
