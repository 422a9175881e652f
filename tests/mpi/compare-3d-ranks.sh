#!/usr/bin/env bash
# Three dimensions in one process and on 2 and 3 ranks: the seed's model problem
# (edp/model-problem-3d.edp, node to node), the Hertz sphere on a block
# (edp/hertz-sphere.edp -block 1, mortar contact; again with scaling = "stiffness", whose
# weights each rank finds for its subdomains and gathers) and the elasticity cubes
# (edp/cubes-elasticity-3d.edp, one stiffness matrix shared by every box through
# stiffnessOf=, each rank holding its boxes' loads): the same dimensions and counts, the
# energy to 1e-10.
# Usage: compare-3d-ranks.sh SOURCE_DIR   (run where freefem++.pref points at the build)
set -euo pipefail
source_dir=$1
script="$source_dir/edp/model-problem-3d.edp"
args=(-n 16 -Hh 4 -reference 0)
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
source "$(dirname "${BASH_SOURCE[0]}")/result-keys.sh"

serial=$(FreeFem++-nw -v 0 "$script" "${args[@]}" | result)
[ -n "$serial" ] || { echo "no RESULT line from the serial run"; exit 1; }
for ranks in 2 3; do
  parallel=$(mpirun --oversubscribe -np "$ranks" FreeFem++-mpi -v 0 "$script" "${args[@]}" | result)
  [ -n "$parallel" ] || { echo "no RESULT line with $ranks ranks"; exit 1; }
  same_keys "$ranks ranks" "$serial" "$parallel" status subdomains primal dual couples active floating outer hessian
  close_keys "$ranks ranks" "$serial" "$parallel" 1e-10 energy
done

sphere="$source_dir/edp/hertz-sphere.edp"
for scaling in multiplicity stiffness; do
  sphere_args=(-h 0.2 -block 1 -meshes "$source_dir/meshes" -scaling "$scaling")
  serial=$(FreeFem++-nw -v 0 "$sphere" "${sphere_args[@]}" | result)
  [ -n "$serial" ] || { echo "no RESULT line from the serial sphere run ($scaling)"; exit 1; }
  for ranks in 2 3; do
    parallel=$(mpirun --oversubscribe -np "$ranks" FreeFem++-mpi -v 0 "$sphere" "${sphere_args[@]}" | result)
    [ -n "$parallel" ] || { echo "no RESULT line from the sphere with $ranks ranks ($scaling)"; exit 1; }
    same_keys "sphere ($scaling), $ranks ranks" "$serial" "$parallel" status subdomains unknowns couples active hessian
    close_keys "sphere ($scaling), $ranks ranks" "$serial" "$parallel" 1e-10 energy a p0
  done
done
cubes="$source_dir/edp/cubes-elasticity-3d.edp"
serial=$(FreeFem++-nw -v 0 "$cubes" -n 16 | result)
[ -n "$serial" ] || { echo "no RESULT line from the serial cubes run"; exit 1; }
for ranks in 2 3; do
  parallel=$(mpirun --oversubscribe -np "$ranks" FreeFem++-mpi -v 0 "$cubes" -n 16 | result)
  [ -n "$parallel" ] || { echo "no RESULT line from the cubes with $ranks ranks"; exit 1; }
  same_keys "cubes, $ranks ranks" "$serial" "$parallel" status subdomains unknowns dual coarse couples active hessian
  close_keys "cubes, $ranks ranks" "$serial" "$parallel" 1e-10 energy
done
[ "$failures" -eq 0 ] && echo "all checks passed" || { echo "$failures check(s) failed"; exit 1; }
