#!/bin/bash
# The paper-fast pour from its start, binaries interleaved (A B A B ...): each pours COUNT beads of
# the paper's strongbox at `paper-fast` settings (studies/paper-table2.toml) and the pour stage's
# cost line of run.log is printed (wall clock, particle-steps and their rate, neighbour-list
# rebuilds and their share). What the pour's rebuilds cost, before and after an engine change,
# without a checkpoint to start from (bench/case-ab.sh resumes one).
#
# usage: bench/pour-ab.sh BINARY...      e.g.  bench/pour-ab.sh bin/trapdem-main build/apps/trapdem
# Env: ROUNDS (2), THREADS (2), COUNT (60000 beads, ~75 s a pour on 2 Zen 5 cores), WORK (scratch
# folder, default a new one under /tmp, removed at the end), SETS (more `key=value` settings, spaced;
# a binary given as BINARY@key=value,key=value runs with those settings too, so one binary can be
# compared with itself: bench/pour-ab.sh build/apps/trapdem build/apps/trapdem@numerics.skin_fraction=0.3). Compare rates (M/s) within one run:
# the pour's end is chaotic, so two engines that differ in round-off pour different particle-steps.
set -euo pipefail
[ $# -ge 1 ] || { sed -n '2,12p' "$0" >&2; exit 2; }
ROUNDS=${ROUNDS:-2}
THREADS=${THREADS:-2}
COUNT=${COUNT:-60000}
WORK=${WORK:-$(mktemp -d /tmp/pour-ab.XXXXXX)}
trap 'rm -rf "$WORK"' EXIT
sets=(contact.normal_stiffness=5.0e4 contact.tangential_stiffness=2.5e4 numerics.time_step_fraction=0.4
      pluviation.flow_rate=0.0 pluviation.drop_height=0.08 trapdoor.rate=0.1 "pluviation.count=$COUNT"
      settling.min_time=0.0 settling.max_time=0.0005 spin_up.ramp_time=0.0005 trapdoor.travel=0.0001)
args=()
for s in "${sets[@]}" ${SETS:-}; do args+=(--set "$s"); done
echo "pour-ab: $COUNT beads, $ROUNDS rounds, $THREADS threads, CPU: $(lscpu | sed -n 's/^Model name: *//p' | head -1)"
for round in $(seq "$ROUNDS"); do
  for spec in "$@"; do
    b=${spec%%@*}
    own=()
    if [ "$b" != "$spec" ]; then
      IFS=, read -r -a pairs <<< "${spec#*@}"
      for s in "${pairs[@]}"; do own+=(--set "$s"); done
    fi
    out="$WORK/run"
    rm -rf "$out"
    OMP_WAIT_POLICY=passive "$b" run --preset paper-calibrated "${args[@]}" "${own[@]}" --out "$out" --threads "$THREADS" \
      --quiet > /dev/null
    echo "$spec round $round: $(grep -A1 'stage pluviation finished' "$out/run.log" | tail -1 | sed 's/^ *//')"
  done
done
