#!/usr/bin/env bash
# The contact law's batch loops (src/dem/threaded_cpu/pair_sweep.cpp, src/dem/threaded_cpu/wall_sweep.cpp: the loop after
# `#pragma GCC ivdep`) vectorise for every law instance the dispatch compiles. They carry about half
# of a step's time, and a change inside the law that GCC cannot turn into vector code (an aggregate
# copy, a Vec3 passed by reference into an inlined helper) makes every run silently ~15 % slower
# and, through the other contraction of its multiply-adds, no longer byte-identical to the run
# before it. Each file is compiled again with its own flags (compile_commands.json) and GCC's
# -fopt-info-vec-all report: the batch loop must be reported vectorised and never "couldn't
# vectorize". Usage: vectorised_batch_loops.sh BUILD_DIR SOURCE...
set -euo pipefail
build=$1
shift
report=$(mktemp -d "${TMPDIR:-/tmp}/trapdem-vectorised.XXXXXX")
trap 'rm -rf "$report"' EXIT
status=0
for source in "$@"; do
  line=$(grep -n '^#pragma GCC ivdep' "$source" | head -1 | cut -d: -f1)
  loop=$((line + 1))
  command=$(/usr/bin/python3 - "$build/compile_commands.json" "$source" <<'PY'
import json, os, shlex, sys
entries = json.load(open(sys.argv[1]))
source = os.path.realpath(sys.argv[2])
for e in entries:
    if os.path.realpath(os.path.join(e["directory"], e["file"])) == source:
        args = shlex.split(e["command"])
        out = args.index("-o")
        args[out + 1] = "/dev/null"
        print("cd " + shlex.quote(e["directory"]) + " && " + shlex.join(args))
        break
else:
    sys.exit("not in compile_commands.json: " + source)
PY
)
  name=$(basename "$source")
  bash -c "$command -fopt-info-vec-all=$report/$name.txt"
  vectorised=$(grep -c "$name:$loop:[0-9]*: optimized: loop vectorized" "$report/$name.txt" || true)
  missed=$(grep -c "$name:$loop:[0-9]*: missed: couldn't vectorize loop" "$report/$name.txt" || true)
  echo "$name:$loop: $vectorised vectorised, $missed not"
  if [ "$vectorised" -eq 0 ] || [ "$missed" -ne 0 ]; then
    echo "FAIL: the batch loop at $source:$loop does not vectorise for every law instance" >&2
    grep -A4 "$name:$loop:[0-9]*: missed: couldn't vectorize loop" "$report/$name.txt" | head -20 >&2
    status=1
  fi
done
exit $status
