#!/usr/bin/env bash
# tests/scratch_check.sh on a made-up /tmp (SCRATCH_CHECK_ROOT): it passes when the folders listed
# before are untouched, and fails naming the folder when one is new, when one listed before was
# written into (an entry added, the folder made again, a file rewritten deeper down), and not when
# another folder was. Usage: scratch_check_test.sh SCRIPT
set -euo pipefail
[ $# -eq 1 ] || { echo "usage: $0 SCRATCH_CHECK_SCRIPT" >&2; exit 2; }
script=$1
work=$(mktemp -d /tmp/trapdem-scratch-check-XXXXXX)
trap 'rm -rf "$work"' EXIT
export SCRATCH_CHECK_ROOT=$work/tmp
failures=0

# A fresh made-up /tmp: an old fixed-name folder with a subfolder, and a folder no test owns.
setup() {
  rm -rf "$SCRATCH_CHECK_ROOT"
  mkdir -p "$SCRATCH_CHECK_ROOT/trapdem-fixed/sub" "$SCRATCH_CHECK_ROOT/other"
  echo old > "$SCRATCH_CHECK_ROOT/trapdem-fixed/sub/file.txt"
  touch -d '2020-01-01' "$SCRATCH_CHECK_ROOT/trapdem-fixed/sub/file.txt" "$SCRATCH_CHECK_ROOT/trapdem-fixed/sub" \
    "$SCRATCH_CHECK_ROOT/trapdem-fixed"
  bash "$script" before "$work/before.txt"
}

# check NAME EXPECTED_STATUS [TEXT]: runs `after`; its exit status must be EXPECTED_STATUS and its
# output must hold TEXT.
check() {
  local name=$1 expected=$2 text=${3:-} status=0 said
  said=$(bash "$script" after "$work/before.txt" 2>&1) || status=$?
  if [ "$status" -ne "$expected" ] || ! grep -qF -- "$text" <<< "$said"; then
    echo "FAIL $name: exit $status (expected $expected), output:"; echo "$said"
    failures=$((failures + 1))
  else
    echo "ok   $name"
  fi
}

setup
check untouched 0 "no new or reused"

setup
mkdir "$SCRATCH_CHECK_ROOT/trapdem-new-abc123"
check "a new folder" 1 "$SCRATCH_CHECK_ROOT/trapdem-new-abc123"

setup
echo x > "$SCRATCH_CHECK_ROOT/trapdem-fixed/written.txt"
check "an entry added to a folder listed before" 1 "$SCRATCH_CHECK_ROOT/trapdem-fixed"

setup
rm -rf "$SCRATCH_CHECK_ROOT/trapdem-fixed"
mkdir -p "$SCRATCH_CHECK_ROOT/trapdem-fixed/sub"
check "a folder listed before removed and made again" 1 "$SCRATCH_CHECK_ROOT/trapdem-fixed"

setup
sleep 0.05  # a clearly later time than the before-file's
echo new > "$SCRATCH_CHECK_ROOT/trapdem-fixed/sub/file.txt"
check "a file rewritten deeper down" 1 "$SCRATCH_CHECK_ROOT/trapdem-fixed"

setup
echo x > "$SCRATCH_CHECK_ROOT/other/file.txt"
check "a folder that is not trapdem's" 0 "no new or reused"

[ "$failures" -eq 0 ] || { echo "$failures check(s) failed"; exit 1; }
echo "PASS: scratch_check.sh flags new and reused folders"
