#!/bin/bash
# The clump benchmark against LAMMPS: trapdem's bed of rigid dimers (build/bench/clumps --shape
# dimer) and the same problem in LAMMPS with rigid bodies (bench/peers-clumps/in.dimers.lammps:
# fix rigid/small, pair granular, fix wall/gran; it says what matches and what does not), on 1 and
# 2 threads (trapdem: OpenMP threads; LAMMPS: MPI ranks, this LAMMPS has no OPENMP package).
# Each side settles the bed from the same lattice and orientations for SETTLE steps, runs 100
# untimed steps, then times STEPS steps. Prints the median per case, and the ratio:
#   trapdem-clumps shape=dimer bodies=4440 members=8880 threads=1 Mbody-steps/s=1.23 Mmember-steps/s=2.46
#   lammps-rigid N=8880 bodies=4440 ranks=1 Mmember-steps/s=0.61   # contacts/member settled=... timed=... reps=3
#   ratio trapdem-clumps/lammps-rigid N=8880 threads=1 = 4.03
# Each process settles its own bed once (neither code restarts), then times REPS runs of STEPS
# steps one after another (trapdem --reps, LAMMPS -var TIMED) and reports their median; settling
# takes ~95 % of a process's time, so the repetitions cost little. ROUNDS repeats the whole (each
# round runs trapdem once, then LAMMPS once per rank count, so that a slow spell of a shared host
# falls on all cases alike) and the summary takes the median round.
# Usage: bash bench/run-clumps.sh [BUILD]
# Env: REPS (3), ROUNDS (1), WIDTH (0.1 m), SETTLE (80000: the top layers land after ~55 000 steps), STEPS (2000), THREADS ("1 2"), BENCH_DATA (logs go
#      to BENCH_DATA/clumps, default BUILD/bench-data/clumps).
source "$(dirname "$0")/common.sh"
REPS=${REPS:-3}
ROUNDS=${ROUNDS:-1}
WIDTH=${WIDTH:-0.1}
SETTLE=${SETTLE:-80000}
STEPS=${STEPS:-2000}
THREADS=${THREADS:-"1 2"}
export OMP_PROC_BIND=${OMP_PROC_BIND:-true}   # pin threads like mpirun pins ranks
EXE="$BUILD/bench/clumps"
INPUT_DIR="$BENCH_DIR/peers-clumps"
[ -x "$EXE" ] || { echo "bench-clumps: $EXE not found; build it: cmake --build $BUILD --target clumps" >&2; exit 1; }
command -v lmp > /dev/null && command -v mpirun > /dev/null && command -v python3 > /dev/null || {
  echo "bench-clumps: lmp, mpirun or python3 missing; run scripts/install-deps --peers" >&2; exit 1; }
WORK="$DATA/clumps"
mkdir -p "$WORK"
RUNS="$WORK/runs.tsv"   # case, threads, rep, Mmember-steps/s, the case's other fields
: > "$RUNS"
echo "bench-clumps: W=$WIDTH settle=$SETTLE steps=$STEPS threads/ranks=\"$THREADS\" reps=$REPS rounds=$ROUNDS; logs in $WORK" >&2

for rep in $(seq 1 "$ROUNDS"); do
  out="$WORK/trapdem_r$rep.txt"
  if ! "$EXE" --shape dimer --width "$WIDTH" --settle "$SETTLE" --steps "$STEPS" --reps "$REPS" --threads "$THREADS" > "$out"; then
    echo "bench-clumps: trapdem failed (rep=$rep); see $out" >&2; exit 1
  fi
  # "# dimer: ... dt 2.813e-07 s; after K settling steps: 0.41 contacts per member, ..."
  zpm=$(sed -n 's/^# dimer:.* \([0-9.]*\) contacts per member.*/\1/p' "$out")
  dt=$(sed -n 's/^# dimer:.*; dt \([0-9.eE+-]*\) s;.*/\1/p' "$out")
  grep '^trapdem-clumps ' "$out" | while read -r line; do
    t=$(echo "$line" | sed -n 's/.* threads=\([0-9]*\) .*/\1/p')
    rate=$(echo "$line" | sed -n 's/.* Mmember-steps\/s=\([0-9.eE+-]*\).*/\1/p')
    printf 'trapdem\t%s\t%s\t%s\t%s\t%s\t%s\n' "$t" "$rep" "$rate" "$zpm" "$dt" "$line" >> "$RUNS"
  done
  for T in $THREADS; do
    dir="$WORK/lammps_np${T}_r$rep"
    rm -rf "$dir"; mkdir -p "$dir"
    pre=""; [ "$T" -gt 1 ] && pre="$MPIRUN -np $T"
    if ! (cd "$dir" && $pre lmp -in "$INPUT_DIR/in.dimers.lammps" -var HERE "$INPUT_DIR" -var W "$WIDTH" \
            -var SETTLE "$SETTLE" -var NSTEPS "$STEPS" -var TIMED "$REPS" -log log.lammps -screen none > stdout.txt 2>&1); then
      tail -5 "$dir/log.lammps" >&2; echo "bench-clumps: LAMMPS failed (ranks=$T rep=$rep); see $dir" >&2; exit 1
    fi
    python3 - "$dir/log.lammps" "$STEPS" "$T" "$rep" >> "$RUNS" <<'PY'
