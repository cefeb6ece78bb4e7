#!/usr/bin/env bash
# The element tests of issue 36 §1: the seed's Table 2 particles (paper-calibrated, at the
# paper-scale stiffness k_n 5e4 N/m, k_t 2.5e4 N/m) with Blaze-DEM's law read as a strength
# (tangential_model = "blaze_tresca", rolling_model = "angular_damping", damping_model =
# "restitution_blaze") against trapdem's law, biaxial, dense and loose, 4000 spheres, 1 thread.
# Usage: bash run.sh TRAPDEM OUT_DIR   (each case ~1.5 min a confining stress on one core)
set -euo pipefail
trapdem=$1
out=$2
mkdir -p "$out"
common=(--preset paper-calibrated --set contact.normal_stiffness=5e4 --set contact.tangential_stiffness=2.5e4
        --threads 1 --quiet)
blaze=(--set contact.tangential_model=blaze_tresca --set contact.rolling_model=angular_damping
       --set contact.damping_model=restitution_blaze)
calibrated=(--set contact.kinetic_friction=0.18 --set contact.rolling_friction=0.001)
rf3=(--set contact.kinetic_friction=0.5 --set contact.rolling_friction=0.4)
run() {  # name, then options
  local name=$1; shift
  [ -f "$out/$name/element.json" ] && return 0
  "$trapdem" element "${common[@]}" "$@" --out "$out/$name" > "$out/$name.log" 2>&1 || echo "$name failed (see $name.log)"
}
run blaze-calibrated-dtref2e-9 "${blaze[@]}" "${calibrated[@]}" --set contact.reference_time_step=2e-9 --confining 10e3,50e3,200e3
run ours-calibrated "${calibrated[@]}" --confining 10e3,50e3,200e3
run blaze-calibrated-dtref2e-7 "${blaze[@]}" "${calibrated[@]}" --set contact.reference_time_step=2e-7 --confining 10e3,50e3,200e3
run blaze-rf3-dtref2e-9 "${blaze[@]}" "${rf3[@]}" --set contact.reference_time_step=2e-9 --confining 50e3
run ours-rf3 "${rf3[@]}" --confining 50e3
run blaze-calibrated-dtref2e-8 "${blaze[@]}" "${calibrated[@]}" --set contact.reference_time_step=2e-8 --confining 50e3
run blaze-calibrated-dtref2e-6 "${blaze[@]}" "${calibrated[@]}" --set contact.reference_time_step=2e-6 --confining 50e3
