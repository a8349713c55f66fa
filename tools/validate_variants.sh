#!/bin/bash
# Runs the variants of a sensitivity study: measured conditions of the validation matrix, each with some
# `mpmcut validate` options changed, two runs at a time (1 thread each). Resumable: a run whose record
# RECORDS/<variant>/<condition>/summary.json exists is not run again; each run's result directory and log go to
# OUT/<variant>_<condition>. Used by the run.sh of the studies in docs/results (friction_sensitivity,
# yield_and_rate, crack_gap).
# usage: tools/validate_variants.sh MPMCUT RECORDS OUT < JOBS
#   JOBS: one line per run, "<variant> <condition> <validate options...>" (options without spaces inside)
#   MPMCUT: validate runs each condition with the binary it was started as; use a copy of build/mpmcut if a build
#   may relink it meanwhile.
set -euo pipefail
MPMCUT=$1 RECORDS=$2 OUT=$3
mkdir -p "$OUT"
while read -r variant condition options; do
  [ -n "$variant" ] || continue
  [ -f "$RECORDS/$variant/$condition/summary.json" ] || echo "$variant $condition $options"
done | xargs -r -P 2 -L 1 bash -c '
  MPMCUT=$0 RECORDS=$1 OUT=$2 variant=$3 condition=$4; shift 4
  "$MPMCUT" validate "$@" --conditions "$condition" --out "$OUT/${variant}_$condition" \
    --records "$RECORDS/$variant" --jobs 1 --threads 1 --no-plots > "$OUT/${variant}_$condition.log" 2>&1 ||
    echo "$variant $condition failed: $OUT/${variant}_$condition.log"
' "$MPMCUT" "$RECORDS" "$OUT"
