#!/bin/bash
# Part of run.sh: is the chip's growth with refinement at 12.6 m/min tied to how finely the cells resolve the
# measured edge (r_n = 31.5 um: 4, 5 and 7.5 cells across it at the matrix's cell, t0/16 and t0/24)? The no-damage
# runs again with a sharp edge, r_n = 5 um (not a measured tool), at the same cells: 7.875 um (the matrix's) and
# 6.25 um (t0/16), and 4.17 um (t0/24) when given "all". One run at a time, one thread; resumable (a run with a
# record is skipped; `run --keep-complete` resumes an interrupted one from its checkpoint).
# usage: bash docs/results/low_speed_chip/run_sharp.sh MPMCUT [all]
set -euo pipefail
cd "$(dirname "$0")/../../.."
MPMCUT=$1
c=forces_h0.1mm_vc12.6mpmin R=docs/results/low_speed_chip/records OUT=results/low_speed_chip
mkdir -p "$OUT"
cells="7.875e-06 6.25e-06"
[ "${2:-}" = all ] && cells="$cells 4.1666666666666665e-06"
for cell in $cells; do
  variant=sharp_nodamage_cell$cell
  [ -f "$R/$variant/$c/summary.json" ] && continue
  # The matrix case of the no-damage study, with only the edge radius and the cell changed.
  "$MPMCUT" validate --material-file docs/results/low_speed_chip/no_damage_material.toml --contact-detection penalty \
    --conditions $c --out "$OUT/sharp_cases" --list > /dev/null
  case_file="$OUT/sharp_cases/cases/$c.toml"
  [ -f "$case_file" ] || { echo "run_sharp.sh: validate --list wrote no case file"; exit 1; }
  sed -e "s/^edge_radius = .*/edge_radius = 5e-06  # this study: a sharp edge, not the measured r_n/" \
      -e "s/^cell_size = .*/cell_size = $cell  # this study: the cell of the r_n = 31.5 um run it is compared with/" \
      "$case_file" > "$OUT/$variant.toml"
  grep -q "^edge_radius = 5e-06" "$OUT/$variant.toml" && grep -q "^cell_size = $cell" "$OUT/$variant.toml" ||
    { echo "run_sharp.sh: could not set the edge radius and cell in $OUT/$variant.toml"; exit 1; }
  "$MPMCUT" run "$OUT/$variant.toml" --out "$OUT/$variant" --threads 1 --keep-complete > "$OUT/$variant.log" 2>&1
  mkdir -p "$R/$variant/$c"
  cp "$OUT/$variant"/{summary.json,forces.csv,scene.toml} "$R/$variant/$c/"
done
