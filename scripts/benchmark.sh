#!/usr/bin/env bash
# Benchmarks (not tests: they measure and report). Each writes a page with tables and
# plots into docs/results/ from one run on this machine.
#   ./scripts/benchmark.sh model-problem   numerical scalability, accuracy against time,
#                                          solver variants, direct-solver floor, the dual operator
#                                          against the memory bandwidth (~4 min; "model-problem
#                                          --only bandwidth": that last part alone, ~2 min)
#   ./scripts/benchmark.sh parallel        MPI ranks and OpenMP threads, h = 1/1024 (~3 min)
#   ./scripts/benchmark.sh hertz           cylinder on a block against Hertz, mesh refinement
#   ./scripts/benchmark.sh multibody       three stacked bodies: figures and a von Mises picture
#   ./scripts/benchmark.sh shape-optimization  design loops, gradient costs and checks (~6 min; the 3D section adds an estimated 20, not yet timed idle)
#   ./scripts/benchmark.sh scalability     Hessian multiplications over h up to n = 2048, with and
#                                          without contact, with and without preconditioner (~10 min)
#   ./scripts/benchmark.sh large-contact   a large contact zone: expansion steps, stopping tests,
#                                          against an active set reference (~4 min)
#   ./scripts/benchmark.sh hard-cases      the hard-case suite as a table (~1 min)
#   ./scripts/benchmark.sh accuracy        what accuracy costs in time, every scene, tol 1e-2 .. 1e-10, and a
#                                          design gradient's and design loops' accuracy against tol (~13 min,
#                                          the 3D cubes near a million unknowns about 4 of them; 2.5 GB)
#   ./scripts/benchmark.sh real-meshes     a real mesh (gmsh, METIS parts, node to face) weak scaling to 4.5 million
#                                          unknowns (22 GB, 72 min on a loaded machine), part sizes, the MUMPS peer
#   ./scripts/benchmark.sh dual-operator   the dual operator implicit, explicit and automatic side by side against the
#                                          memory-bandwidth bound: 2D model problem, 3D cubes, the real mesh (~5 min)
#   ./scripts/benchmark.sh factor-rate     the factorizations' GFlop/s on one thread against a dense product (~2 min)
#   ./scripts/benchmark.sh dynamics        transient contact: a bar on a wall, a block sliding to rest (~2 min)
#   ./scripts/benchmark.sh busy-machine    scenes idle and beside busy neighbour processes, threads (~2 min)
#   ./scripts/benchmark.sh friction        Cattaneo-Mindlin and a block on a slope: tractions, stick/slip,
#                                          the Coulomb fixed point's cost against frictionless, and
#                                          the sphere in 3D (~11 min, 1.6 GB: the sphere's default mesh
#                                          of 147k unknowns nine times)
#   ./scripts/benchmark.sh three-dimensions  3D elasticity contact (two cubes) at H/h = 8 up to 17.9 million
#                                          unknowns (16 GB, ~8 min alone): phases, the dual solve's parts, memory, the coarse problem, preconditioners,
#                                          factor kinds; the direct peers (active set method with UMFPACK and
#                                          MUMPS) beside FETI on the cubes and the sphere; the model problem as two cubes up to
#                                          6 million unknowns, factor kinds in 3D, against 2D, Hertz for a
#                                          sphere on a plane and on a block, a rigid ball, the patch test,
#                                          3D gradients and a picture (~30 min, 16 GB, and the peers up to
#                                          about 2 h more: each peer stops at 30 min or 20 GiB; "three-dimensions
#                                          --only PART": one part alone, PART cubes, sphere, elasticity, peers or
#                                          mpi, the largest elasticity case on 1 process and 2 MPI ranks,
#                                          which the full run leaves out)
#   ./scripts/benchmark.sh elasticity-3d   the same as "three-dimensions --only elasticity"
#   ./scripts/benchmark.sh                 all
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
"$root/scripts/setup.sh"
dpkg-query -W -f='${Status}' python3-matplotlib 2>/dev/null | grep -q "install ok installed" || {
  as_root=(); [ "$(id -u)" -eq 0 ] || as_root=(sudo)
  "${as_root[@]}" apt-get install -y -qq python3-matplotlib >/dev/null
}
case "${1:-all}" in
  model-problem) /usr/bin/python3 "$root/scripts/model_problem_benchmark.py" "${@:2}" ;;
  parallel) /usr/bin/python3 "$root/scripts/parallel_benchmark.py" ;;
  hertz) /usr/bin/python3 "$root/scripts/hertz_benchmark.py" ;;
  factor-rate) /usr/bin/python3 "$root/scripts/factor_rate_benchmark.py" ;;
  dual-operator) /usr/bin/python3 "$root/scripts/dual_operator_benchmark.py" ;;
  multibody) /usr/bin/python3 "$root/scripts/multibody_picture.py" ;;
  shape-optimization) /usr/bin/python3 "$root/scripts/shape_optimization_benchmark.py" ;;
  busy-machine) /usr/bin/python3 "$root/scripts/busy_machine_benchmark.py" ;;
  scalability) /usr/bin/python3 "$root/scripts/scalability_benchmark.py" ;;
  large-contact) /usr/bin/python3 "$root/scripts/large_contact_benchmark.py" ;;
  hard-cases) /usr/bin/python3 "$root/scripts/hard_cases_table.py" ;;
  dynamics) /usr/bin/python3 "$root/scripts/dynamics_benchmark.py" ;;
  accuracy) /usr/bin/python3 "$root/scripts/accuracy_benchmark.py" ;;
  friction) /usr/bin/python3 "$root/scripts/friction_benchmark.py" ;;
  three-dimensions) /usr/bin/python3 "$root/scripts/three_dimensions_benchmark.py" "${@:2}" ;;
  elasticity-3d) /usr/bin/python3 "$root/scripts/three_dimensions_benchmark.py" --only elasticity ;;
  real-meshes) /usr/bin/python3 "$root/scripts/real_meshes_benchmark.py" "${@:2}" ;;
  all) /usr/bin/python3 "$root/scripts/model_problem_benchmark.py"
       /usr/bin/python3 "$root/scripts/parallel_benchmark.py"
       /usr/bin/python3 "$root/scripts/hertz_benchmark.py"
       /usr/bin/python3 "$root/scripts/multibody_picture.py"
       /usr/bin/python3 "$root/scripts/shape_optimization_benchmark.py"
       /usr/bin/python3 "$root/scripts/scalability_benchmark.py"
       /usr/bin/python3 "$root/scripts/large_contact_benchmark.py"
       /usr/bin/python3 "$root/scripts/hard_cases_table.py"
       /usr/bin/python3 "$root/scripts/dynamics_benchmark.py"
       /usr/bin/python3 "$root/scripts/accuracy_benchmark.py"
       /usr/bin/python3 "$root/scripts/busy_machine_benchmark.py"
       /usr/bin/python3 "$root/scripts/friction_benchmark.py"
       /usr/bin/python3 "$root/scripts/three_dimensions_benchmark.py"
       /usr/bin/python3 "$root/scripts/real_meshes_benchmark.py"
       /usr/bin/python3 "$root/scripts/factor_rate_benchmark.py"
       /usr/bin/python3 "$root/scripts/dual_operator_benchmark.py" ;;
  *) echo "usage: $0 [model-problem|parallel|hertz|multibody|shape-optimization|scalability|large-contact|hard-cases|dynamics|accuracy|busy-machine|friction|three-dimensions|elasticity-3d|real-meshes|factor-rate|dual-operator]" >&2; exit 2 ;;
esac
