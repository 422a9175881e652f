#!/usr/bin/env bash
# ffeti-solve on bad input for a solid ("components": 3, getdp/sphere-block.json): each case
# must exit with status 2 and a message naming the key or the element and what is wrong,
# never a crash. The unchanged problem runs first (status 0), so that every refusal below
# is the edit's doing.
# Usage: bad-input-3d.sh SOURCE_DIR FFETI_SOLVE.  Exit 77 (skipped) when GetDP is not installed.
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
cp "$source_dir/getdp/sphere-block.pro" "$source_dir/getdp/sphere-block.json" .
gmsh -3 -format msh22 -v 0 "$source_dir/meshes/sphere-block.geo" -o sphere-block.msh
gmsh -2 -format msh22 -v 0 "$source_dir/meshes/hertz-pair.geo" -o plane.msh
getdp sphere-block.pro -msh sphere-block.msh -solve Assemble -v 0
# Two meshes with one tetrahedron of volume 202 made flat: its fourth node moved onto the
# plane of the other three (exactly, and 1e-12 of the edge length off it).
python3 - <<'PY'
lines = open("sphere-block.msh").read().split("\n")
nodes_at = lines.index("$Nodes") + 2
elements_at = lines.index("$Elements") + 2
node_line = {}
for i in range(nodes_at, lines.index("$EndNodes")):
    node_line[int(lines[i].split()[0])] = i
tet = next(l.split() for l in lines[elements_at:] if len(l.split()) > 4 and l.split()[1] == "4" and l.split()[3] == "202")
a, b, c, d = (int(t) for t in tet[-4:])
p = {n: [float(v) for v in lines[node_line[n]].split()[1:4]] for n in (a, b, c)}
centre = [(p[a][k] + p[b][k] + p[c][k]) / 3 for k in range(3)]
u = [p[b][k] - p[a][k] for k in range(3)]
v = [p[c][k] - p[a][k] for k in range(3)]
n = [u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]]
size = sum(x * x for x in u) ** 0.5
norm = sum(x * x for x in n) ** 0.5
for name, offset in (("flat.msh", 0.0), ("nearly-flat.msh", 1e-12 * size)):
    moved = list(lines)
    moved[node_line[d]] = f"{d} " + " ".join(repr(centre[k] + offset * n[k] / norm) for k in range(3))
    open(name, "w").write("\n".join(moved))
PY

"$ffeti_solve" sphere-block.json > out.txt 2>&1 || { echo "FAILED: the unchanged problem does not run:"; cat out.txt; exit 1; }
echo "ok: the unchanged problem runs"
failures=0
# expect NAME PATTERN JSON_EDIT: applies the Python statement JSON_EDIT to the problem `p`,
# runs ffeti-solve and checks exit status 2 and PATTERN in its message.
expect() {
  local name=$1 pattern=$2 edit=$3
  python3 -c "
import json
p = json.load(open('sphere-block.json'))
p['output'] = {}
$edit
open('case.json', 'w').write(json.dumps(p))"
  local status=0
  "$ffeti_solve" case.json > out.txt 2>&1 || status=$?
  if [ "$status" -eq 2 ] && grep -q -- "$pattern" out.txt; then
    echo "ok: $name: $(tail -n 1 out.txt)"
  else
    echo "FAILED: $name: exit status $status, expected 2 and \"$pattern\"; got:"; cat out.txt
    failures=$((failures + 1))
  fi
}
expect "components 3 with a plane mesh" \
  "case.json: components: 3 (a solid) needs a volume mesh with physical volumes; ./plane.msh has physical groups of dimension 2" \
  "p['mesh'] = 'plane.msh'"
expect "components 2 with a volume mesh" "case.json: components: 2 (a plane problem) with ./sphere-block.msh, a volume mesh" \
  "p['components'] = 2; p['contact'] = []; p['dirichlet'] = []
for s in p['subdomains']: s['surfaces'] = [3]; del s['volumes']"
expect "volumes without components 3" "subdomains\[0\].volumes: physical volumes need \"components\": 3" "p['components'] = 2"
expect "surfaces for a solid" "subdomains\[0\].surfaces: a solid (\"components\": 3) is cut into physical volumes" \
  "p['subdomains'][0]['surfaces'] = [4]"
