#!/bin/bash
# Issue 39's density check: spheres with RF3's law (the shape study's "rolling") from a deposit as
# dense as the dimers' (199 mm at 50 g against rolling's own 222 mm). The deposit: the demo pour
# with low contact friction (mu 0.02, no rolling resistance) and restitution 0.6 (frictionless
# beads at e 0.9 splash out of the box), settled at 1 g (its snapshot 1); then RF3's law settles it
# again at 1 g, spins it up and lowers the door, as equal-density-demo.toml does. Seed 2019.
# Run from the checkout: bash docs/results/shape-dense-rolling/run.sh [THREADS]
set -euo pipefail
threads=${1:-2}
out=trapdem-out/shape-dense-rolling
build/apps/trapdem run --preset demo --threads "$threads" --quiet --out "$out/deposit-2019" \
  --set contact.static_friction=0.02 --set contact.kinetic_friction=0.02 --set contact.rolling_friction=0 \
  --set contact.restitution=0.6
build/apps/trapdem run --preset demo --threads "$threads" --quiet --out "$out/rolling-2019" \
  --set contact.static_friction=0.18 --set contact.kinetic_friction=0.5 --set contact.rolling_friction=0.4 \
  --set "packing.from=\"$PWD/$out/deposit-2019\"" --set 'packing.format="trapdem"' --set packing.snapshot=1 \
  --set 'packing.start_stage="settling"'
build/apps/trapdem analyze "$out/deposit-2019" --quiet
build/apps/trapdem analyze "$out/rolling-2019" --quiet
