#!/bin/bash
# The friction sensitivity study: h = 0.1 mm at 12.6, 100 and 381.3 m/min with the penalty contact and the
# speed-ends material, at mu = 0.1, 0.2, 0.35 and 0.5 (records/mu<mu>/<condition>); resumable, two runs at a time.
# usage: bash docs/results/friction_sensitivity/run.sh [MPMCUT]  (default build/mpmcut; see tools/validate_variants.sh)
set -euo pipefail
cd "$(dirname "$0")/../../.."
for c in forces_h0.1mm_vc381.3mpmin forces_h0.1mm_vc12.6mpmin forces_h0.1mm_vc100mpmin; do
  for mu in 0.1 0.2 0.35 0.5; do
    echo "mu$mu $c --material-file docs/results/calibration_speed_ends/best_material.toml --contact-detection penalty --friction $mu"
  done
done | tools/validate_variants.sh "${1:-build/mpmcut}" docs/results/friction_sensitivity/records results/friction_sensitivity
