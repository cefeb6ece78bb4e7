#!/usr/bin/env bash
# Test fixture: a finished run of the tiny preset with dimers (particles.shape, issue 39), shortened
# as make_tiny_run.sh does (a shallow pour, 3 mm of travel, a snapshot every millimetre), and
# analysed: the ParaView test reads its snapshots (member spheres with their body) and its fields
# (one node per body). Usage: make_tiny_clump_run.sh TRAPDEM OUT
set -euo pipefail
trapdem=$1
out=$2
rm -rf "$out"
OMP_NUM_THREADS=1 "$trapdem" run --preset tiny --out "$out" --quiet --threads 1 \
  --set 'particles.shape.kind="dimer"' --set particles.shape.aspect=1.5 \
  --set pluviation.fill_height=0.02 --set settling.max_time=0.04 --set trapdoor.travel=0.003 \
  --set "output.snapshot_displacements=[0.0, 0.001, 0.002, 0.003]"
"$trapdem" analyze "$out" > /dev/null
test -f "$out/snapshots.xmf" && test -f "$out/analysis/fields.xmf"
