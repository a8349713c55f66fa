#!/bin/bash
# The h = 0.1 mm speed series of the measured matrix at t0/24 (4.17 um cells, 96 000 particles): does the
# speed trend that shear_localisation found at the two ends at t0/24 (Fc ratio 0.887) hold at every speed?
# Same physics and options as shear_localisation's t0/24 runs (penalty contact, the speed-ends material, crack
# gap, automatic mass scaling); its three t0/24 records (12.6, 100, 381.3 m/min) are copied into records/ and
# re-analysed with the current chip analysis (`mpmcut analyze` on their last snapshot), so only the other four
# speeds run. Resumable: validate keeps complete records and resumes an interrupted run from its checkpoint.
# About 1 core-hour per speed (two at a time, one thread each).
# usage: bash docs/results/validation_t0_24/run.sh MPMCUT   (a copy of build/mpmcut, so no build relinks it)
set -euo pipefail
cd "$(dirname "$0")/../../.."
MPMCUT=$1
"$MPMCUT" validate --h 0.1 --speeds-m-per-min 12.6,39.9,100,150,212.2,318.5,381.3 --cells-per-feed 24 \
  --contact-detection penalty --material-file docs/results/calibration_speed_ends/best_material.toml \
  --out results/validation_t0_24 --records docs/results/validation_t0_24/records --jobs 2 --threads 1
