#!/bin/bash
# A crowded host (issue 41): what the wait policy costs and saves. For each binary, interleaved
# over ROUNDS rounds, the whole tiny preset (the same work every time: ~700 beads poured, settled,
# spun up and lowered, ~68 M particle-steps) run
#   alone   one run of 2 threads (the reference);
#   pair    two runs of 2 threads side by side (4 threads on 2 cores);
#   ranks   2 MPI ranks x 2 threads (4 threads on 2 cores);
# and the particle-steps per second of each (run.json; for the pair, the mean of the two runs). A run
# that needs more than LIMIT seconds (300) is stopped and reported as "> LIMIT s" (a rate below
# its particle-steps over LIMIT). The binaries must accept --set box.height=0.06 (the tiny preset's
# box since a07b819; an older binary's preset was 45 mm high).
#
# usage: bench/crowded.sh BINARY...      e.g. bench/crowded.sh /work/wt-base/build/apps/trapdem build/apps/trapdem
# Env: ROUNDS (3), LIMIT (300). Run nothing else beside it.
set -uo pipefail
[ $# -ge 1 ] || { sed -n '2,15p' "$0" >&2; exit 2; }
ROUNDS=${ROUNDS:-3}
LIMIT=${LIMIT:-300}
WORK=$(mktemp -d /tmp/trapdem-crowded.XXXXXX)
trap 'rm -rf "$WORK"' EXIT
echo "crowded: $(lscpu | sed -n 's/^Model name: *//p' | head -1), $(nproc) cores, $ROUNDS rounds, limit $LIMIT s"
ARGS=(run --preset tiny --set box.height=0.06 --threads 2 --quiet)
rate() {  # run.json's particle-steps per second, or "> LIMIT s" for a run stopped by the limit
  if [ "$2" = 124 ] || [ ! -f "$1/run.json" ]; then echo "timeout"; return; fi
  /usr/bin/python3 -c "import json,sys; r=json.load(open(sys.argv[1])); print(f\"{r['particle_steps']/r['wall_seconds']/1e6:.2f}\")" "$1/run.json"
}
declare -A results
for round in $(seq "$ROUNDS"); do
  k=0
  for b in "$@"; do
    k=$((k + 1))
    d="$WORK/r$round-b$k"
    mkdir -p "$d"
    timeout "$LIMIT" "$b" "${ARGS[@]}" --out "$d/alone" > /dev/null 2>&1; rc=$?
    alone=$(rate "$d/alone" $rc)
    timeout "$LIMIT" "$b" "${ARGS[@]}" --out "$d/pair-a" > /dev/null 2>&1 & pa=$!
    timeout "$LIMIT" "$b" "${ARGS[@]}" --out "$d/pair-b" > /dev/null 2>&1 & pb=$!
    wait $pa; ra=$?; wait $pb; rb=$?
    pair="$(rate "$d/pair-a" $ra) $(rate "$d/pair-b" $rb)"
    timeout "$LIMIT" mpirun --allow-run-as-root --oversubscribe -np 2 "$b" "${ARGS[@]}" --out "$d/ranks" > /dev/null 2>&1; rc=$?
    ranks=$(rate "$d/ranks" $rc)
    echo "round $round binary $k ($b): alone $alone, pair $pair, ranks $ranks M particle-steps/s"
    results[$k]="${results[$k]:-}|$alone;$pair;$ranks"
    rm -rf "$d"
  done
done
