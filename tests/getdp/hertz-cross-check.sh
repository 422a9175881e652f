#!/usr/bin/env bash
# The Hertz scene through GetDP and ffeti-solve (getdp/hertz.pro, getdp/hertz.json) against
# the same scene through FreeFEM and the plugin (edp/hertz.edp -pair) on the same gmsh mesh
# with the same P1 elements, at tol = 1e-10: displacements, contact forces and GetDP's von
# Mises stresses agree to 1e-6 relative; a and p0 within 5% of Hertz's. The cylinder alone
# on a rigid obstacle against Hertz and the force balance. Then the same
# problem file under mpirun -np 1, 2, 3 and 7 gives the serial result (1e-8 relative).
# Usage: hertz-cross-check.sh SOURCE_DIR FFETI_SOLVE   (in a folder with the tests' freefem++.pref)
# Exit 77 (skipped) when GetDP is not installed.
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
cp "$pref" .
cp "$source_dir/getdp/hertz.pro" .
gmsh -2 -format msh22 -v 0 "$source_dir/meshes/hertz-pair.geo" -o hertz.msh
# The example's problem file at tol = 1e-10, with the element stress table for the check.
python3 - "$source_dir/getdp/hertz.json" <<'PY'
import json, sys
problem = json.load(open(sys.argv[1]))
problem["solver"]["tol"] = 1e-10
problem["output"]["stress_table"] = "hertz-ffeti-stress.csv"
json.dump(problem, open("hertz-tight.json", "w"), indent=2)
PY
# The load ffeti-solve reports is the half model's: half of hertz.pro's Fload = 35000 N/mm.
getdp hertz.pro -msh hertz.msh -setstring solver "$ffeti_solve" -setstring problem hertz-tight.json \
  -solve Hertz -v 1 | grep '^RESULT' | grep 'status_name=converged.* load_x=0 load_y=-17500$'
FreeFem++-nw -v 0 "$source_dir/edp/hertz.edp" -pair hertz.msh -parts 2 -tol 1e-10 -table freefem.csv | grep '^RESULT' \
  | grep 'status=converged'
python3 "$source_dir/tests/getdp/compare_hertz.py" hertz-ffeti.csv freefem.csv hertz-ffeti-stress.csv \
  'hertz-vonmises-*.txt' 1e-6 0.05

# The cylinder alone on a rigid plane (the block's two subdomains dropped, an obstacle
# instead): the contact forces balance the load (1e-8), a and p0 within 5% of Hertz with a
# rigid half-space (E* = E1 / (1 - nu^2)).
python3 - <<'PY'
import json
problem = json.load(open("hertz-tight.json"))
problem["subdomains"] = problem["subdomains"][:2]
problem["bodies"] = problem["bodies"][:1]
problem["dirichlet"] = [{"group": 3, "components": [0]}]
problem["contact"] = [{"slave": 1, "obstacle": {"point": [0, 0], "normal": [0, 1]}}]
problem["output"] = {"table": "obstacle.csv"}
json.dump(problem, open("obstacle.json", "w"), indent=2)
problem["contact"] = [{"slave": 1, "obstacle": {"curve": 11}}]  # the same plane drawn in gmsh: the block's top
problem["output"] = {"table": "obstacle-curve.csv"}
json.dump(problem, open("obstacle-curve.json", "w"), indent=2)
PY
for case in obstacle obstacle-curve; do
  "$ffeti_solve" $case.json | grep '^RESULT' | grep -q 'status_name=converged' || { echo "FAILED: $case"; exit 1; }
done
python3 - <<'PY'
import csv, sys
a = list(csv.DictReader(open("obstacle.csv")))
b = list(csv.DictReader(open("obstacle-curve.csv")))
scale = max(abs(float(r["u_y"])) for r in a)
error = max(abs(float(x[k]) - float(y[k])) for x, y in zip(a, b) for k in ("u_x", "u_y")) / scale
ok = len(a) == len(b) and error <= 1e-9
print(f"{'ok' if ok else 'FAILED'}: obstacle as a physical curve: relative difference {error:.1e} from point and normal (bound 1e-9)")
sys.exit(0 if ok else 1)
PY
python3 - <<'PY'
import csv, math, sys
rows = sorted((r for r in csv.DictReader(open("obstacle.csv")) if r["contact_row"] == "1"), key=lambda r: float(r["x"]))
x = [float(r["x"]) for r in rows]
f = [float(r["contact_force"]) for r in rows]
E1, nu, R, F = 70e3, 0.3, 50.0, 35000.0
a_exact = math.sqrt(4 * F * R / (math.pi * E1 / (1 - nu**2)))
p0_exact = 2 * F / (math.pi * a_exact)
last = max(i for i in range(len(f)) if f[i] > 0)
a, p0 = (x[last] + x[last + 1]) / 2, f[0] / ((x[1] - x[0]) / 2)
checks = [("obstacle: force balance", abs(sum(f) - F / 2) / (F / 2), 1e-8),
          ("obstacle: Hertz a", abs(a - a_exact) / a_exact, 0.05), ("obstacle: Hertz p0", abs(p0 - p0_exact) / p0_exact, 0.05)]
for name, error, bound in checks:
    print(f"{'ok' if error <= bound else 'FAILED'}: {name}: relative difference {error:.3e} (bound {bound:g})")
