#!/bin/bash
# The serrated -> discontinuous speed series at the two finest grids (issue 11, item 2): the default cut
# (cases/ti64_default.toml: ti64-cutting, h = 0.1 mm, 0 deg rake, 5 um edge, mu = 0.35, 0.4 mm of cut) at 20, 50,
# 100 and 200 m/s, at t0/16 and t0/24. Rerun of the b498cf9 series with today's model (crack gap) and chip analysis
# (the steady chip, the entry left out; one-station dips bridged). About 1 core-hour in all (t0/24 at 20 m/s is
# half of it). Resumable: sweep keeps complete cases and resumes interrupted ones from their checkpoints.
# usage: bash docs/results/transition/run.sh MPMCUT [JOBS]   (a copy of build/mpmcut, so no build relinks it)
set -euo pipefail
cd "$(dirname "$0")/../../.."
MPMCUT=$1
"$MPMCUT" sweep cases/ti64_default.toml --speeds 20,50,100,200 --cells-per-feed 16,24 --jobs "${2:-1}" \
  --out results/transition
