#!/usr/bin/env bash
# The contact law's batch loops (src/dem/threaded_cpu/pair_sweep.cpp, src/dem/threaded_cpu/wall_sweep.cpp: the loop after
# `#pragma GCC ivdep`) vectorise for every law instance the dispatch compiles. They carry about half
# of a step's time, and a change inside the law that GCC cannot turn into vector code (an aggregate
# copy, a Vec3 passed by reference into an inlined helper) makes every run silently ~15 % slower
# and, through the other contraction of its multiply-adds, no longer byte-identical to the run
# before it. GCC's -fopt-info-vec-all report must say the batch loop vectorised and never
# "couldn't vectorize". The build writes that report as it compiles the file (CMakeLists.txt:
# BUILD_DIR/vectorise-report); the object follows it by the assembler's few seconds. Where the
# report is missing or the object is minutes newer (an object ccache gave back without compiling),
# the file is compiled again with its own flags (compile_commands.json) for a report of its own.
# Usage: vectorised_batch_loops.sh BUILD_DIR SOURCE...
set -euo pipefail
build=$1
shift
scratch=$(mktemp -d "${TMPDIR:-/tmp}/trapdem-vectorised.XXXXXX")
trap 'rm -rf "$scratch"' EXIT
status=0
for source in "$@"; do
  line=$(grep -n '^#pragma GCC ivdep' "$source" | head -1 | cut -d: -f1)
  loop=$((line + 1))
  name=$(basename "$source")
  # The file's compile command (its output sent to /dev/null) and the object it builds.
  { read -r object; read -r command; } < <(/usr/bin/python3 - "$build/compile_commands.json" "$source" <<'PY'
import json, os, shlex, sys
entries = json.load(open(sys.argv[1]))
source = os.path.realpath(sys.argv[2])
for e in entries:
    if os.path.realpath(os.path.join(e["directory"], e["file"])) == source:
        args = shlex.split(e["command"])
        out = args.index("-o")
        print(os.path.join(e["directory"], args[out + 1]))
        args[out + 1] = "/dev/null"
        args = [a for a in args if not a.startswith("-fopt-info")]
        print("cd " + shlex.quote(e["directory"]) + " && " + shlex.join(args))
        break
else:
    sys.exit("not in compile_commands.json: " + source)
PY
)
  report=$build/vectorise-report/$name.txt
  apart=$(( $(stat -c %Y "$object" 2>/dev/null || echo 0) - $(stat -c %Y "$report" 2>/dev/null || echo 0) ))
  if [ -s "$report" ] && [ -f "$object" ] && [ "${apart#-}" -lt 120 ]; then
    echo "$name: the build's report ($report)"
  else
    echo "$name: no report written with $object; compiling it again for one"
    report=$scratch/$name.txt
    bash -c "$command -fopt-info-vec-all=$report"
  fi
  vectorised=$(grep -c "$name:$loop:[0-9]*: optimized: loop vectorized" "$report" || true)
  missed=$(grep -c "$name:$loop:[0-9]*: missed: couldn't vectorize loop" "$report" || true)
  echo "$name:$loop: $vectorised vectorised, $missed not"
  if [ "$vectorised" -eq 0 ] || [ "$missed" -ne 0 ]; then
    echo "FAIL: the batch loop at $source:$loop does not vectorise for every law instance" >&2
    grep -A4 "$name:$loop:[0-9]*: missed: couldn't vectorize loop" "$report" | head -20 >&2
    status=1
  fi
done
exit $status
