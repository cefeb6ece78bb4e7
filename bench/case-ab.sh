#!/bin/bash
# The speed of a real run at its own scale: resumes copies of one run folder's checkpoint with each
# binary for the same wall-clock time, the binaries interleaved (A B A B ...), and prints each
# binary's particle-steps per second over those segments (from run.json: the particle-steps and
# wall seconds the segment added; the progress lines' rates are printed too). So an engine change is judged on the paper's case itself (its
# pour, its settled bed at 50 g, its lowering) and not only on the standard bed of bench/standard.
#
# usage: bench/case-ab.sh RUN_FOLDER SECONDS BINARY...      e.g.
#   bench/case-ab.sh trapdem-out/paper-table2-paper/cases/calibrated 120 bin/trapdem-main build/apps/trapdem
# Env: ROUNDS (3), THREADS (2), WORK (scratch folder, default a new one under /tmp; it holds a copy of
# the checkpoint per binary, ~125 MB each at 300k particles).
#
# A segment's wall clock includes reading the checkpoint, the first neighbour-list build and writing
# the checkpoint at the end (a few seconds at 300k, the same for every binary): use SECONDS >= 120.
# The run folder itself is only read. Run nothing else beside it: compare only within one run.
set -euo pipefail
[ $# -ge 3 ] || { sed -n '2,15p' "$0" >&2; exit 2; }
SOURCE=$1; SECONDS_EACH=$2; shift 2
[ -f "$SOURCE/checkpoint.h5" ] || { echo "case-ab.sh: $SOURCE/checkpoint.h5 not found (a run folder with a checkpoint)" >&2; exit 2; }
ROUNDS=${ROUNDS:-3}
THREADS=${THREADS:-2}
WORK=${WORK:-$(mktemp -d /tmp/case-ab.XXXXXX)}
json() { python3 -c "import json,sys; r=json.load(open(sys.argv[1])); print(r['particle_steps'], r['wall_seconds'], r['particles'])" "$1"; }
echo "case-ab: $SOURCE, $SECONDS_EACH s a segment, $ROUNDS rounds, $THREADS threads, CPU: $(lscpu | sed -n 's/^Model name: *//p' | head -1)"
declare -A rates
for round in $(seq "$ROUNDS"); do
  k=0
  for b in "$@"; do
    k=$((k + 1))
    dir="$WORK/binary-$k"
    rm -rf "$dir" && mkdir -p "$dir"
    # A fresh copy each round: every segment starts from the same state.
    for f in checkpoint.h5 resolved.toml run.json run.log trapdoor.csv; do [ -e "$SOURCE/$f" ] && cp "$SOURCE/$f" "$dir/"; done
    [ -d "$SOURCE/snapshots" ] && cp -r "$SOURCE/snapshots" "$dir/"
    for f in "$SOURCE"/snapshots.*; do [ -e "$f" ] && cp "$f" "$dir/"; done
    before=($(json "$dir/run.json"))
    # Exit status 130: stopped by --stop-after with a checkpoint written, as asked.
    rc=0
    OMP_PROC_BIND=true "$b" run --resume "$dir" --stop-after "$SECONDS_EACH" --threads "$THREADS" --quiet > "$dir/out.txt" 2>&1 || rc=$?
    [ $rc = 0 ] || [ $rc = 130 ] || { echo "case-ab.sh: $b failed (exit status $rc), see $dir/run.log" >&2; exit 1; }
    after=($(json "$dir/run.json"))
    rate=$(python3 -c 'import sys; a = [float(x) for x in sys.argv[1:]]; print(f"{(a[1] - a[0]) / (a[3] - a[2]) / 1e6:.3f}")' \
      "${before[0]}" "${after[0]}" "${before[1]}" "${after[1]}")
    # The progress lines' own rates (each over the last log interval, 60 s unless the run set it):
    # the steady rate, without the checkpoint's reading and writing.
    lines=$(tac "$dir/run.log" | sed '/^resumed /q' | tac | grep -oE '[0-9.]+ M particle-steps/s  ' | awk '{print $1}' | tr '\n' ' ')
    echo "round $round binary $k ($b): $rate M particle-steps/s over $((after[0] - before[0])) particle-steps, ${after[2]} particles; progress lines: $lines"
    rates[$k]="${rates[$k]:-} $rate"
  done
done
k=0
for b in "$@"; do
  k=$((k + 1))
  echo "binary $k ($b): median $(printf '%s\n' ${rates[$k]} | sort -g | sed -n "$(( (ROUNDS + 1) / 2 ))p") M particle-steps/s (rounds:${rates[$k]})"
done
