#!/usr/bin/env bash
# ffeti-solve's "cylinder" key (a contact entry's rigid cylinder, read through the contact
# registry as fetiSetup's obstacleCylinder=): the quarter sphere of getdp/sphere-block.json
# alone, its cut pushed down by 0.05, pressed onto a cylinder of radius 1e6 along y whose top
# is the plane z = 0 (outside, a shaft) and onto the floor z = 0 of a cylinder of radius 1e6
# (inside, a hole), with Tresca friction (0.5 per row), against the same sphere on the rigid
# plane z = 0 ("obstacle"): over the contact zone (x < 1) the cylinders depart from the
# plane by x^2/(2R) < 1e-6 and their normals by x/R < 1e-6, so the contact forces agree to
# 2e-4 of the largest (the friction forces as vectors; measured 1e-4: the stiffness times
# the gaps' departure), a shaft of ten times the radius ten times closer, and each row's
# normal is the cylinder's at its node (1e-6, the table's digits). Bad
# entries are errors naming the file and the key: a zero axis, a negative radius, a missing
# radius, an unknown key, a master group beside the cylinder, a plane problem.
# Usage: cylinder.sh SOURCE_DIR FFETI_SOLVE. Exit 77 (skipped) when GetDP is not installed.
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
cp "$source_dir/getdp/sphere-block.pro" .
gmsh -3 -format msh22 -v 0 "$source_dir/meshes/sphere-block.geo" -o sphere-block.msh
python3 - "$source_dir/getdp/sphere-block.json" <<'PY'
import json, sys
base = json.load(open(sys.argv[1]))
base["subdomains"] = base["subdomains"][:2]
base["bodies"] = base["bodies"][:1]
base["dirichlet"] = [{"group": 3, "components": [0, 1], "value": 0}, {"group": 3, "components": [2], "value": -0.05}]
R = 1e6
base["solver"] = {"tol": 1e-11}  # the forces compared to 1e-4: solved far below that
cases = {
    "plane": {"obstacle": {"point": [0, 0, 0], "normal": [0, 0, 1]}},
    "shaft": {"cylinder": {"point": [0, 0, -R], "axis": [0, 1, 0], "radius": R}},
    "hole": {"cylinder": {"point": [0, 0, R], "axis": [0, 2, 0], "radius": R, "inside": True}},
    "far-shaft": {"cylinder": {"point": [0, 0, -10 * R], "axis": [0, 1, 0], "radius": 10 * R}},
}
for name, support in cases.items():
    problem = json.loads(json.dumps(base))
    problem["contact"] = [dict({"slave": 4, "slip_bound": 0.5}, **support)]
    problem["output"] = {"table": f"{name}.csv"}
    json.dump(problem, open(f"{name}.json", "w"), indent=2)
bad = {
    "zero-axis": ({"cylinder": {"point": [0, 0, -1], "axis": [0, 0, 0], "radius": 1}}, 3,
                  "contact[0].cylinder: the axis [ax, ay, az] must not be zero"),
    "negative-radius": ({"cylinder": {"point": [0, 0, -1], "axis": [0, 1, 0], "radius": -1}}, 3,
                        "contact[0].cylinder: the radius must be > 0, got -1"),
    "missing-radius": ({"cylinder": {"point": [0, 0, -1], "axis": [0, 1, 0]}}, 3, "contact[0].cylinder.radius: missing"),
    "unknown-key": ({"cylinder": {"point": [0, 0, -1], "axis": [0, 1, 0], "radius": 1, "centre": 1}}, 3,
                    "contact[0].cylinder.centre: unknown key"),
    "short-axis": ({"cylinder": {"point": [0, 0, -1], "axis": [0, 1], "radius": 1}}, 3,
                   "contact[0].cylinder.axis: needs 3 numbers, got 2"),
    "with-master": ({"cylinder": {"point": [0, 0, -1], "axis": [0, 1, 0], "radius": 1}, "master": 11}, 3,
                    "contact[0].master: give a master curve or an obstacle, not both"),
    "plane-problem": ({"cylinder": {"point": [0, 0, -1], "axis": [0, 1, 0], "radius": 1}}, 2,
                      "contact[0].cylinder: cylinder contact does not support plane problems yet"),
}
for name, (support, components, message) in bad.items():
    problem = json.loads(json.dumps(base))
    problem["contact"] = [dict({"slave": 4}, **support)]
    if components == 2:
        problem["components"] = 2
        for s in problem["subdomains"]:
            s["surfaces"] = s.pop("volumes")
        problem["dirichlet"] = []
    json.dump(problem, open(f"bad-{name}.json", "w"), indent=2)
    open(f"bad-{name}.expected", "w").write(message)
PY
getdp sphere-block.pro -msh sphere-block.msh -solve Assemble -v 1 > /dev/null
failures=0
for name in plane shaft hole far-shaft; do
  "$ffeti_solve" $name.json > $name-result.txt 2>&1 || true
  grep -q 'status_name=converged' $name-result.txt || { echo "FAILED: $name: $(cat $name-result.txt)"; failures=1; }
done
for expected in bad-*.expected; do
  name=${expected%.expected}
  if "$ffeti_solve" $name.json > $name.txt 2>&1; then
    echo "FAILED: $name accepted"; failures=1
  elif ! grep -qF "$name.json: $(cat $expected)" $name.txt; then
    echo "FAILED: $name: expected '$(cat $expected)', got: $(cat $name.txt)"; failures=1
  else
    echo "ok: $name: $(head -c 200 $name.txt)"
  fi
done
[ "$failures" -eq 0 ] || exit 1
python3 - <<'PY' || failures=1
import csv, math, sys
R = 1e6
def rows(name):
    return {(round(float(r["x"]), 9), round(float(r["y"]), 9), round(float(r["z"]), 9)): r
            for r in csv.DictReader(open(f"{name}.csv")) if r["contact_row"] == "1"}
def friction(r, i):
    axis = "xyz"[i]
    return float(r["friction_force"]) * float(r[f"t1_{axis}"]) + float(r["friction_force_2"]) * float(r[f"t2_{axis}"])
plane = rows("plane")
scale = max(float(r["contact_force"]) for r in plane.values())
ok = scale > 0
difference = {}
for name, axis_z, sign in (("shaft", -R, 1), ("hole", R, -1), ("far-shaft", -10 * R, 1)):
    cylinder = rows(name)
    force = normal = 0.0
    for key, r in cylinder.items():
        x, y, z = key
        d = math.hypot(x, z - axis_z)
        n = (sign * x / d, 0.0, sign * (z - axis_z) / d)
        normal = max(normal, max(abs(float(r[c]) - n[i]) for i, c in enumerate(("n_x", "n_y", "n_z"))))
        p = plane[key]
        # Friction as vectors: the rows' tangent pairs differ (a function of n alone: the plane's
        # t1 is e_x, the cylinder's, n_y being 0 and n_x not, e_y).
        force = max([force, abs(float(r["contact_force"]) - float(p["contact_force"]))] +
                    [abs(friction(r, i) - friction(p, i)) for i in range(3)])
    difference[name] = force / scale
    print(f"{name}: rows={len(cylinder)} (plane {len(plane)}) force_difference={force / scale:.2e} normal_error={normal:.2e}")
    ok &= len(cylinder) == len(plane) and force <= 2e-4 * scale and normal <= 1e-6
# The departure from the plane is x^2/(2R) in the gaps: ten times the radius, a tenth of it.
ok &= difference["far-shaft"] < 0.2 * difference["shaft"]
sys.exit(0 if ok else 1)
PY
[ "$failures" -eq 0 ] && echo "cylinder: all checks passed"
exit $failures
