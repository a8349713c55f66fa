#!/bin/bash
# The speed trend of Fc with other published Johnson-Cook flow-stress sets (docs/results/flow_law_trend).
# Each set keeps ti64-cutting's damage and fracture energy, so that only the flow law differs.
# Resumable: a rerun keeps the complete runs (run --keep-complete). Usage, from the repository root:
#   docs/results/flow_law_trend/run_flow_law_trend.sh [MPMCUT] [OUT] [SETS] [SPEEDS]
set -e
B=${1:-build/mpmcut}
OUT=${2:-results/flow_law_trend}
SETS=${3:-"ti64-seo-2005 ti64-lee-lin-1998 ti64-lesuer-2000 ti64-lee-lin-1998-sima"}
SPEEDS=${4:-"12.6 381.3"}
mkdir -p "$OUT/cases"
# the validation matrix's own case files (cell = min(t0/10, r_n/4), measured edge radius, tip on a node row)
"$B" validate --list -o "$OUT/matrix" > /dev/null
for set in $SETS; do
  for v in $SPEEDS; do
    id=forces_h0.1mm_vc${v}mpmin
    case="$OUT/cases/${set}_${id}.toml"
    sed -e "s/^material = \"ti64-cutting\".*/material = \"cut-${set}\"  # ${set} with ti64-cutting's fracture energy/" \
        "$OUT/matrix/cases/${id}.toml" > "$case"
    cat >> "$case" <<TOML

[[material]]
name = "cut-${set}"
library = "${set}"
fracture_energy = 15.0e3                 # as ti64-cutting (materials/ti6al4v.toml)
fracture_energy_brittle = 5.0e3
fracture_transition_strain_rate = 2.0e6
fracture_transition_exponent = 4.0
TOML
    "$B" run "$case" -o "$OUT/${set}/${id}" --keep-complete --threads 1 --fixed-threads --no-plots --no-progress \
      > "$OUT/${set}_${id}.log" 2>&1 || echo "FAILED: $set $id (see $OUT/${set}_${id}.log)"
  done
done
