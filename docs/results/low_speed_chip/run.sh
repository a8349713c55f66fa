#!/bin/bash
# Why does the chip at 12.6 m/min keep thickening with refinement (docs/results/shear_localisation: steady chip
# 143 -> 162 -> 178 -> 202 um from 8 um to t0/32, measured 157)? One change at a time against the t0/16 run of
# shear_localisation (penalty contact, speed-ends material, crack gap, mass scaling to inertia number 0.002):
#   node:     the node contact instead of the penalty contact
#   inertia:  mass scaling to inertia number 0.0005 instead of 0.002 (inertia x ~2200 instead of x 8825)
#   mu0.2:    Coulomb coefficient 0.2 instead of 0.35 (does the sticking rake contact drive the thickening?),
#             also at t0/24 (mu0.2_t0_24)
#   nodamage: the speed-ends material without damage (no_damage_material.toml), at the matrix's cell, t0/16 and
#             t0/24 (nodamage, nodamage_t0_16, nodamage_t0_24), at 12.6 and 381.3 m/min: does the damage softening
#             of the shear zones, whose Hillerborg length is the cell, make the chip depend on the cell?
#   tanh:     the library's ti64-sima-ozel-2010 (Lee & Lin's Johnson-Cook set with the TANH strain softening of
#             Calamaz et al., its own damage) at the matrix's cell, t0/16 and t0/24 (tanh, tanh_t0_16, tanh_t0_24),
#             at 12.6 m/min, at 381.3 m/min at the matrix's cell, t0/16, t0/24 and t0/32, and at t0/16 at 39.9, 100 and
#             150 m/min: does a flow law that softens at large strain make the chip converge, and what does it do
#             to the speed trend?
#   leelin:   its base set without the softening (ti64-lee-lin-1998-sima) at the matrix's cell and t0/16 (leelin,
#             leelin_t0_16): the control, is it the softening or the hardening and damage of that set?
#   rate:     the speed-ends material with Lee & Lin's strain-rate constant C = 0.035 instead of 0.012
#             (rate_material.toml) at the matrix's cell and t0/16 (rate, rate_t0_16): is it the rate sensitivity?
# Two at a time, one thread each. Resumable: a run with a record is not run again, an interrupted one resumes
# from its checkpoint. Records in docs/results/low_speed_chip/records/<variant>/<condition>.
# usage: bash docs/results/low_speed_chip/run.sh MPMCUT [all]   (a copy of build/mpmcut, so no build relinks it)
set -euo pipefail
cd "$(dirname "$0")/../../.."
MPMCUT=$1
c=forces_h0.1mm_vc12.6mpmin c2=forces_h0.1mm_vc381.3mpmin
R=docs/results/low_speed_chip/records OUT=results/low_speed_chip
mkdir -p "$OUT"
material="--material-file docs/results/calibration_speed_ends/best_material.toml"
tanh="--material ti64-sima-ozel-2010 --contact-detection penalty"
leelin="--material ti64-lee-lin-1998-sima --contact-detection penalty"
rate="--material-file docs/results/low_speed_chip/rate_material.toml --contact-detection penalty"
no_damage="--material-file docs/results/low_speed_chip/no_damage_material.toml --contact-detection penalty"
printf '%s\n' "node $c --cells-per-feed 16 $material --contact-detection node" \
  "mu0.2 $c --cells-per-feed 16 $material --contact-detection penalty --friction 0.2" \
  "nodamage $c $no_damage" "nodamage $c2 $no_damage" \
  "nodamage_t0_16 $c --cells-per-feed 16 $no_damage" "nodamage_t0_16 $c2 --cells-per-feed 16 $no_damage" \
  "nodamage_t0_24 $c --cells-per-feed 24 $no_damage" "nodamage_t0_24 $c2 --cells-per-feed 24 $no_damage" \
  "mu0.2_t0_24 $c --cells-per-feed 24 $material --contact-detection penalty --friction 0.2" \
  "tanh $c $tanh" "tanh_t0_16 $c --cells-per-feed 16 $tanh" "tanh_t0_24 $c --cells-per-feed 24 $tanh" \
  "tanh $c2 $tanh" "tanh_t0_16 $c2 --cells-per-feed 16 $tanh" "tanh_t0_24 $c2 --cells-per-feed 24 $tanh" \
  "tanh_t0_32 $c2 --cells-per-feed 32 $tanh" \
  "tanh_t0_16 forces_h0.1mm_vc100mpmin --cells-per-feed 16 $tanh" \
  "tanh_t0_16 forces_h0.1mm_vc150mpmin --cells-per-feed 16 $tanh" \
  "tanh_t0_16 forces_h0.1mm_vc39.9mpmin --cells-per-feed 16 $tanh" \
  "leelin $c $leelin" "leelin_t0_16 $c --cells-per-feed 16 $leelin" \
  "rate $c $rate" "rate_t0_16 $c --cells-per-feed 16 $rate" |
  tools/validate_variants.sh "$MPMCUT" "$R" "$OUT" &
if [ ! -f "$R/inertia/$c/summary.json" ]; then
  # The t0/16 case of validate with only the inertia number changed.
  "$MPMCUT" validate --cells-per-feed 16 $material --contact-detection penalty --conditions $c \
    --out "$OUT/inertia_cases" --list > /dev/null
  case_file=$(ls "$OUT"/inertia_cases/cases/$c.toml 2>/dev/null || true)
  [ -n "$case_file" ] || { echo "run.sh: validate --list wrote no case file"; exit 1; }
  sed 's/^mass_scaling = "auto".*/mass_scaling = "auto"\nmass_scaling_inertia_number = 0.0005  # this study: a quarter of the default/' \
    "$case_file" > "$OUT/inertia_$c.toml"
  "$MPMCUT" run "$OUT/inertia_$c.toml" --out "$OUT/inertia_$c" --threads 1 --keep-complete > "$OUT/inertia_$c.log" 2>&1
  mkdir -p "$R/inertia/$c"
  cp "$OUT/inertia_$c"/{summary.json,forces.csv,scene.toml} "$R/inertia/$c/"
fi
wait
# The sharp-edge runs (one at a time, after the others): run_sharp.sh ("all" adds its t0/24 cell).
bash docs/results/low_speed_chip/run_sharp.sh "$MPMCUT" "${2:-}"
