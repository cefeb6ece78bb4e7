#!/usr/bin/env bash
# The suite leaves no scratch (issue 41): `before FILE` lists the trapdem* and tdslurm.* folders in
# /tmp (ctest fixture scratch_check's setup, run before every test), `after FILE` (its cleanup, run
# after the last test, also under ctest -j) fails naming each one that is new. A folder another
# trapdem suite on the same host makes meanwhile counts as new too: run one suite at a time.
set -euo pipefail
[ $# -eq 2 ] || { echo "usage: $0 before|after FILE" >&2; exit 2; }
list() { find /tmp -maxdepth 1 -mindepth 1 \( -name 'trapdem*' -o -name 'tdslurm.*' \) -print | sort; }
case "$1" in
  before) list > "$2" ;;
  after)
    [ -f "$2" ] || { echo "scratch_check: $2 missing (the before step did not run)" >&2; exit 1; }
    left=$(list | comm -13 "$2" -)
    rm -f "$2"
    if [ -n "$left" ]; then
      echo "scratch_check: the suite left these in /tmp (a test that does not remove its scratch):" >&2
      echo "$left" >&2
      exit 1
    fi
    echo "scratch_check: no new trapdem* or tdslurm.* folder in /tmp" ;;
  *) echo "usage: $0 before|after FILE" >&2; exit 2 ;;
esac
