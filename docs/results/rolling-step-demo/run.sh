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
rf1=(--set contact.static_friction=0.18 --set contact.kinetic_friction=0.2 --set contact.rolling_friction=0.2)
from_deposit() {  # the options that start a run from a deposit's snapshot 1 (settled at 1 g)
  from=(--set "packing.from=\"$PWD/$out/$1\"" --set 'packing.format="trapdem"' --set packing.snapshot=1
        --set 'packing.start_stage="settling"')
}
from_deposit calibrated-deposit
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
run rf1-step-default "${rf1[@]}" "${from[@]}"
run rf1-step-3e-7 "${rf1[@]}" "${from[@]}" --set numerics.time_step=3e-7
# RF1's friction with the elastic-plastic rolling spring (EPSD): in the element test its strength does
# not move with the step (phi'_peak / phi'_cs 46.1 / 31.8 deg at the demo's step, 47.1 / 33.4 at 3e-7 s,
# three specimens each; docs/element.md), near Table 1's sands
epsd=(--set contact.rolling_model=elastic_plastic)
run rf1-epsd-step-default "${rf1[@]}" "${epsd[@]}" "${from[@]}"
run rf1-epsd-step-3e-7 "${rf1[@]}" "${epsd[@]}" "${from[@]}" --set numerics.time_step=3e-7
# The RF3 A/B again from a second deposit (pour seed 2020): is the step's effect larger than the
# packings' spread?
run calibrated-deposit-2020 --set pluviation.seed=2020
from_deposit calibrated-deposit-2020
run rf3-step-default-2020 "${rf3[@]}" "${from[@]}"
run rf3-step-3e-7-2020 "${rf3[@]}" "${from[@]}" --set numerics.time_step=3e-7
# RF1 with EPSD and with the constant torque from the second and a third deposit (pour seed 2021):
# does EPSD's near-vertical pair of bands repeat, beside the constant torque's from the same deposits?
run rf1-epsd-step-default-2020 "${rf1[@]}" "${epsd[@]}" "${from[@]}"
run rf1-step-default-2020 "${rf1[@]}" "${from[@]}"
run calibrated-deposit-2021 --set pluviation.seed=2021
from_deposit calibrated-deposit-2021
run rf1-epsd-step-default-2021 "${rf1[@]}" "${epsd[@]}" "${from[@]}"
run rf1-step-default-2021 "${rf1[@]}" "${from[@]}"
