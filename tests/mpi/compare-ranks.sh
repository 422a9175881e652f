#!/usr/bin/env bash
# Runs the model problem in one process and under mpirun with 2 and 3 ranks (3 does not
# divide the subdomains evenly) and checks that the results do not depend on the rank
# count: equal dimensions and iteration counts, energy and solution norms equal to 1e-10.
# Usage: compare-ranks.sh SOURCE_DIR N   (run where freefem++.pref points at the build)
set -euo pipefail
source_dir=$1
n=$2
script="$source_dir/edp/model-problem.edp"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1

source "$(dirname "${BASH_SOURCE[0]}")/result-keys.sh"

serial=$(FreeFem++-nw -v 0 "$script" -n "$n" | result)
[ -n "$serial" ] || { echo "no RESULT line from the serial run"; exit 1; }
for ranks in 2 3; do
  parallel=$(mpirun --oversubscribe -np "$ranks" FreeFem++-mpi -v 0 "$script" -n "$n" | result)
  [ -n "$parallel" ] || { echo "no RESULT line with $ranks ranks"; exit 1; }
  [ "$(value "$parallel" ranks)" = "$ranks" ] || { echo "ranks key is not $ranks"; failures=$((failures + 1)); }
  same_keys "$ranks ranks" "$serial" "$parallel" status subdomains primal dual couples active floating outer hessian cg expansion
  close_keys "$ranks ranks" "$serial" "$parallel" 1e-10 energy energy_plugin u_norm lambda_norm
done
[ "$failures" -eq 0 ] && echo "all checks passed" || { echo "$failures check(s) failed"; exit 1; }
