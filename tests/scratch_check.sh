#!/usr/bin/env bash
# The suite leaves no scratch (issue 41): `before FILE` lists the trapdem* and tdslurm.* folders in
# /tmp with their modification times (ctest fixture scratch_check's setup, run before every test);
# `after FILE` (its cleanup, run after the last test, also under ctest -j) fails naming each one that
# is new, and each one listed before that the suite wrote into: its modification time changed (an
# entry made or removed in it, or the folder removed and made again) or something inside it is newer
# than FILE. That is a test reusing a folder of a fixed name instead of a scratch folder of its own
# (tests/scratch_dir.hpp). A folder another trapdem suite on the same host makes or writes meanwhile
# counts too: run one suite at a time. SCRATCH_CHECK_ROOT replaces /tmp (for tests/scratch_check_test.sh).
set -euo pipefail
[ $# -eq 2 ] || { echo "usage: $0 before|after FILE" >&2; exit 2; }
root=${SCRATCH_CHECK_ROOT:-/tmp}
# One line per folder: its path, a tab, its modification time (seconds since 1970, nanoseconds).
list() { find "$root" -maxdepth 1 -mindepth 1 \( -name 'trapdem*' -o -name 'tdslurm.*' \) -printf '%p\t%T@\n' | sort; }
case "$1" in
  before) list > "$2" ;;
  after)
    [ -f "$2" ] || { echo "scratch_check: $2 missing (the before step did not run)" >&2; exit 1; }
    now=$(list)
    left=$(awk -F'\t' 'NR == FNR { before[$1]; next } !($1 in before) { print $1 }' "$2" - <<< "$now")
    changed=$(awk -F'\t' 'NR == FNR { before[$1] = $2; next } ($1 in before) && before[$1] != $2 { print $1 }' \
                "$2" - <<< "$now")
    # Kept the same time but written deeper down (a file rewritten in a subfolder).
    while IFS=$'\t' read -r folder _; do
      [ -n "$folder" ] && [ -d "$folder" ] || continue
      grep -qxF "$folder" <<< "$changed" && continue
      if [ -n "$(find "$folder" -mindepth 1 -newer "$2" -print -quit 2>/dev/null)" ]; then
        changed+=${changed:+$'\n'}$folder
      fi
    done < "$2"
    rm -f "$2"
    status=0
    if [ -n "$left" ]; then
      echo "scratch_check: the suite left these in $root (a test that does not remove its scratch):" >&2
      echo "$left" >&2
      status=1
    fi
    if [ -n "$changed" ]; then
      echo "scratch_check: the suite wrote into these, which were in $root before it (a test reusing a folder" \
           "of a fixed name instead of a scratch folder of its own, tests/scratch_dir.hpp):" >&2
      echo "$changed" >&2
      status=1
    fi
    [ "$status" -eq 0 ] && echo "scratch_check: no new or reused trapdem* or tdslurm.* folder in $root"
    exit "$status" ;;
  *) echo "usage: $0 before|after FILE" >&2; exit 2 ;;
esac
