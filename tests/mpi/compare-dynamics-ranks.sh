#!/usr/bin/env bash
# Transient contact on 1, 2 and 3 ranks: the bar on a wall (edp/bar-impact.edp, each rank
# assembling its own subdomains, the energies and momenta summed by fetiSum) must give the
# serial counts exactly and its figures to 1e-8, for one bar, two bars meeting, a bar
# bouncing under gravity and the trapezoidal scheme.
# Usage: compare-dynamics-ranks.sh SOURCE_DIR   (run where freefem++.pref points at the build)
set -euo pipefail
source_dir=$1
script="$source_dir/edp/bar-impact.edp"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1

source "$(dirname "${BASH_SOURCE[0]}")/result-keys.sh"

for case in "-n 40" "-bars 2 -n 20 -dim 3" "-g 2e4 -n 20 -steps 300" "-n 20 -scheme newmark"; do
  read -r -a args <<< "$case"
  serial=$(FreeFem++-nw -v 0 "$script" "${args[@]}" | result)
  [ -n "$serial" ] || { echo "no RESULT line from the serial run of $case"; exit 1; }
  [ "$(value "$serial" status)" = converged ] || { echo "serial run of $case: $(value "$serial" status)"; exit 1; }
  for ranks in 2 3; do
    parallel=$(mpirun --oversubscribe -np "$ranks" FreeFem++-mpi -v 0 "$script" "${args[@]}" | result)
    [ -n "$parallel" ] || { echo "no RESULT line with $ranks ranks ($case)"; exit 1; }
    same_keys "$ranks ranks, $case" "$serial" "$parallel" status impacts steps hessian_per_step_max hessian_total
    close_keys "$ranks ranks, $case" "$serial" "$parallel" 1e-8 contact_time mean_contact_force_per_area \
      rebound_velocity energy_change
  done
done
[ "$failures" -eq 0 ] && echo "all checks passed" || { echo "$failures check(s) failed"; exit 1; }
