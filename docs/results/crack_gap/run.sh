#!/bin/bash
# The crack gap (theory_materials.md 5.3b) against the penalty matrix: the given measured conditions (penalty
# contact, the speed-ends material) run with a binary that has the gap (records/gap/<condition>); resumable, two
# runs at a time.
# usage: bash docs/results/crack_gap/run.sh MPMCUT CONDITION...   (see tools/validate_variants.sh)
set -euo pipefail
cd "$(dirname "$0")/../../.."
MPMCUT=$1; shift
for c in "$@"; do
  echo "gap $c --material-file docs/results/calibration_speed_ends/best_material.toml --contact-detection penalty"
done | tools/validate_variants.sh "$MPMCUT" docs/results/crack_gap/records results/crack_gap
