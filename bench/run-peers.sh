#!/bin/bash
# The standard benchmark against the peer codes, in one run on this machine: LIGGGHTS and LAMMPS
# (pair granular, "lmp_granular") via the peers' own run_all.sh on the same packing files, then
# trapdem (bench/run-bench.sh); prints per case
#   liggghts N=19928 threads=1 Mpsteps/s=4.89
#   ratio trapdem/liggghts N=19928 threads=1 = 2.31
# (threads = MPI ranks for the peers, OpenMP threads for trapdem).
# Usage: bash bench/run-peers.sh [BUILD]     (make bench-peers)
# Env: PEER_REPS (REPS or 3), CODES ("liggghts lmp_granular"), and those of run-bench.sh.
source "$(dirname "$0")/common.sh"
PEER_REPS=${PEER_REPS:-${REPS:-3}}
CODES=${CODES:-"liggghts lmp_granular"}
command -v liggghts > /dev/null && command -v lmp > /dev/null && command -v mpirun > /dev/null || {
  echo "bench-peers: liggghts, lmp or mpirun missing; run scripts/install-deps --peers" >&2; exit 1; }
[ -f "$PEERS/run_all.sh" ] || { echo "bench-peers: $PEERS/run_all.sh not found; set PEERS=" >&2; exit 1; }
make_packings

echo "bench-peers: peers ($CODES), $PEER_REPS repetitions; log in $DATA/peers.out" >&2
WORK="$DATA" INSTALL=0 CODES="$CODES" REPS=$PEER_REPS SIZES="$SIZES" STEPS_S=$(steps_for 0.1) STEPS_L=$(steps_for 0.4) \
  bash "$PEERS/run_all.sh" > "$DATA/peers.out" 2>&1 || { tail -20 "$DATA/peers.out" >&2; echo "bench-peers: run_all.sh failed" >&2; exit 1; }

echo "bench-peers: trapdem" >&2
bash "$BENCH_DIR/run-bench.sh" "$BUILD" | tee "$DATA/trapdem_medians.txt"

python3 - "$DATA" <<'PY' | tee "$DATA/summary.txt"
import csv, re, statistics, sys
data = sys.argv[1]
rows = list(csv.DictReader(open(f"{data}/results.csv")))
natoms = {}
def atoms(W):
    if W not in natoms:
        natoms[W] = int(re.search(r'(\d+) atoms', open(f"{data}/pack_W{W}.data").read()).group(1))
    return natoms[W]
names = {"lmp_granular": "lammps", "lmp_hooke": "lammps_hooke"}
peer = {}
for key in sorted({(r['code'], r['N_box_W'], r['np']) for r in rows}, key=lambda k: (float(k[1]), k[0], k[2])):
    g = [r for r in rows if (r['code'], r['N_box_W'], r['np']) == key]
    loop = statistics.median(float(r['loop_s']) for r in g)
    n = atoms(key[1])
    rate = n * int(g[0]['steps']) / loop / 1e6
    peer[(names.get(key[0], key[0]), n, key[2])] = (rate, g[0]['contacts_per_particle'], len(g))
ours = {}
host = ""
for line in open(f"{data}/trapdem_medians.txt"):
    if line.startswith("# trapdem ") and not host: host = line.strip()
    m = re.match(r'trapdem N=(\d+) threads=(\d+) Mpsteps/s=([0-9.eE+-]+)', line)
    if m: ours[(int(m.group(1)), m.group(2))] = float(m.group(3))
print("# median Mpsteps/s (particle-steps per second / 1e6); peers: contacts/particle, repetitions")
if host: print(host)
for (n, t), r in sorted(ours.items()):
    print(f"trapdem N={n} threads={t} Mpsteps/s={r:.3f}")
    for code in sorted({k[0] for k in peer}):
        if (code, n, t) in peer:
            pr, zpp, reps = peer[(code, n, t)]
            print(f"{code} N={n} threads={t} Mpsteps/s={pr:.3f}   # contacts/particle={zpp} reps={reps}")
    for code in sorted({k[0] for k in peer}):
        if (code, n, t) in peer:
            print(f"ratio trapdem/{code} N={n} threads={t} = {r / peer[(code, n, t)][0]:.2f}")
PY
