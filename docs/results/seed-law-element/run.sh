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
run() {  # name, confining stress (Pa), then options: one folder a stress, so a failure at one keeps the others
  local name=$1 confining=$2; shift 2
  local folder="$out/$name-$confining"
  [ -f "$folder/element.json" ] && return 0
  rm -rf "$folder"
  "$trapdem" element "${common[@]}" "$@" --confining "$confining" --out "$folder" > "$folder.log" 2>&1 ||
    echo "$name at $confining Pa failed (see $folder.log)"
}
for p in 10000 50000 200000; do
  run blaze-calibrated-dtref2e-9 $p "${blaze[@]}" "${calibrated[@]}" --set contact.reference_time_step=2e-9
  run ours-calibrated $p "${calibrated[@]}"
done
run blaze-rf3-dtref2e-9 50000 "${blaze[@]}" "${rf3[@]}" --set contact.reference_time_step=2e-9
run ours-rf3 50000 "${rf3[@]}"
for dt in 2e-8 2e-7 2e-6; do
  run blaze-calibrated-dtref$dt 50000 "${blaze[@]}" "${calibrated[@]}" --set contact.reference_time_step=$dt
done
for p in 10000 200000; do
  run blaze-calibrated-dtref2e-7 $p "${blaze[@]}" "${calibrated[@]}" --set contact.reference_time_step=2e-7
done
