#!/usr/bin/env bash
# The seed's membranes through GetDP and ffeti-solve (getdp/membranes.pro, .json: FETI-1,
# floating subdomains, node-to-node contact) against FreeFEM and the plugin on the same
# gmsh mesh (tests/getdp/membranes.edp), at tol = 1e-10: the displacements agree to 1e-6
# relative and the energies to 1e-8.
# Usage: membranes-cross-check.sh SOURCE_DIR FFETI_SOLVE   (in a folder with the tests' freefem++.pref)
# Exit 77 (skipped) when GetDP is not installed.
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
cp "$pref" "$source_dir/getdp/membranes.pro" .
gmsh -2 -format msh22 -v 0 "$source_dir/meshes/membranes.geo" -o membranes.msh
python3 - "$source_dir/getdp/membranes.json" <<'PY'
import json, sys
problem = json.load(open(sys.argv[1]))
problem["solver"]["tol"] = 1e-10
json.dump(problem, open("membranes-tight.json", "w"), indent=2)
PY
getdp_result=$(getdp membranes.pro -msh membranes.msh -setstring solver "$ffeti_solve" \
  -setstring problem membranes-tight.json -solve Membranes -v 1 | grep '^RESULT')
freefem_result=$(FreeFem++-nw -v 0 "$source_dir/tests/getdp/membranes.edp" -mesh membranes.msh -tol 1e-10 \
  -table freefem.csv | grep '^RESULT')
echo "ffeti-solve: $getdp_result" | cut -c1-200
echo "plugin:      $freefem_result" | cut -c1-200
for result in "$getdp_result" "$freefem_result"; do
  grep -q 'status_name=converged' <<< "$result" || { echo "FAILED: not converged: $result"; exit 1; }
done
python3 - "$getdp_result" "$freefem_result" <<'PY'
import csv, sys
def value(line, key):
    return float(line.split(f" {key}=")[1].split()[0])
ffeti = {(r["body"], round(float(r["x"]), 9), round(float(r["y"]), 9)): float(r["u_x"])
         for r in csv.DictReader(open("membranes-ffeti.csv"))}
sums = {}
for r in csv.DictReader(open("freefem.csv")):
    entry = sums.setdefault((r["body"], round(float(r["x"]), 9), round(float(r["y"]), 9)), [0.0, 0])
    entry[0] += float(r["u"]); entry[1] += 1
freefem = {k: v[0] / v[1] for k, v in sums.items()}
failures = 0
if ffeti.keys() != freefem.keys():
    print(f"FAILED: node sets differ ({len(ffeti)} and {len(freefem)})"); failures += 1
common = ffeti.keys() & freefem.keys()
u_error = max(abs(ffeti[k] - freefem[k]) for k in common) / max(abs(v) for v in freefem.values())
e_getdp, e_freefem = value(sys.argv[1], "energy"), value(sys.argv[2], "energy")
e_error = abs(e_getdp - e_freefem) / abs(e_freefem)
for name, error, bound in [("displacement", u_error, 1e-6), ("energy", e_error, 1e-8)]:
    print(f"{'ok' if error <= bound else 'FAILED'}: {name}: relative difference {error:.3e} (bound {bound:g})")
    failures += error > bound
for key in ("variant", "couples", "active", "floating"):
    a, b = sys.argv[1].split(f" {key}=")[1].split()[0], sys.argv[2].split(f" {key}=")[1].split()[0]
    print(f"{'ok' if a == b else 'FAILED'}: {key}: {a} (plugin {b})")
    failures += a != b
sys.exit(1 if failures else 0)
PY
