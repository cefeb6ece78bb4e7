#!/usr/bin/env bash
# Copies what a reader of a study needs, without its snapshots and checkpoints, into a folder to commit or share:
# the report (page, figures, metrics.csv, case_summary.csv, summary.json) where it exists, and for
# every run its run.json, resolved.toml, trapdoor.csv and run.log, with deposit.json and
# analysis/metrics.json and analysis/field_history.h5 (every snapshot's settlement and strain on one
# grid, float32 and compressed: ~0.1-5 MB a run, what a later analysis needs once the snapshots are
# gone) where they exist. Snapshots, checkpoints and the analysis' particle-level fields.h5 stay
# behind (megabytes to gigabytes a run; the run folder keeps them).
#
#   scripts/publish-study.sh STUDY_DIR DEST_DIR [--finished-only] [--figures]
#
# --finished-only: runs whose run.json does not say "complete": true are left out.
# --figures: each run's analysis figures too (analysis/*.png, .svg, .pdf: ~1 MB a run), for runs
#   whose snapshots will not outlive their machine: without them the report draws such a run only
#   in its strain panel, from field_history.h5 (docs/study.md), so these are then its only full
#   pictures.
# The checkout's absolute path in the copied text files (a packing's `from`, the configuration's
# path in resolved.toml and run.log) is written `<checkout>/`: what is published names no machine.
# DEST_DIR's files are replaced one by one (a file that is no longer in the study stays: remove
# DEST_DIR first for an exact copy), but for study.log, whose published lines are kept and the
# study's new ones added after them.
set -euo pipefail
usage() { echo "usage: $0 STUDY_DIR DEST_DIR [--finished-only] [--figures]" >&2; exit 2; }
[ $# -ge 2 ] || usage
study=$1
dest=$2
shift 2
finished_only=0
figures=0
for option in "$@"; do
  case $option in
    --finished-only) finished_only=1 ;;
    --figures) figures=1 ;;
    *) usage ;;
  esac
done
[ -d "$study/cases" ] || { echo "$0: $study holds no study (no cases/ folder)" >&2; exit 1; }
mkdir -p "$dest"

copied=0
checkout=$(cd "$(dirname "$0")/.." && pwd -P)
# Copies FILE to TARGET with the checkout's absolute path replaced by `<checkout>/` (escaped in HTML).
copy_text() {
  local marker='<checkout>/'
  case $1 in *.html) marker='\&lt;checkout\&gt;/' ;; esac
  sed "s|$checkout/|$marker|g" "$1" > "$2"
}
# A run is a folder under cases/ with a resolved.toml (cases/NAME or cases/NAME/seed-S).
while IFS= read -r -d '' resolved; do
  run=$(dirname "$resolved")
  rel=${run#"$study"/}
  if [ $finished_only -eq 1 ] && ! grep -q '"complete": *true' "$run/run.json" 2>/dev/null; then
    continue
  fi
  mkdir -p "$dest/$rel"
  for f in run.json resolved.toml run.log deposit.json; do
    [ -f "$run/$f" ] && copy_text "$run/$f" "$dest/$rel/$f"
  done
  [ -f "$run/trapdoor.csv" ] && cp "$run/trapdoor.csv" "$dest/$rel/trapdoor.csv"
  if [ -f "$run/analysis/metrics.json" ]; then
    mkdir -p "$dest/$rel/analysis"
    cp "$run/analysis/metrics.json" "$dest/$rel/analysis/metrics.json"
  fi
  if [ -f "$run/analysis/field_history.h5" ]; then
    mkdir -p "$dest/$rel/analysis"
    cp "$run/analysis/field_history.h5" "$dest/$rel/analysis/field_history.h5"
  fi
  if [ $figures -eq 1 ] && [ -d "$run/analysis" ]; then
    mkdir -p "$dest/$rel/analysis"
    find "$run/analysis" -maxdepth 1 -type f \( -name '*.png' -o -name '*.svg' -o -name '*.pdf' \) \
      -exec cp {} "$dest/$rel/analysis/" \;
  fi
  copied=$((copied + 1))
done < <(find "$study/cases" -name resolved.toml -print0 | sort -z)

if [ -d "$study/report" ]; then
  mkdir -p "$dest/report"
  for f in "$study/report"/*; do
    [ -f "$f" ] || continue
    case $f in
      *.h5) ;;
      *.html | *.csv | *.json | *.txt) copy_text "$f" "$dest/report/$(basename "$f")" ;;
      *) cp "$f" "$dest/report/" ;;
    esac
  done
fi
[ -f "$study/study.json" ] && copy_text "$study/study.json" "$dest/study.json"
# study.log: the lines published before stay, and this folder's are added after them, each line
# once. A study carried from machine to machine (one case a session, each in a new folder) keeps
# its whole history, whether or not the new folder began from the published log.
if [ -f "$study/study.log" ]; then
  if [ -f "$dest/study.log" ]; then
    merged=$(mktemp "$dest/.study.log.XXXXXX")
    awk '!seen[$0]++' "$dest/study.log" "$study/study.log" > "$merged"
    mv "$merged" "$dest/study.log"
  else
    cp "$study/study.log" "$dest/study.log"
  fi
fi
echo "publish-study: $copied runs and $( [ -d "$study/report" ] && echo "the report" || echo "no report") copied to $dest"