expect "components 4" "case.json: components: must be 1 (scalar field), 2 (plane displacements) or 3" "p['components'] = 4"
expect "a physical volume that does not exist" \
  "subdomains\[1\].volumes: ./sphere-block.msh: no physical volume 999 (the mesh has 101, 102, 201, 202)" \
  "p['subdomains'][1]['volumes'] = [999]"
expect "a Dirichlet surface that does not exist" "dirichlet\[0\].group: ./sphere-block.msh: no physical surface 77" \
  "p['dirichlet'][0]['group'] = 77"
expect "a slave surface that does not exist" "contact\[0\].slave: ./sphere-block.msh: no physical surface 66" \
  "p['contact'][0]['slave'] = 66"
expect "a master surface that does not exist" "contact\[0\].master: ./sphere-block.msh: no physical surface 88" \
  "p['contact'][0]['master'] = 88"
expect "a volume as the master" "contact\[0\].master: ./sphere-block.msh: no physical surface 201" \
  "p['contact'][0]['master'] = 201"
expect "slave and master on one body" "contact\[0\]: the slave surface 4 and the master surface 1 both lie on body 0" \
  "p['contact'][0]['master'] = 1"
expect "a Dirichlet group of dimension 3" "dirichlet\[0\].dim: must be 2 (a physical surface), 1 (a curve) or 0 (a point)" \
  "p['dirichlet'][0]['dim'] = 3"
expect "an obstacle point in two coordinates" "contact\[0\].obstacle.point: needs three numbers \[x, y, z\]" \
  "p['contact'] = [{'slave': 4, 'obstacle': {'point': [0, 0], 'normal': [0, 0, 1]}}]"
expect "a zero obstacle normal" "contact\[0\].obstacle.normal: must not be zero" \
  "p['contact'] = [{'slave': 4, 'obstacle': {'point': [0, 0, 0], 'normal': [0, 0, 0]}}]"
expect "an obstacle curve in 3D" "contact\[0\].obstacle.curve: a plane problem's obstacle line" \
  "p['contact'] = [{'slave': 4, 'obstacle': {'curve': 11}}]"
expect "a negative friction coefficient in 3D" "contact\[0\].friction: must be >= 0" \
  "p['contact'][0]['friction'] = -0.3"
expect "a plane model for a solid" "bodies\[0\].material.model: applies to plane problems only" \
  "p['bodies'][0]['material']['model'] = 'plane stress'"
expect "the system of another volume" "sphere-block.pre: subdomains\[1\]: node .* is not a vertex of the subdomain's tetrahedra" \
  "p['subdomains'][1]['dofs']['system'] = 0; p['subdomains'][1]['matrix'] = 'file_mat_sphere-block-A1.m'; p['subdomains'][1]['rhs'] = 'file_vec_sphere-block-A1.m'"
expect "a flat tetrahedron" \
  "subdomains\[3\].volumes: ./flat.msh: physical volume 202: tetrahedron [0-9]* (nodes .*) is flat or degenerate: |volume| / (longest edge)^3 = .*, below 1e-06" \
  "p['mesh'] = 'flat.msh'"
expect "a nearly flat tetrahedron" "subdomains\[3\].volumes: ./nearly-flat.msh: physical volume 202: tetrahedron [0-9]* .* is flat or degenerate" \
  "p['mesh'] = 'nearly-flat.msh'"
expect "a contact_normal that is no choice" \
  'contact\[0\].contact_normal: must be "master", "slave", "average" or "flatter", got "normal"' \
  "p['contact'][0]['contact_normal'] = 'normal'"
expect "a contact_normal on an obstacle" "contact\[0\].contact_normal: applies to node-to-face contact" \
  "p['contact'] = [{'slave': 4, 'obstacle': {'point': [0, 0, 0], 'normal': [0, 0, 1]}, 'contact_normal': 'slave'}]"
# A valid choice runs: the rows take the slave surface's normal (its faces added to the
# master faces by ffeti-solve).
python3 -c "
import json
p = json.load(open('sphere-block.json'))
p['output'] = {}
p['contact'][0]['contact_normal'] = 'average'
open('case.json', 'w').write(json.dumps(p))"
if "$ffeti_solve" case.json > out.txt 2>&1 && grep -q "status_name=converged" out.txt; then
  echo "ok: contact_normal average runs"
else
  echo "FAILED: contact_normal average:"; cat out.txt; failures=$((failures + 1))
fi
if [ "$failures" -eq 0 ]; then echo "all cases refused clearly"; else echo "FAILED: $failures cases"; exit 1; fi
