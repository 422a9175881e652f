#!/usr/bin/env bash
# The quarter sphere on a block (three dimensions) through GetDP and ffeti-solve
# (getdp/sphere-block.pro, .json: tetrahedra, node-to-face contact) against the same problem
# assembled by FreeFEM on the same gmsh mesh and solved by the plugin
# (tests/edp/sphere-block.edp), at tol = 1e-10: displacements, contact forces, energies and
# GetDP's von Mises stresses agree to 1e-6 relative, the contact forces balance the load.
# Then the sphere alone on the rigid plane z = 0 (obstacle with point and normal, the
# sphere's two GetDP systems) both ways, checked the same way.
# Usage: sphere-block-cross-check.sh SOURCE_DIR FFETI_SOLVE   (in a folder with the tests' freefem++.pref)
# Exit 77 (skipped) when GetDP is not installed.
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
cp "$pref" "$source_dir/getdp/sphere-block.pro" .
gmsh -3 -format msh22 -v 0 "$source_dir/meshes/sphere-block.geo" -o sphere-block.msh
python3 - "$source_dir/getdp/sphere-block.json" <<'PY'
import json, sys
problem = json.load(open(sys.argv[1]))
problem["solver"]["tol"] = 1e-10
problem["output"]["stress_table"] = "sphere-block-ffeti-stress.csv"
json.dump(problem, open("sphere-block-tight.json", "w"), indent=2)
# The sphere alone on the plane z = 0: its two systems, its symmetry planes, an obstacle.
problem["subdomains"] = problem["subdomains"][:2]
problem["bodies"] = problem["bodies"][:1]
problem["dirichlet"] = [d for d in problem["dirichlet"] if d["group"] in (1, 2)]
problem["contact"] = [{"slave": 4, "obstacle": {"point": [0, 0, 0], "normal": [0, 0, 1]}}]
problem["output"] = {"table": "obstacle.csv"}
json.dump(problem, open("obstacle.json", "w"), indent=2)
PY
getdp sphere-block.pro -msh sphere-block.msh -setstring solver "$ffeti_solve" -setstring problem sphere-block-tight.json \
  -solve SphereBlock -v 1 | grep '^RESULT' > ffeti-result.txt
"$ffeti_solve" obstacle.json | grep '^RESULT' > obstacle-result.txt || true
FreeFem++-nw -v 0 "$source_dir/tests/edp/sphere-block.edp" -mesh sphere-block.msh -tol 1e-10 -table freefem.csv \
  | grep '^RESULT' > freefem-result.txt || true
FreeFem++-nw -v 0 "$source_dir/tests/edp/sphere-block.edp" -mesh sphere-block.msh -tol 1e-10 -table freefem-obstacle.csv \
  -obstacle 1 | grep '^RESULT' > freefem-obstacle-result.txt || true
failures=0
for result in ffeti-result obstacle-result freefem-result freefem-obstacle-result; do
  grep -q 'status_name=converged' $result.txt || { echo "FAILED: $result: not converged: $(cat $result.txt)"; failures=1; }
done
[ "$failures" -eq 0 ] || exit 1
python3 "$source_dir/tests/getdp/compare_solid.py" sphere-on-block sphere-block-ffeti.csv ffeti-result.txt \
  freefem.csv freefem-result.txt 1e-6 sphere-block-ffeti-stress.csv 'sphere-block-vonmises-*.txt' || failures=1
python3 "$source_dir/tests/getdp/compare_solid.py" sphere-on-plane obstacle.csv obstacle-result.txt \
  freefem-obstacle.csv freefem-obstacle-result.txt 1e-6 || failures=1
exit $failures
