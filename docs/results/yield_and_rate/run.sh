#!/bin/bash
# The yield-and-rate sensitivity study: h = 0.1 mm at 12.6 and 381.3 m/min, penalty contact, the speed-ends material
# with one Johnson-Cook parameter changed (materials/*.toml: A x 0.75, A x 1.25, C = 0, C = 0.035), two runs at a
# time (1 thread each). Resumable: a complete run is kept in records/<variant>/<condition> and is not run again.
# usage: bash docs/results/yield_and_rate/run.sh [MPMCUT]  (default build/mpmcut; run a copy if a build may relink it)
set -euo pipefail
cd "$(dirname "$0")/../../.."
MPMCUT=${1:-build/mpmcut}
HERE=docs/results/yield_and_rate
mkdir -p results/yield_and_rate
jobs=()
for v in A1078 C0 A647 C035; do
  for c in forces_h0.1mm_vc381.3mpmin forces_h0.1mm_vc12.6mpmin; do
    [ -f "$HERE/records/$v/$c/summary.json" ] || jobs+=("$v $c")
  done
done
printf '%s\n' "${jobs[@]}" | xargs -r -P 2 -L 1 bash -c '
  "$0" validate --material-file "docs/results/yield_and_rate/materials/$1.toml" --contact-detection penalty \
    --conditions "$2" --out "results/yield_and_rate/$1_$2" \
    --records "docs/results/yield_and_rate/records/$1" --jobs 1 --threads 1 --no-plots \
    > "results/yield_and_rate/$1_$2.log" 2>&1 || echo "$1 $2 failed: results/yield_and_rate/$1_$2.log"
' "$MPMCUT"
