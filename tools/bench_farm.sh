#!/usr/bin/env bash
# Overhead of the MPI task farm: N coarse cases on 2 worker ranks (mpirun -n 3: rank 0 only hands out)
# against the local pool with --jobs 2. Not a test: run it on a quiet machine, e.g.
#   tools/bench_farm.sh build/mpmcut 8
# Prints both wall times and the difference per case.
set -euo pipefail
binary=${1:-build/mpmcut}
n=${2:-8}
speeds=$(seq -s, 10 5 $((10 + 5 * (n - 1))))
out=$(mktemp -d)
args=(sweep "$(dirname "$0")/../cases/ti64_quick.toml" --speeds "$speeds" --set cutting.cut_length=40e-6
      --set cutting.cell_size=25e-6 --no-plots)
root=()
[ "$(id -u)" -eq 0 ] && root=(--allow-run-as-root)
t0=$(date +%s.%N)
"$binary" "${args[@]}" --jobs 2 --out "$out/local" >/dev/null
t1=$(date +%s.%N)
mpirun "${root[@]}" --oversubscribe --bind-to none -n 3 "$binary" "${args[@]}" --out "$out/mpi" >/dev/null
t2=$(date +%s.%N)
awk -v a="$t0" -v b="$t1" -v c="$t2" -v n="$n" 'BEGIN {
  printf "local --jobs 2: %.1f s; mpirun -n 3 (2 workers): %.1f s; farm overhead %.2f s per case (%d cases)\n",
         b - a, c - b, ((c - b) - (b - a)) / n, n }'
rm -rf "$out"
