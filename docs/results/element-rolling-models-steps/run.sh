#!/usr/bin/env bash
# Issue 36: does a rolling-resistance model give the interlock cases a strength that does not move with
# the time step? RF1's friction (mu_k 0.2, mu_r 0.2) in the biaxial element test at 50 kPa, with the
# constant torque (the presets' model) and with the elastic-plastic rolling spring (EPSD, Ai et al.
# 2011 type C), at several steps and three specimen seeds each:
#   rf1-{torque,epsd}-dtX-seedS   the paper-scale runs' stiffness (k_n 5e4 N/m, 2 mm spheres); X from
#                                 5.36e-6 s (paper-fast's step) down to 6.7e-7 s
#   demo-rf1-MODEL-dtX-seedS      the demo preset's 4 mm spheres at k_n 1e6 N/m, at the demo's own
#                                 step (1.56e-6 s) and at 3e-7 s
# The protocol of docs/element.md's tables (1000 spheres, I = 2e-3, to 25 % axial strain, dense and loose).
# Usage: bash run.sh TRAPDEM OUT_DIR   (4-90 s a run on one core; a finished run is skipped)
# then:  python3 summary.py OUT_DIR    (the table of means and standard deviations)
set -euo pipefail
trapdem=$1
out=$2
mkdir -p "$out"
soft=(--set contact.normal_stiffness=5e4 --set contact.tangential_stiffness=2.5e4)
common=(--set element.particles=1000 --set element.inertial_number=2e-3 --set element.max_axial_strain=0.25
        --threads 1 --quiet)
epsd=(--set contact.rolling_model=elastic_plastic)
run() {  # name, preset, then options
  local name=$1 preset=$2; shift 2
  local folder="$out/$name"
  [ -f "$folder/element.json" ] && return 0
  rm -rf "$folder"
  "$trapdem" element --preset "$preset" "${common[@]}" "$@" --out "$folder" > "$folder.log" 2>&1 ||
    echo "$name failed (see $folder.log)"
}
for seed in 1 2 3; do
  for dt in 5.36e-6 2.68e-6 1.34e-6 6.7e-7; do
    run "rf1-epsd-dt$dt-seed$seed" paper-rf1 "${soft[@]}" "${epsd[@]}" --set numerics.time_step=$dt --set element.seed=$seed
  done
  for dt in 5.36e-6 1.34e-6 6.7e-7; do
    run "rf1-torque-dt$dt-seed$seed" paper-rf1 "${soft[@]}" --set numerics.time_step=$dt --set element.seed=$seed
  done
  rf1_on_demo=(--set contact.kinetic_friction=0.2 --set contact.rolling_friction=0.2 "${epsd[@]}" --set element.seed=$seed)
  run "demo-rf1-epsd-dtdefault-seed$seed" demo "${rf1_on_demo[@]}"
  run "demo-rf1-epsd-dt3e-7-seed$seed" demo "${rf1_on_demo[@]}" --set numerics.time_step=3e-7
  rf1_torque_on_demo=(--set contact.kinetic_friction=0.2 --set contact.rolling_friction=0.2 --set element.seed=$seed)
  run "demo-rf1-torque-dtdefault-seed$seed" demo "${rf1_torque_on_demo[@]}"
  run "demo-rf1-torque-dt3e-7-seed$seed" demo "${rf1_torque_on_demo[@]}" --set numerics.time_step=3e-7
done
