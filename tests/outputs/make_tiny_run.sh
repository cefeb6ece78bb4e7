#!/usr/bin/env bash
# Test fixture: a finished run of the tiny preset, shortened as the other tests do (a shallow pour,
# 3 mm of travel, a snapshot every millimetre), analysed, drawn by `trapdem render` and measured by
# the `trapdem piv` line render suggests (camera/piv/piv.h5), in OUT. The ParaView and Python tests
# read it. Usage: make_tiny_run.sh TRAPDEM OUT
set -euo pipefail
trapdem=$1
out=$2
rm -rf "$out"
OMP_NUM_THREADS=1 "$trapdem" run --preset tiny --out "$out" --quiet --threads 1 \
  --set pluviation.fill_height=0.02 --set settling.max_time=0.04 --set trapdoor.travel=0.003 \
  --set "output.snapshot_displacements=[0.0, 0.001, 0.002, 0.003]"
"$trapdem" analyze "$out" > /dev/null
"$trapdem" render "$out" > /dev/null
piv_arguments=$(sed -n 's/^# trapdem piv //p' "$out/camera/scale.txt")
test -n "$piv_arguments"
eval "\"\$trapdem\" piv $piv_arguments" > /dev/null
test -f "$out/snapshots.xmf" && test -f "$out/analysis/fields.xmf" && test -f "$out/camera/piv/piv.h5"