sys.exit(0 if all(e <= b for _, e, b in checks) else 1)
PY

# Friction from the problem file: the same cylinder on the plane with "friction": 0.3 builds
# friction rows, converges and keeps the force balance; "friction": 0 builds none and gives the
# frictionless contact forces (1e-8), a friction coefficient on a scalar field is refused by name.
python3 - <<'PY'
import json
problem = json.load(open("obstacle.json"))
for mu in (0.3, 0):
    problem["contact"][0]["friction"] = mu
    problem["output"] = {"table": f"friction{mu}.csv"}
    json.dump(problem, open(f"friction{mu}.json", "w"), indent=2)
PY
"$ffeti_solve" friction0.3.json | grep '^RESULT' | grep 'status_name=converged' | grep -q ' friction_rows=[1-9]' \
  || { echo "FAILED: friction 0.3: no converged solve with friction rows"; exit 1; }
# mu = 0 is the frictionless problem itself: no friction rows at all.
result0=$("$ffeti_solve" friction0.json | grep '^RESULT')
echo "$result0" | grep -q 'status_name=converged' && ! echo "$result0" | grep -q ' friction_rows=[1-9]' \
  || { echo "FAILED: friction 0: not a converged solve without friction rows"; exit 1; }
python3 - <<'PY'
import csv, sys
F = 35000.0
plain = {r["node"]: float(r["contact_force"]) for r in csv.DictReader(open("obstacle.csv")) if r["contact_row"] == "1"}
zero = {r["node"]: float(r["contact_force"]) for r in csv.DictReader(open("friction0.csv")) if r["contact_row"] == "1"}
rough = [float(r["contact_force"]) for r in csv.DictReader(open("friction0.3.csv")) if r["contact_row"] == "1"]
scale = max(abs(v) for v in plain.values())
table = [r for r in csv.DictReader(open("friction0.3.csv")) if r["contact_row"] == "1"]
beyond = max(abs(float(r["friction_force"])) - 0.3 * float(r["contact_force"]) for r in table)
states = {r["state"] for r in table if float(r["contact_force"]) > 0}
print(f"{'ok' if states <= {'1', '2'} else 'FAILED'}: friction 0.3: closed rows stick or slip (states {sorted(states)})")
# the bound is mu lambda_n of the last fixed-point iterate: met to the fixed point's tolerance
checks = [("friction 0.3: |friction force| <= 0.3 normal force", max(beyond, 0) / (F / 2), 1e-8),
          ("friction 0.3: force balance", abs(sum(rough) - F / 2) / (F / 2), 1e-8),
          ("friction 0: the frictionless forces", max(abs(plain[n] - zero[n]) for n in plain) / scale, 1e-8)]
for name, error, bound in checks:
    print(f"{'ok' if error <= bound else 'FAILED'}: {name}: relative difference {error:.3e} (bound {bound:g})")
sys.exit(0 if all(e <= b for _, e, b in checks) and plain.keys() == zero.keys() and states <= {'1', '2'} else 1)
PY

# The same problem file under mpirun on 1, 2, 3 and 7 ranks (6 subdomains, spread by size:
# 3-3 on 2 ranks, 2-2-2 on 3, one rank without a subdomain on 7).
failures=0
for ranks in 1 2 3 7; do
  python3 - "$ranks" <<'PY'
import json, sys
problem = json.load(open("hertz-tight.json"))
problem["output"] = {"table": f"ranks{sys.argv[1]}.csv"}
json.dump(problem, open(f"ranks{sys.argv[1]}.json", "w"), indent=2)
PY
  mpirun --oversubscribe -np "$ranks" "$ffeti_solve" "ranks$ranks.json" > "ranks$ranks.out"
  grep '^RESULT' "ranks$ranks.out" | grep -q 'status_name=converged' \
    || { echo "FAILED: $ranks ranks did not converge"; failures=$((failures + 1)); continue; }
  if [ "$ranks" -eq 2 ]; then  # subdomains spread by size: neither rank holds 60 % of the unknowns
    python3 - <<'PY' || failures=$((failures + 1))
import re
primal = [int(v) for v in re.findall(r"^RANK rank=\d+ subdomains=\d+ primal=(\d+)", open("ranks2.out").read(), re.M)]
ok = len(primal) == 2 and max(primal) <= 0.6 * sum(primal)
print(f"{'ok' if ok else 'FAILED'}: 2 ranks hold {primal} unknowns")
raise SystemExit(0 if ok else 1)
PY
  fi
  python3 - "$ranks" <<'PY' || failures=$((failures + 1))
import csv, sys
serial = {r["node"]: r for r in csv.DictReader(open("hertz-ffeti.csv"))}
ranks = {r["node"]: r for r in csv.DictReader(open(f"ranks{sys.argv[1]}.csv"))}
assert serial.keys() == ranks.keys(), "node sets differ"
scale = {k: max(abs(float(r[k])) for r in serial.values()) for k in ("u_x", "u_y", "contact_force")}
error = max(abs(float(serial[n][k]) - float(ranks[n][k])) / scale[k] for n in serial for k in scale)
ok = error <= 1e-8
print(f"{'ok' if ok else 'FAILED'}: {sys.argv[1]} ranks: largest relative difference from the serial run {error:.2e}")
sys.exit(0 if ok else 1)
PY
done
exit $failures
