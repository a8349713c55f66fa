#!/bin/bash
# The yield-and-rate sensitivity study: h = 0.1 mm at 12.6 and 381.3 m/min, penalty contact, the speed-ends material
# with one Johnson-Cook constant changed (materials/<variant>.toml: A x 0.75, A x 1.25, C = 0, C = 0.035;
# records/<variant>/<condition>); resumable, two runs at a time.
# usage: bash docs/results/yield_and_rate/run.sh [MPMCUT]  (default build/mpmcut; see tools/validate_variants.sh)
set -euo pipefail
cd "$(dirname "$0")/../../.."
for v in A1078 C0 A647 C035; do
  for c in forces_h0.1mm_vc381.3mpmin forces_h0.1mm_vc12.6mpmin; do
    echo "$v $c --material-file docs/results/yield_and_rate/materials/$v.toml --contact-detection penalty"
  done
done | tools/validate_variants.sh "${1:-build/mpmcut}" docs/results/yield_and_rate/records results/yield_and_rate
