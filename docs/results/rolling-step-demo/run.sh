#!/bin/bash
# Issue 36: does the constant-torque rolling resistance's step dependence (docs/element.md,
# "Rolling resistance and the time step": RF3's phi'_cs 31.5 deg at the demo's step of 1.56e-6 s,
# 35.9 deg at 3e-7 s) change the trapdoor's mechanism? RF3 from one deposit (the demo Calibrated
# pour, seed 2019, settled at 1 g: its snapshot 1, as equal-density-demo.toml does), settled again
# at 1 g with RF3's law, spun up and lowered, once at the demo's own step and once at 3e-7 s
# (everything else equal); then RF2 the same way. Run from the checkout: bash docs/results/rolling-step-demo/run.sh [THREADS] [TRAPDEM]
set -euo pipefail
threads=${1:-2}
trapdem=${2:-build/apps/trapdem}
out=trapdem-out/rolling-step-demo
rf3=(--set contact.static_friction=0.18 --set contact.kinetic_friction=0.5 --set contact.rolling_friction=0.4)
rf2=(--set contact.static_friction=0.18 --set contact.kinetic_friction=0.5 --set contact.rolling_friction=0.2)
from=(--set "packing.from=\"$PWD/$out/calibrated-deposit\"" --set 'packing.format="trapdem"' --set packing.snapshot=1
      --set 'packing.start_stage="settling"')
run() {  # folder, options: a finished run is skipped, a stopped one resumed
  local folder=$out/$1; shift
  if [ -f "$folder/run.json" ] && grep -q '"complete": true' "$folder/run.json"; then return 0; fi
  if [ -f "$folder/resolved.toml" ]; then "$trapdem" run --resume "$folder" --threads "$threads" --quiet
  else "$trapdem" run --preset demo --threads "$threads" --quiet --out "$folder" "$@"; fi
  "$trapdem" analyze "$folder" --quiet
}
run calibrated-deposit
run rf3-step-default "${rf3[@]}" "${from[@]}"
run rf3-step-3e-7 "${rf3[@]}" "${from[@]}" --set numerics.time_step=3e-7
run rf2-step-default "${rf2[@]}" "${from[@]}"
run rf2-step-3e-7 "${rf2[@]}" "${from[@]}" --set numerics.time_step=3e-7
