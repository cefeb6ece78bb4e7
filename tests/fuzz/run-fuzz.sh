#!/usr/bin/env bash
# Runs every fuzz target of a `make fuzz` build for FUZZ_SECONDS each, one at a time, niced.
# Usage: tests/fuzz/run-fuzz.sh BUILD_DIR [TARGET...]   (default: every fuzz_* program built)
# Each target starts from its seeds (tests/fuzz/corpus/NAME, plus the binary seeds make_seeds
# writes) and grows its own corpus in BUILD_DIR/corpus/NAME. A finding (crash, sanitizer report,
# escaping exception, hang over FUZZ_TIMEOUT s, more than FUZZ_RSS_MB of memory) is saved as
# BUILD_DIR/findings/NAME-*; the log of each run is BUILD_DIR/logs/NAME.log. Exit status 1 if any
# target had a finding.
set -uo pipefail
build=$(cd "$1" && pwd)
shift
src=$(cd "$(dirname "$0")" && pwd)
seconds=${FUZZ_SECONDS:-600}
timeout_s=${FUZZ_TIMEOUT:-10}
rss_mb=${FUZZ_RSS_MB:-2048}
targets=("$@")
if [ ${#targets[@]} -eq 0 ]; then
  for f in "$build"/fuzz/fuzz_*; do
    name=$(basename "$f")
    [ "$name" = fuzz_make_seeds ] && continue
    targets+=("${name#fuzz_}")
  done
fi
mkdir -p "$build/logs" "$build/findings" "$build/seeds"
case " ${targets[*]} " in
  *" snapshot "*|*" image "*) "$build/fuzz/fuzz_make_seeds" "$build/seeds/snapshot" "$build/seeds/image" || exit 1 ;;
esac
# The HDF5 readers check a file in a child process first (io/hdf5_probe), where a crash is no
# finding. A sanitizer's report there ends the child through its own death callback, but
# libFuzzer's malloc limit would still save the input as the parent's "oom" finding: AddressSanitizer
# refuses an allocation above the limit first (a report, so a finding only in the parent).
# Leaks: -detect_leaks=0 below stops libFuzzer's check after each input, and detect_leaks=0 here
# LeakSanitizer's check at exit, which otherwise reports libhdf5's and OpenCV's own (libhdf5 1.10
# keeps memory on the error paths of damaged files: 7.5 kB in 20 blocks allocated inside
# libhdf5 after 1 736 damaged inputs) and fails the run at its very end. Our code's leaks are
# caught where the corpus is replayed under LeakSanitizer: the fuzz.replay_* tests of `make test-asan`.
export ASAN_OPTIONS="${ASAN_OPTIONS:+$ASAN_OPTIONS:}max_allocation_size_mb=$((rss_mb - 1)):detect_leaks=0"
status=0
printf '%-12s %8s %12s %10s %s\n' target seconds executions corpus findings
for name in "${targets[@]}"; do
  corpus="$build/corpus/$name"
  mkdir -p "$corpus"
  seeds=("$src/corpus/$name")
  [ -d "$build/seeds/$name" ] && seeds+=("$build/seeds/$name")
  # Our code's findings only: leaks inside OpenCV's and HDF5's own caches are theirs, and
  # -detect_leaks=0 keeps a leak from ending the run before the time is up.
  nice -n 10 "$build/fuzz/fuzz_$name" -max_total_time="$seconds" -timeout="$timeout_s" \
    -rss_limit_mb="$rss_mb" -malloc_limit_mb="$rss_mb" -detect_leaks=0 -print_final_stats=1 \
    -artifact_prefix="$build/findings/$name-" "$corpus" "${seeds[@]}" > "$build/logs/$name.log" 2>&1
  rc=$?
  runs=$(grep -o 'stat::number_of_executed_units: *[0-9]*' "$build/logs/$name.log" | grep -o '[0-9]*$')
  files=$(ls "$corpus" | wc -l)
  found=$(ls "$build/findings" | grep -c "^$name-")
  printf '%-12s %8s %12s %10s %s\n' "$name" "$seconds" "${runs:-?}" "$files" "$found"
  if [ $rc -ne 0 ]; then
    status=1
    grep -m3 -E 'ERROR|SUMMARY|Test unit written|uncaught|deadly' "$build/logs/$name.log" | sed 's/^/    /'
  fi
done
exit $status
