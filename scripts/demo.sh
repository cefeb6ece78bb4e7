#!/usr/bin/env bash
# make demo: runs the default experiment (the demo preset) into trapdem-out/demo and prints what it
# measured. An interrupted demo is resumed; a finished one is kept (remove the folder to run again).
set -euo pipefail
build=${1:-build}
out=trapdem-out/demo
trapdem="$build/apps/trapdem"
if [ -f "$out/checkpoint.h5" ] && grep -q '^finished' "$out/run.log" 2>/dev/null; then
  echo "make demo: $out holds a finished demo run (remove the folder to run it again):"
elif [ -f "$out/checkpoint.h5" ]; then
  echo "make demo: resuming the interrupted demo in $out"
  "$trapdem" run --resume "$out"
else
  rm -rf "$out"
  "$trapdem" run --out "$out"
fi
echo
grep -E '^stage [a-z-]+ finished|^finished' "$out/run.log" || true  # the stages' summaries, not the progress lines
echo
"$trapdem" analyze "$out" --incremental
echo
echo "figures: $out/analysis/*.png; fields for ParaView: $out/analysis/fields.xmf and $out/snapshots.xmf"
echo "ground reaction curve: $out/trapdoor.csv; metrics: $out/analysis/metrics.json"
