#!/usr/bin/env bash
# Friction in three dimensions on 1, 2 and 3 ranks: the block on a slope (edp/block-on-slope-3d.edp)
# held by Coulomb friction on a rigid plane with the load turned by 30 degrees, slipping
# against a wall under Tresca's law, held on an elastic base by node-to-node friction (four
# subdomains per body, -ny 2) and on a base meshed apart by mortar friction (two per body,
# coarser: its solve takes far more multiplications) must give the serial counts exactly and
# the forces to 1e-8: the tangent pairs and the discs do not depend on how the subdomains are
# spread over the ranks. With -ny 1 (two subdomains) the third rank holds none and still
# reads the plane obstacle as a solid problem's.
# Usage: compare-friction-3d-ranks.sh SOURCE_DIR   (run where freefem++.pref points at the build)
set -euo pipefail
source_dir=$1
script="$source_dir/edp/block-on-slope-3d.edp"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
source "$(dirname "${BASH_SOURCE[0]}")/result-keys.sh"

compare() {
  local label=$1
  shift
  local serial parallel ranks
  serial=$(FreeFem++-nw -v 0 "$script" "$@" | result)
  [ -n "$serial" ] || { echo "no RESULT line from the serial run ($label)"; exit 1; }
  [ "$(value "$serial" status)" = converged ] || { echo "serial run ($label): $(value "$serial" status)"; exit 1; }
  for ranks in 2 3; do
    parallel=$(mpirun --oversubscribe -np "$ranks" FreeFem++-mpi -v 0 "$script" "$@" | result)
    [ -n "$parallel" ] || { echo "no RESULT line with $ranks ranks ($label)"; exit 1; }
    same_keys "$label, $ranks ranks" "$serial" "$parallel" status rows closed sticking slipping \
      fixed_point_iterations hessian
    close_keys "$label, $ranks ranks" "$serial" "$parallel" 1e-8 normal_force friction_force
  done
}

compare "plane, coulomb" -ny 2 -law coulomb -theta 15 -phi 30
compare "plane, tresca" -ny 2 -law tresca
compare "plane, coulomb, a rank without subdomains" -ny 1 -law coulomb -theta 15 -phi 30
compare "base, coulomb" -ny 2 -law coulomb -theta 15 -phi 30 -base 1
compare "mortar base, coulomb" -ny 1 -m 2 -law coulomb -theta 15 -phi 30 -base 2
[ "$failures" -eq 0 ] && echo "all checks passed" || { echo "$failures check(s) failed"; exit 1; }