import re, statistics, sys
log, steps, ranks, rep = sys.argv[1], int(sys.argv[2]), sys.argv[3], sys.argv[4]
t = open(log, errors="replace").read()
loops = [(float(s), int(n), int(a)) for s, n, a in
         re.findall(r"Loop time of ([0-9.eE+-]+) on \d+ procs for (\d+) steps with (\d+) atoms", t)]
timed_runs = [l for l in loops if l[1] == steps]   # those of STEPS steps
loop, atoms = statistics.median_high(l[0] for l in timed_runs), timed_runs[0][2]   # the median rate's
settled = re.search(r"^settled: .*contacts_per_member=([0-9.]+)", t, re.M).group(1)
timed = re.search(r"^timed: .*contacts_per_member=([0-9.]+)", t, re.M).group(1)
dims = re.search(r"^dimers: .* bodies=(\d+) dt=(\S+)", t, re.M)
print(f"lammps\t{ranks}\t{rep}\t{atoms * steps / loop / 1e6:.4f}\t{settled}\t{dims.group(2)}\t"
      f"N={atoms} bodies={dims.group(1)} timed={timed} loop_s={loop:.4f} runs={len(timed_runs)}")
PY
  done
done

python3 - "$RUNS" "$SETTLE" <<'PY' | tee "$WORK/summary.txt"
import statistics, sys
from collections import defaultdict
runs, settle = sys.argv[1], sys.argv[2]
case = defaultdict(list)
for l in open(runs):
    code, t, rep, rate, zpm, dt, rest = l.rstrip("\n").split("\t")
    case[(code, int(t))].append((float(rate), float(zpm), float(dt), rest))
def median_run(rs):  # the run of median rate (the lower middle one for an even count)
    return sorted(rs)[(len(rs) - 1) // 2]
threads = sorted({t for _, t in case})
if ("trapdem", threads[0]) in case and ("lammps", threads[0]) in case:
    td, ld = case[("trapdem", threads[0])][0][2], case[("lammps", threads[0])][0][2]
    note = "" if abs(td / ld - 1) < 1e-3 else "   # WARNING: the time steps differ"
    print(f"# time step: trapdem {td:.4g} s, lammps {ld:.10g} s{note}")
    print(f"# contacts per member after {settle} settling steps (median over runs): trapdem "
          f"{statistics.median(r[1] for r in case[('trapdem', threads[0])]):.3f}, lammps "
          f"{statistics.median(r[1] for rs in (v for k, v in case.items() if k[0] == 'lammps') for r in rs):.3f}")
for t in threads:
    tr = case.get(("trapdem", t)); lr = case.get(("lammps", t))
    if tr:
        print(median_run(tr)[3])
    if lr:
        rate, zpm, _, rest = median_run(lr)
        n, bodies, timed, _ = rest.split(" ", 3)
        print(f"lammps-rigid {n} {bodies} ranks={t} Mmember-steps/s={rate:.3f}   "
              f"# contacts/member settled={zpm:.3f} {timed} rounds={len(lr)}")
    if tr and lr:
        print(f"ratio trapdem-clumps/lammps-rigid {n} threads={t} = {median_run(tr)[0] / rate:.2f}")
PY
