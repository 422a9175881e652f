#!/usr/bin/env bash
# ffeti-solve's "friction" key in three dimensions: the quarter sphere pressed on the block
# (getdp/sphere-block.json: node to face, the block's flat top z = 0 the master) and on the
# rigid plane z = 0 (an obstacle), each with Tresca friction (a bound of 0.5 per row), the
# sphere's cut pushed down, without the quarter model's symmetry planes (friction refuses a
# slave held along one of its tangents only). Both converge, and
# the table gives per slave node n = e_z, t1 = e_x, t2 = e_y (the top's and the plane's,
# known here), friction forces inside the disc ||lambda_t|| <= 0.5 (1e-9 of the largest
# contact force), and on
# the plane the slip along t1 and t2 is (u_x, u_y) of the node (the plane does not move; to
# the table's 6 digits).
# The views file holds the friction views. A problem mixing "friction" and "slip_bound" is
# refused.
# Usage: friction-3d.sh SOURCE_DIR FFETI_SOLVE. Exit 77 (skipped) when GetDP is not installed.
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
cp "$source_dir/getdp/sphere-block.pro" .
gmsh -3 -format msh22 -v 0 "$source_dir/meshes/sphere-block.geo" -o sphere-block.msh
python3 - "$source_dir/getdp/sphere-block.json" <<'PY'
import json, sys
problem = json.load(open(sys.argv[1]))
# No symmetry planes: the sphere's cut z = R pushed down by 0.05, the block's bottom fixed.
pushed = [{"group": 3, "components": [0, 1], "value": 0}, {"group": 3, "components": [2], "value": -0.05}]
problem["dirichlet"] = pushed + [{"group": 14}]
problem["contact"][0]["slip_bound"] = 0.5
problem["output"] = {"table": "block.csv", "views": "block.msh"}
json.dump(problem, open("block.json", "w"), indent=2)
plane = json.loads(json.dumps(problem))
plane["subdomains"] = plane["subdomains"][:2]
plane["bodies"] = plane["bodies"][:1]
plane["dirichlet"] = pushed
plane["contact"] = [{"slave": 4, "obstacle": {"point": [0, 0, 0], "normal": [0, 0, 1]}, "slip_bound": 0.5}]
plane["output"] = {"table": "plane.csv"}
json.dump(plane, open("plane.json", "w"), indent=2)
mixed = json.loads(json.dumps(problem))
mixed["contact"].append({"slave": 5, "obstacle": {"point": [0, 0, -9], "normal": [0, 0, 1]}, "friction": 0.3})
json.dump(mixed, open("mixed.json", "w"), indent=2)
PY
# GetDP assembles the systems and the dof map (its Assemble resolution: no solve).
getdp sphere-block.pro -msh sphere-block.msh -solve Assemble -v 1 > /dev/null
failures=0
for name in block plane; do
  "$ffeti_solve" $name.json > $name-result.txt 2>&1 || true
  grep -q 'status_name=converged' $name-result.txt || { echo "FAILED: $name: $(cat $name-result.txt)"; failures=1; }
done
if "$ffeti_solve" mixed.json > mixed.txt 2>&1 || ! grep -q "one law per problem" mixed.txt; then
  echo "FAILED: friction and slip_bound in one problem not refused: $(cat mixed.txt)"; failures=1
fi
[ "$failures" -eq 0 ] || exit 1
python3 - <<'PY' || failures=1
import csv, sys
ok = True
for name, plane in (("block", False), ("plane", True)):
    rows = [r for r in csv.DictReader(open(f"{name}.csv")) if r["contact_row"] == "1"]
    closed = slipping = 0
    frame = slip = disc = slip_scale = 0.0
    for r in rows:
        v = {k: float(r[k]) for k in r if k not in ("node", "body")}
        frame = max(frame, abs(v["n_x"]) + abs(v["n_y"]) + abs(v["n_z"] - 1), abs(v["t1_x"] - 1) + abs(v["t1_y"]) + abs(v["t1_z"]),
                    abs(v["t2_x"]) + abs(v["t2_y"] - 1) + abs(v["t2_z"]))
        force = (v["friction_force"] ** 2 + v["friction_force_2"] ** 2) ** 0.5
        disc = max(disc, force - 0.5)
        closed += v["contact_force"] > 0
        slipping += int(r["state"]) == 2
        if plane:
            slip = max(slip, abs(v["slip"] - v["u_x"]) + abs(v["slip_2"] - v["u_y"]))
            slip_scale = max(slip_scale, abs(v["u_x"]) + abs(v["u_y"]))
    scale = max(float(r["contact_force"]) for r in rows)
    print(f"{name}: rows={len(rows)} closed={closed} slipping={slipping} frame_error={frame:.2e} "
          f"disc_excess={disc / scale:.2e} slip_error={slip:.2e} of {slip_scale:.2e}")
    # The table's numbers have 6 significant digits.
    ok &= len(rows) > 0 and closed > 0 and frame < 1e-12 and disc <= 1e-9 * scale and slip <= 1e-5 * slip_scale
    ok &= not plane or slip_scale > 0
sys.exit(0 if ok else 1)
PY
for view in "friction force along t2" "slip along t2" "tangent t2" "contact normal"; do
  grep -q "\"$view\"" block.msh || { echo "FAILED: no view '$view' in block.msh"; failures=1; }
done
[ "$failures" -eq 0 ] && echo "friction-3d: all checks passed"
exit $failures
