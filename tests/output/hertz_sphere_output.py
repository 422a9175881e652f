#!/usr/bin/env python3
"""edp/hertz-sphere.edp's output files: written and well-formed when asked, nothing when not.

Runs the scene on its coarse mesh (h = 0.2 mm) twice, each in an empty folder holding the
test tree's freefem++.pref (so that it loads the build's plugin):
  - without -vtk and -gmsh: the folder then holds only the mesh the scene always writes;
  - with -vtk out.vtu -gmsh out.msh: the VTK file has one point per node and one cell per
    tetrahedron of that mesh, finite displacements, a positive finite von Mises stress in
    every cell whose largest value is the RESULT line's, subdomains 0..3, and the contact
    nodes that carry pressure lie on the plane (z + u_z = 0: the subdomains' fields were
    gathered onto the right nodes); the gmsh file has the same nodes, tetrahedra and von Mises
    values, a pressure on contact-face triangles, and its .opt file beside it.
Usage: hertz_sphere_output.py SOURCE_DIR FREEFEM_PREF"""
import math
import os
import shutil
import subprocess
import sys
import tempfile
import xml.etree.ElementTree as ET

source, pref = sys.argv[1], sys.argv[2]
failures = []


def check(what, condition):
    print(("ok: " if condition else "FAILED: ") + what)
    if not condition:
        failures.append(what)


def run(folder, *args):
    """The scene in folder; its RESULT line as a dict."""
    shutil.copy(pref, os.path.join(folder, "freefem++.pref"))
    command = ["FreeFem++-nw", "-v", "0", os.path.join(source, "edp", "hertz-sphere.edp"), "-h", "0.2",
               "-meshes", os.path.join(source, "meshes"), *args]
    done = subprocess.run(command, cwd=folder, capture_output=True, text=True, timeout=300)
    lines = [line for line in done.stdout.splitlines() if line.startswith("RESULT ")]
    if done.returncode != 0 or not lines:
        sys.exit(f"FAILED: {' '.join(command)} (status {done.returncode}):\n{done.stdout[-2000:]}{done.stderr[-2000:]}")
    return dict(word.split("=", 1) for word in lines[0].split()[1:])


def msh_sections(path):
    """{name: lines between $name and $Endname} of a gmsh format 2.2 ASCII file."""
    with open(path) as file:
        lines = file.read().split("\n")
    sections, k = {}, 0
    while k < len(lines):
        if lines[k].startswith("$") and not lines[k].startswith("$End"):
            end = lines.index("$End" + lines[k][1:], k)
            sections[lines[k][1:]] = lines[k + 1:end]
            k = end
        k += 1
    return sections


mesh_name = "hertz-sphere-h0.2-r0.msh"
with tempfile.TemporaryDirectory() as quiet:
    run(quiet)
    check("without -vtk and -gmsh only the mesh is written",
          sorted(os.listdir(quiet)) == sorted(["freefem++.pref", mesh_name]))

with tempfile.TemporaryDirectory() as folder:
    result = run(folder, "-vtk", "out.vtu", "-gmsh", "out.msh")
    check("the three files are written", all(os.path.exists(os.path.join(folder, name))
                                             for name in ("out.vtu", "out.msh", "out.msh.opt")))
    # The mesh gmsh made for the scene: its tetrahedra and the nodes they use.
    elements = [line.split() for line in msh_sections(os.path.join(folder, mesh_name))["Elements"][1:]]
    tets = [w for w in elements if w[1] == "4"]
    nodes = {v for w in tets for v in w[-4:]}

    piece = next(ET.parse(os.path.join(folder, "out.vtu")).iter("Piece"))
    points, cells = int(piece.get("NumberOfPoints")), int(piece.get("NumberOfCells"))
    check(f"VTK: {points} points, one per node of the mesh ({len(nodes)})", points == len(nodes))
    check(f"VTK: {cells} cells, one per tetrahedron ({len(tets)})", cells == len(tets))
    arrays = {a.get("Name"): [float(v) for v in a.text.split()] for a in piece.iter("DataArray")}
    sizes = {"connectivity": 4 * cells, "displacement": 3 * points, "pressure": points, "vonMises": cells,
             "subdomain": cells, None: 3 * points}
    check("VTK: every array has its size", all(len(arrays.get(name, [])) == n for name, n in sizes.items()))
    von_mises, xyz, u, p = arrays["vonMises"], arrays[None], arrays["displacement"], arrays["pressure"]
    check("VTK: von Mises finite and positive in every cell", all(math.isfinite(v) and v > 0 for v in von_mises))
    check(f"VTK: the largest von Mises {max(von_mises)} is the RESULT line's {result['von_mises_max']}",
          abs(max(von_mises) - float(result["von_mises_max"])) <= 1e-6 * max(von_mises))
    check("VTK: displacements finite", all(math.isfinite(v) for v in u))
    check("VTK: subdomains 0, 1, 2, 3", sorted(set(arrays["subdomain"])) == [0, 1, 2, 3])
    closed = [i for i in range(points) if p[i] > 0]
    check(f"VTK: {len(closed)} nodes carry pressure, as many as active rows ({result['active']})",
          len(closed) == int(result["active"]))
    check("VTK: the nodes carrying pressure lie on the plane (|z + u_z| < 1e-5 mm)",
          closed and all(abs(xyz[3 * i + 2] + u[3 * i + 2]) < 1e-5 for i in closed))

    views = msh_sections(os.path.join(folder, "out.msh"))
    elements = [line.split() for line in views["Elements"][1:]]
    check("gmsh: the mesh's nodes and tetrahedra", int(views["Nodes"][0]) == points
          and sum(w[1] == "4" for w in elements) == cells)
    triangles = [w for w in elements if w[1] == "2"]
    check(f"gmsh: {len(triangles)} contact-face triangles", len(triangles) > 0)
    check("gmsh: a displacement per node", int(views["NodeData"][7]) == points
          and all(len(line.split()) == 4 for line in views["NodeData"][8:8 + points]))
    element_von_mises = [float(line.split()[1]) for line in views["ElementData"][8:8 + cells]]
    check("gmsh: the VTK file's von Mises per tetrahedron",
          len(element_von_mises) == cells and max(abs(a - b) for a, b in zip(element_von_mises, von_mises))
          <= 1e-6 * max(von_mises))
    corner = [line.split() for line in views["ElementNodeData"][8:]]
    check("gmsh: a pressure at the corners of every contact triangle, finite, not negative, some positive",
          len(corner) == len(triangles) and all(w[1] == "3" and all(math.isfinite(float(v)) and float(v) >= 0
                                                                    for v in w[2:5]) for w in corner)
          and max(float(v) for w in corner for v in w[2:5]) > 0)
    with open(os.path.join(folder, "out.msh.opt")) as options:
        check("gmsh: the .opt file draws the displaced body coloured by von Mises",
              "View[0].ExternalView = 1;" in options.read())

if failures:
    sys.exit(f"{len(failures)} check(s) failed")
print("all checks passed")
