#!/bin/bash
# The friction sensitivity study: h = 0.1 mm at 12.6, 100 and 381.3 m/min with the penalty contact and the
# speed-ends material, at mu = 0.1, 0.2, 0.35 and 0.5, two runs at a time (1 thread each). Resumable: a complete run
# is kept in records/mu<mu>/<condition> and is not run again.
# usage: bash docs/results/friction_sensitivity/run.sh [MPMCUT]  (default build/mpmcut; validate runs each
# condition with the binary it was started as, so run a copy if a build may relink build/mpmcut meanwhile)
set -euo pipefail
cd "$(dirname "$0")/../../.."
MPMCUT=${1:-build/mpmcut}
HERE=docs/results/friction_sensitivity
mkdir -p results/friction_sensitivity
jobs=()
for c in forces_h0.1mm_vc381.3mpmin forces_h0.1mm_vc12.6mpmin forces_h0.1mm_vc100mpmin; do
  for mu in 0.1 0.2 0.35 0.5; do
    [ -f "$HERE/records/mu$mu/$c/summary.json" ] || jobs+=("$mu $c")
  done
done
printf '%s\n' "${jobs[@]}" | xargs -r -P 2 -L 1 bash -c '
  "$0" validate --material-file docs/results/calibration_speed_ends/best_material.toml --contact-detection penalty \
    --friction "$1" --conditions "$2" --out "results/friction_sensitivity/mu$1_$2" \
    --records "docs/results/friction_sensitivity/records/mu$1" --jobs 1 --threads 1 --no-plots \
    > "results/friction_sensitivity/mu$1_$2.log" 2>&1 || echo "mu $1 $2 failed: results/friction_sensitivity/mu$1_$2.log"
' "$MPMCUT"
