#!/bin/bash
# Shear localisation and the speed trend: the two ends of the h = 0.1 mm speed series (12.6 and 381.3 m/min), and
# 100 m/min between them at t0/24, with the penalty contact and the speed-ends material at finer cells than the
# matrix's (t0/16 and t0/24 against the matrix's r_n/4 = 7.9-8.6 um; t0/32 at the two ends, about 2 core-hours
# each, to see where it converges), to see whether resolving the shear bands lowers Fc more at the high speed.
# Resumable, two runs at a time (records/<variant>/<condition>); an interrupted run resumes from its checkpoint
# (every 30 min of wall time) in results/shear_localisation when this is run again.
# usage: bash docs/results/shear_localisation/run.sh MPMCUT   (see tools/validate_variants.sh)
set -euo pipefail
cd "$(dirname "$0")/../../.."
MPMCUT=$1
common="--material-file docs/results/calibration_speed_ends/best_material.toml --contact-detection penalty"
runs="16:12.6 16:381.3 24:12.6 24:381.3 24:100 32:381.3 32:12.6"
for r in $runs; do
  n=${r%%:*} v=${r#*:}
  echo "t0_$n forces_h0.1mm_vc${v}mpmin --cells-per-feed $n $common"
done | tools/validate_variants.sh "$MPMCUT" docs/results/shear_localisation/records results/shear_localisation
