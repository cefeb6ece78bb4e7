#!/bin/bash
# Issue 39: the element test (biaxial, 50 kPa, 1000 grains, mu 0.5, no rolling resistance) on
# clumps, run from this folder with trapdem on the PATH. Each specimen takes 2-8 minutes on one
# core of a Zen 5 (dimers the least, sub-angular grains of 7 spheres the most).
set -euo pipefail
run() { trapdem element base.toml --threads 1 --quiet "$@"; }
dimer() { echo --set 'particles.shape.kind="dimer"' --set "particles.shape.aspect=$1"; }

# Session 2026-12-06 00:27: dimers of aspect 1.5, dense and loose.
run --out dimer $(dimer 1.5)

# Session 2026-12-06 04:16: the shapes' critical state and the preparation friction (element.packings).
run --out dimer-prep $(dimer 1.5) --set 'element.packings=["mu_prep=0.15","mu_prep=0.3"]'
run --out dimer18 $(dimer 1.8) --set 'element.packings=["loose","mu_prep=0.15"]'
run --out tetrahedral --set 'particles.shape.kind="tetrahedral"' --set 'element.packings=["loose","mu_prep=0.15"]'
run --out sub-angular --set 'particles.shape.kind="sub_angular"' --set 'element.packings=["loose","mu_prep=0.15"]'
run --out sub-angular-r035 --set 'particles.shape.kind="sub_angular"' --set particles.shape.satellite_radius=0.35 \
    --set 'element.packings=["loose","mu_prep=0.15"]'

# Table 1's sands (coarse: phi'_peak 39.0, phi'_cs 32.0 deg; fine: 42.3, 34.8 deg): the candidates
# at their preparation friction, three gas seeds each.
for seed in 1 2 3; do
  run --out coarse-dimer15-s$seed $(dimer 1.5) --set 'element.packings=["mu_prep=0.22"]' --set element.seed=$seed
  run --out coarse-dimer15-p018-s$seed $(dimer 1.5) --set 'element.packings=["mu_prep=0.18"]' --set element.seed=$seed
  run --out fine-dimer18-s$seed $(dimer 1.8) --set 'element.packings=["mu_prep=0.2"]' --set element.seed=$seed
  run --out fine-dimer18-p017-s$seed $(dimer 1.8) --set 'element.packings=["mu_prep=0.17"]' --set element.seed=$seed
  run --out fine-subang035-s$seed --set 'particles.shape.kind="sub_angular"' --set particles.shape.satellite_radius=0.35 \
      --set 'element.packings=["mu_prep=0.25"]' --set element.seed=$seed
done
