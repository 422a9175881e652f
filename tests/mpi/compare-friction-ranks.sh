#!/usr/bin/env bash
# Friction on 1, 2 and 3 ranks: the Cattaneo-Mindlin scene (edp/cattaneo-mindlin.edp, both
# load steps and their Coulomb fixed points) must give the serial counts exactly and its
# figures to 1e-8: the fixed point, the bounds and the load steps do not depend on the ranks.
# Usage: compare-friction-ranks.sh SOURCE_DIR   (run where freefem++.pref points at the build)
set -euo pipefail
source_dir=$1
script="$source_dir/edp/cattaneo-mindlin.edp"
args=(-h 0.25 -meshes "$source_dir/meshes")
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1

source "$(dirname "${BASH_SOURCE[0]}")/result-keys.sh"

serial=$(FreeFem++-nw -v 0 "$script" "${args[@]}" | result)
[ -n "$serial" ] || { echo "no RESULT line from the serial run"; exit 1; }
[ "$(value "$serial" status)" = converged ] || { echo "serial run: $(value "$serial" status)"; exit 1; }
for ranks in 2 3; do
  parallel=$(mpirun --oversubscribe -np "$ranks" FreeFem++-mpi -v 0 "$script" "${args[@]}" | result)
  [ -n "$parallel" ] || { echo "no RESULT line with $ranks ranks"; exit 1; }
  same_keys "$ranks ranks" "$serial" "$parallel" status couples sticking slipping fixed_point_iterations \
    fixed_point_iterations_step1 hessian hessian_step1 hessian_frictionless
  close_keys "$ranks ranks" "$serial" "$parallel" 1e-8 stick_ratio a P tangential_force
done
[ "$failures" -eq 0 ] && echo "all checks passed" || { echo "$failures check(s) failed"; exit 1; }
