#!/usr/bin/env python3
"""Three dimensions, as far as they go. Opens with 3D elasticity contact at scale
(edp/cubes-elasticity-3d.edp, scripts/three_dimensions_elasticity.py: weak scaling, the whole
scene's phases, the coarse problem, preconditioners and factor kinds; MPI optionally) and
the direct peers beside FETI on the cubes and the sphere (scripts/three_dimensions_peers.py);
then the seed's model problem as two cubes (edp/model-problem-3d.edp) at fixed H/h against
the undivided cubes' active set solution, the Hessian count, the phases and times as h falls to a problem above a million unknowns, CHOLMOD's simplicial against supernodal
factors on 3D subdomains, and the 2D model problem of about the same size beside it; Hertz for
a sphere (edp/hertz-sphere.edp) on a rigid plane and on an elastic block (mortar contact) with
a picture of its stress and contact pressure; the contact patch test and the 3D gradient
checks (tests/edp/). Writes docs/results/three-dimensions.md and its plots from one run on
this machine (--only PART: that part alone, the other tables kept: cubes, sphere, elasticity,
gram (the coarse Gram matrices' two layouts), peers, or mpi, the two-rank elasticity run, which the full run leaves out; --sphere: --only sphere;
--render: from the CSVs, no run). Smaller runs to try it: FFETI_THREE_DIMENSIONS_SIZES,
FFETI_THREE_DIMENSIONS_FACTOR_SIZES, FFETI_THREE_DIMENSIONS_SEARCH_SIZES,
FFETI_THREE_DIMENSIONS_PLANE ("n H/h") and the
FFETI_ELASTICITY_3D_* variables of three_dimensions_elasticity.py and FFETI_PEER_* of
three_dimensions_peers.py."""
import argparse
import math
import os
import tempfile

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import matplotlib.tri as mtri  # noqa: E402
from matplotlib.collections import PolyCollection  # noqa: E402
from matplotlib.colors import LogNorm  # noqa: E402
from mpl_toolkits.mplot3d.art3d import Poly3DCollection  # noqa: E402

from ffeti_bench import (OUT, ROOT, begin_run, end_run, f, listing, machine_line, markdown_table, run_machine,  # noqa: E402
                         read_csv, run, save_page, span, write_csv)
import three_dimensions_elasticity as elasticity  # noqa: E402
import three_dimensions_peers as peers  # noqa: E402

PAGE = "three-dimensions"
HH = 8
# 80: 1.46 million unknowns; 128: 6 million, the third refinement of 16
SIZES = [int(n) for n in os.environ.get("FFETI_THREE_DIMENSIONS_SIZES", "8 16 32 64 80 128").split()]
REFERENCE_UP_TO = 16  # the undivided cubes' sparse factorization grows fast in 3D
FACTOR_CASES = [(int(n), 16) for n in os.environ.get("FFETI_THREE_DIMENSIONS_FACTOR_SIZES", "32 64").split()]
# the 2D model problem (n, H/h) of about the size of the 3D n = 64
PLANE = tuple(int(v) for v in os.environ.get("FFETI_THREE_DIMENSIONS_PLANE", "640 64").split())
SPHERE_SIZES = [0.2, 0.1, 0.07]  # mesh size at the contact (mm), edp/hertz-sphere.edp
PICTURE_H = 0.1  # the sphere run whose fields the picture draws (its gmsh file)
NU = 0.3  # the sphere's Poisson ratio, for Hertz's stress below the contact

CUBES = [("n", "n"), ("subdomains", "subdomains"), ("unknowns", "primal"), ("dual", "dual"), ("couples", "couples"),
         ("active", "active"), ("Hessian mult.", "hessian"), ("outer", "outer"),
         ("assembly [s]", ("time_assembly", ".2f")), ("plugin set-up [s]", ("time_plugin_setup", ".2f")),
         ("factor [s]", ("time_factor", ".2f")), ("solve [s]", ("time_solve", ".2f")),
         ("whole scene [s]", ("time_scene", ".2f")), ("peak MB", ("process_peak_mb", ".0f")),
         ("MB per subdomain", lambda r: f"{f(r, 'process_peak_mb') / f(r, 'subdomains'):.2f}"),
         # runs before shared factors (no `factorizations` word) factorized every subdomain
         ("factorizations", lambda r: r.get("factorizations") or r["subdomains"]),
         ("factor nonzeros per factor",
          lambda r: f"{f(r, 'factor_nnz') / float(r.get('factorizations') or r['subdomains']):,.0f}"),
         ("energy", "energy"), ("status", "status")]
REFERENCE = [("n", "n"), ("unknowns", "primal"), ("couples", "couples"), ("active", "active"),
             ("active set method: active", "active_reference"), ("its iterations", "pdas_iterations"),
             ("energy", "energy"), ("active set method: energy", "energy_reference"),
             ("relative difference", ("energy_error", ".1e")), ("Hessian mult.", "hessian"), ("status", "status")]
FACTORS = [("n", "n"), ("H/h", "Hh"), ("subdomains", "subdomains"), ("unknowns", "primal"), ("factor", "factor"),
           ("factor nonzeros", "factor_nnz"), ("factor [s]", ("time_factor", ".2f")), ("solve [s]", ("time_solve", ".2f")),
           ("Hessian mult.", "hessian"), ("peak MB", ("process_peak_mb", ".0f"))]
SPHERE = [("support", "support"), ("h [mm]", "h"), ("unknowns", "unknowns"), ("subdomains", "subdomains"), ("couples", "couples"), ("active", "active"),
          ("a [mm]", ("a", ".4f")), ("a Hertz", ("a_hertz", ".4f")), ("error a", ("a_relerr", ".2%")),
          ("p0 [MPa]", ("p0", ".2f")), ("p0 Hertz", ("p0_hertz", ".2f")), ("error p0", ("p0_relerr", ".2%")),
          ("L2 error of p", ("pressure_l2_relerr", ".1%")),
          ("max von Mises [MPa]", ("von_mises_max", ".1f")),
          ("/ p0 Hertz", lambda r: f"{f(r, 'von_mises_max') / f(r, 'p0_hertz'):.3f}"),
          ("its depth z / a Hertz", lambda r: f"{f(r, 'von_mises_max_z') / f(r, 'a_hertz'):.2f}"),
          ("its r / a Hertz", lambda r: f"{peak_radius(r) / f(r, 'a_hertz'):.2f}"),
          ("force balance", ("balance_error", ".0e")), ("Hessian mult.", "hessian"),
          ("slave / master faces", lambda r: f"{r['slave_faces']} / {r['master_faces']}" if r["support"] == "block" else "-"),
          ("constraints [s]", ("time_constraints", ".2f")),
          ("solve [s]", ("time_solve", ".2f")), ("total [s]", ("time_total", ".2f")), ("status", "status")]
INDENTER = [("h [mm]", "h"), ("unknowns", "unknowns"), ("couples", "couples"), ("active", "active"),
            ("F [N]", ("force", ".1f")), ("a [mm]", ("a", ".4f")), ("a Hertz", ("a_hertz", ".4f")),
            ("error a", ("a_relerr", ".2%")), ("p0 [MPa]", ("p0", ".2f")), ("p0 Hertz", ("p0_hertz", ".2f")),
            ("error p0", ("p0_relerr", ".2%")), ("L2 error of p", ("pressure_l2_relerr", ".1%")),
            ("Hessian mult.", "hessian"), ("solve [s]", ("time_solve", ".2f")), ("status", "status")]
# edp/contact-search.edp: m x m cells on the slave side
SEARCH_SIZES = [int(m) for m in os.environ.get("FFETI_THREE_DIMENSIONS_SEARCH_SIZES", "25 50 100 200").split()]
SEARCH = [("contact", "contact"), ("m", "m"), ("slave faces", "slave_faces"), ("master faces", "master_faces"),
          ("rows", "couples"), ("unknowns", "unknowns"), ("constraints [s]", ("time_constraints", ".3f")),
          ("µs per slave face", lambda r: f"{1e6 * f(r, 'time_constraints') / f(r, 'slave_faces'):.1f}"),
          ("factor [s]", ("time_factor", ".2f")), ("solve [s]", ("time_solve", ".2f")), ("Hessian mult.", "hessian"),
          ("largest σ_zz error / p", ("stress_error", ".1e")), ("status", "status")]
PATCH = [("element", "element"), ("meshes", "case"), ("contact", "formulation"), ("variant", "variant"), ("rows", "rows"),
         ("active", "active"), ("Hessian mult.", "hessian"), ("Σ forces / p", ("force", ".12g")),
         ("largest σ_zz error / p", ("stress_error", ".1e")), ("the same, z beyond ±0.5", ("stress_error_far", ".1e"))]
GRADIENTS = [("scene", "scene"), ("contact rows", "case"), ("direct", ("direct", ".10g")),
             ("finite differences", ("fd", ".10g")), ("direct vs differences", ("direct_vs_fd", ".1e")),
             ("adjoint vs direct", ("adjoint_vs_direct", ".1e"))]
PLANE_COLUMNS = [("problem", "problem"), ("unknowns", "primal"), ("subdomains", "subdomains"),
                 ("unknowns per subdomain", lambda r: f"{f(r, 'primal') / f(r, 'subdomains'):.0f}"),
                 ("Hessian mult.", "hessian"), ("factor [s]", ("time_factor", ".2f")), ("solve [s]", ("time_solve", ".2f")),
                 ("peak MB", ("process_peak_mb", ".0f"))]



def shared_factor_words(cubes):
    """What the factorizations column shows: identical boxes share one factor where the grid
    spacing is exact in binary; the sizes where it is not factorize most boxes on their own."""
    runs = [r for r in cubes if r.get("factorizations")]
    if not runs:
        return []
    exact = [r for r in runs if 2 ** round(math.log2(float(r["n"]))) == int(r["n"])]
    inexact = [r for r in runs if r not in exact]
    words = [f"Factorizations: boxes of one position class have bitwise equal matrices where h = 1/n is exact in "
             f"binary and share one factor (`shareFactors`): {listing([r['factorizations'] for r in exact])} "
             f"for {listing([r['subdomains'] for r in exact])} boxes at n = {listing([r['n'] for r in exact])}."]
    for r in inexact:
        words.append(f"At n = {r['n']} (h = 1/{r['n']}, not exact in binary) the translated coordinates round "
                     f"differently and {r['factorizations']} of {r['subdomains']} boxes factorize on their own, "
                     "hence its factorization time.")
    return [" ".join(words)]

def peak_radius(row):
    """The distance from the axis of the centroid of a sphere run's most stressed tetrahedron."""
    return math.hypot(f(row, "von_mises_max_x"), f(row, "von_mises_max_y"))


def run_sphere():
    """The Hertz sphere at each mesh size: its RESULT rows, the pressure per contact row, and
    from the PICTURE_H run's gmsh file the body's surface for the picture; each into its CSV,
    with the part's own run row (sphere-run.csv: --sphere re-runs this part alone)."""
    begun = begin_run()
    sphere, profile = [], []
    with tempfile.TemporaryDirectory() as scratch:
        for block in (0, 1):
            for h in SPHERE_SIZES:
                table = os.path.join(scratch, f"sphere-{h}.csv")
                views = ["-gmsh", os.path.join(scratch, "sphere.msh")] if h == PICTURE_H and not block else []
                sphere.append(run("hertz-sphere.edp", "-h", h, "-block", block, "-meshes", os.path.join(ROOT, "meshes"),
                                  "-table", table, *views)["RESULT"][0])
                with open(table) as rows:
                    header = rows.readline().strip().split(",")
                    profile += [dict(h=h, support=sphere[-1]["support"], **dict(zip(header, line.strip().split(","))))
                                for line in rows]
        nodes, faces = surface(os.path.join(scratch, "sphere.msh"))
    indenter = [run("hertz-indenter.edp", "-h", h, "-meshes", os.path.join(ROOT, "meshes"))["RESULT"][0]
                for h in SPHERE_SIZES]
    write_csv(PAGE, "sphere", sphere)
    write_csv(PAGE, "indenter", indenter)
    write_csv(PAGE, "sphere-pressure", profile)
    write_csv(PAGE, "sphere-surface-nodes", nodes)
    write_csv(PAGE, "sphere-surface-faces", faces)
    end_run(PAGE, begun, "sphere-run")


def surface(path):
    """The body's surface from the gmsh file edp/hertz-sphere.edp writes (format 2.2, ASCII):
    the faces of one tetrahedron only, each with its tetrahedron's von Mises stress, the 4th
    vertex (to orient it outwards) and whether it is a contact-face triangle; the nodes they
    use with their displacement and contact pressure. Returns (nodes, faces) as CSV rows."""
    with open(path) as file:
        lines = file.read().split("\n")
    sections, k = {}, 0
    while k < len(lines):  # each $Section's lines up to its $EndSection (the header lines included)
        if lines[k].startswith("$") and not lines[k].startswith("$End"):
            end = lines.index("$End" + lines[k][1:], k)
            sections[lines[k][1:]] = lines[k + 1:end]
            k = end
        k += 1
    coordinates = {int(w[0]): w[1:4] for w in (line.split() for line in sections["Nodes"][1:])}
    tets, triangles = {}, {}
    for w in (line.split() for line in sections["Elements"][1:]):
        (tets if w[1] == "4" else triangles)[int(w[0])] = [int(v) for v in w[5:]]
    data = lambda name: {int(w[0]): w[1:] for w in (line.split() for line in sections[name][8:])}  # noqa: E731
    displacement, von_mises, corners = data("NodeData"), data("ElementData"), data("ElementNodeData")
    pressure = {}
    for element, values in corners.items():  # "3 p1 p2 p3": the corners' pressures
        pressure.update(zip(triangles[element], values[1:]))
    seen = {}
    for element, vertices in tets.items():
        for opposite in range(4):
            face = tuple(sorted(vertices[:opposite] + vertices[opposite + 1:]))
            seen[face] = None if face in seen else (element, vertices[opposite])
    contact = {tuple(sorted(t)) for t in triangles.values()}
    faces = [dict(n1=face[0], n2=face[1], n3=face[2], opposite=owner[1], von_mises=von_mises[owner[0]][0],
                  contact=int(face in contact)) for face, owner in seen.items() if owner]
    used = sorted({n for face in faces for n in (face["n1"], face["n2"], face["n3"], face["opposite"])})
    nodes = [dict(node=n, x=coordinates[n][0], y=coordinates[n][1], z=coordinates[n][2], ux=displacement[n][0],
                  uy=displacement[n][1], uz=displacement[n][2], pressure=pressure.get(n, "")) for n in used]
    return nodes, faces


def run_cubes():
    """The model problem as two cubes, its reference, factor kinds and 2D neighbour; the patch
    test, the 3D gradients and the contact search: each into its CSV, with the part's own run
    row (cubes-run.csv: --only cubes re-runs this part alone)."""
    begun = begin_run()
    cubes = [run("model-problem-3d.edp", "-n", n, "-Hh", HH, "-reference", 0)["RESULT"][0] for n in SIZES]
    reference = [run("model-problem-3d.edp", "-n", n, "-Hh", HH, "-tol", 1e-8)["RESULT"][0]
                 for n in SIZES if n <= REFERENCE_UP_TO]
    factors = [run("model-problem-3d.edp", "-n", n, "-Hh", hh, "-reference", 0, "-factor", kind)["RESULT"][0]
               for n, hh in FACTOR_CASES for kind in ("simplicial", "supernodal", "auto")]
    plane = run("model-problem.edp", "-n", PLANE[0], "-Hh", PLANE[1])["RESULT"][0]
    patch = [dict(element=element, **row) for element, fe in (("P1", "P13d"), ("P2", "P23d"))
             for row in run(os.path.join(ROOT, "tests", "edp", "patch-test-3d.edp"), f"-DPk={fe}")["RESULT"]]
    gradients = [dict(scene=scene, **row) for scene in ("sensitivity-3d.edp", "sensitivity-3d-faces.edp")
                 for row in run(os.path.join(ROOT, "tests", "edp", scene))["RESULT"]]
    search = [run("contact-search.edp", "-m", m, "-mortar", mortar)["RESULT"][0]
              for mortar in (1, 0) for m in SEARCH_SIZES]
    three = min(cubes, key=lambda r: abs(f(r, "primal") - f(plane, "primal")))  # the 3D row of about its size
    write_csv(PAGE, "cubes", cubes)
    write_csv(PAGE, "reference", reference)
    write_csv(PAGE, "factors", factors)
    write_csv(PAGE, "patch", patch)
    write_csv(PAGE, "search", search)
    write_csv(PAGE, "gradients", gradients)
    write_csv(PAGE, "plane", [dict(problem=f"2D, n = {PLANE[0]}, H/h = {PLANE[1]}", **plane),
                              dict(problem=f"3D, n = {three['n']}, H/h = {HH}", **three)])
    end_run(PAGE, begun, "cubes-run")


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--render", action="store_true", help="re-render the page from its CSVs, no run")
    parser.add_argument("--only", choices=("cubes", "sphere", "elasticity", "gram", "peers", "mpi"),
                        help="run this part alone, keep the other tables (mpi: the largest elasticity case on one "
                             "process and on two ranks, left out of the full run)")
    parser.add_argument("--sphere", action="store_true", help="the same as --only sphere")
    options = parser.parse_args()
    only = "sphere" if options.sphere else options.only
    if not options.render:
        begun = begin_run()
        parts = {"elasticity": lambda: elasticity.measure(begin_run()), "cubes": run_cubes, "sphere": run_sphere,
                 "mpi": lambda: elasticity.measure_mpi(begin_run()), "peers": lambda: peers.measure(begin_run()),
                 "gram": lambda: elasticity.measure_gram(begin_run())}
        for name in [only] if only else ["elasticity", "gram", "cubes", "sphere", "peers"]:
            parts[name]()
        if not only:
            end_run(PAGE, begun)
    render()


def write_plot(cubes):
    fig, ax = plt.subplots(1, 2, figsize=(10, 3.8))
    n = [f(r, "n") for r in cubes]
    ax[0].plot(n, [f(r, "hessian") for r in cubes], "o-")
    ax[0].set_xscale("log", base=2)
    ax[0].set_ylim(0, 1.3 * max(f(r, "hessian") for r in cubes))
    ax[0].set_xlabel("n (h = 1/n)")
    ax[0].set_ylabel("Hessian multiplications")
    ax[0].set_title(f"Two cubes, H/h = {HH}")
    unknowns = [f(r, "primal") for r in cubes]
    for key, label in (("time_assembly", "assembly (FreeFEM)"), ("time_plugin_setup", "plugin set-up"),
                       ("time_factor", "factorization"), ("time_solve", "solve")):
        ax[1].loglog(unknowns, [f(r, key) for r in cubes], "o-", label=label)
    ax[1].set_xlabel("unknowns")
    ax[1].set_ylabel("seconds")
    ax[1].legend(fontsize=8)
    ax[1].set_title("Times")
    fig.tight_layout()
    fig.savefig(os.path.join(OUT, "three-dimensions.png"), dpi=110)
    plt.close(fig)


def write_profile(sphere, profile):
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.2))
    for ax, support, title in zip(axes, ("plane", "block"), ("on a rigid plane", "on an elastic block (mortar)")):
        rows = [r for r in sphere if r["support"] == support]
        finest = rows[-1]
        a, p0 = f(finest, "a_hertz"), f(finest, "p0_hertz")
        rs = [1.5 * a * i / 300 for i in range(301)]
        ax.plot(rs, [p0 * max(0.0, 1 - (r / a) ** 2) ** 0.5 for r in rs], "k-", label="Hertz")
        for row, marker in zip(rows[1:], ["s", "o"]):
            points = [p for p in profile if float(p["h"]) == float(row["h"]) and p["support"] == support]
            ax.plot([f(p, "r") for p in points], [f(p, "pressure") for p in points], marker, ms=3,
                    label=f"ffeti, h = {row['h']} mm")
        ax.set_xlabel("r [mm]")
        ax.set_ylabel("contact pressure [MPa]")
        ax.set_title(f"Sphere {title}: pressure per slave node", fontsize=10)
        ax.legend()
    fig.tight_layout()
    fig.savefig(os.path.join(OUT, "three-dimensions-sphere.png"), dpi=110)
    plt.close(fig)


def hertz_axis_maximum(nu):
    """Hertz's largest von Mises stress under a circular contact, over p0, and its depth over a:
    on the axis sigma_r = sigma_theta, so the von Mises stress is |sigma_r - sigma_z| there, with
    sigma_z / p0 = -1 / (1 + s^2), sigma_r / p0 = -(1 + nu) (1 - s atan(1/s)) + 1 / (2 (1 + s^2)),
    s = z / a (Johnson, Contact Mechanics, eq. 3.45). Scanned at steps of 1e-4 a."""
    best = (0.0, 0.0)
    for i in range(1, 30001):
        s = i / 10000
        sz = -1 / (1 + s * s)
        sr = -(1 + nu) * (1 - s * math.atan(1 / s)) + 0.5 / (1 + s * s)
        best = max(best, (abs(sr - sz), s))
    return best


def write_fields(row, nodes, faces):
    """The PICTURE_H run's fields, displacements at true scale: the quarter sphere's visible
    surface coloured by the von Mises stress (log scale), the symmetry plane y = 0 near the
    contact (linear scale) and the contact pressure on the contact face."""
    a, p0 = f(row, "a_hertz"), f(row, "p0_hertz")
    at = {n["node"]: n for n in nodes}

    def moved(node):
        n = at[node]
        return [f(n, "x") + f(n, "ux"), f(n, "y") + f(n, "uy"), f(n, "z") + f(n, "uz")]

    def minus(p, q):
        return [p[i] - q[i] for i in range(3)]

    def dot(p, q):
        return sum(p[i] * q[i] for i in range(3))

    vm_max = f(row, "von_mises_max")
    fig = plt.figure(figsize=(18, 5.8))
    # Left: the body is convex, so the faces turned towards the viewer are exactly the visible ones.
    elev, azim = 15, -125
    toward = [math.cos(math.radians(elev)) * math.cos(math.radians(azim)),
              math.cos(math.radians(elev)) * math.sin(math.radians(azim)), math.sin(math.radians(elev))]
    polygons, values = [], []
    for face in faces:
        p = [moved(face[k]) for k in ("n1", "n2", "n3")]
        u, v = minus(p[1], p[0]), minus(p[2], p[0])
        normal = [u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]]
        if dot(normal, minus(moved(face["opposite"]), p[0])) > 0:
            normal = [-c for c in normal]
        if dot(normal, toward) > 0:
            polygons.append(p)
            values.append(f(face, "von_mises"))
    log_norm = LogNorm(vmin=min(values), vmax=vm_max)
    ax = fig.add_subplot(1, 3, 1, projection="3d")
    ax.add_collection3d(Poly3DCollection(polygons, facecolors=plt.cm.viridis(log_norm(values)), edgecolors="none"))
    ax.set_xlim(0, 10)
    ax.set_ylim(0, 10)
    ax.set_zlim(0, 10)
    ax.set_box_aspect((1, 1, 1))
    ax.view_init(elev, azim)
    ax.set_xlabel("x [mm]")
    ax.set_ylabel("y [mm]")
    ax.set_zlabel("z [mm]")
    ax.set_title("The quarter sphere from the side of its symmetry planes:\nvon Mises stress, log scale",
                 fontsize=10)
    bar = fig.colorbar(plt.cm.ScalarMappable(norm=log_norm, cmap="viridis"), ax=ax, shrink=0.7, pad=0.1,
                       label="von Mises stress [MPa]")
    bar.set_ticks([t for t in (1, 2, 5, 10, 20, 50, 100) if min(values) <= t <= vm_max])
    bar.set_ticklabels([t for t in (1, 2, 5, 10, 20, 50, 100) if min(values) <= t <= vm_max])
    # Middle: the symmetry plane y = 0 near the contact, where Hertz's maximum lies.
    ax = fig.add_subplot(1, 3, 2)
    linear = plt.Normalize(0, vm_max)
    plane = [face for face in faces if all(abs(f(at[face[k]], "y")) < 1e-9 for k in ("n1", "n2", "n3"))]
    ax.add_collection(PolyCollection([[(moved(face[k])[0], moved(face[k])[2]) for k in ("n1", "n2", "n3")]
                                      for face in plane],
                                     facecolors=plt.cm.viridis(linear([f(face, "von_mises") for face in plane])),
                                     edgecolors="face", linewidths=0.1))
    xs = [2.5 * a * i / 200 for i in range(201)]
    ax.plot(xs, [10 - math.sqrt(100 - x * x) for x in xs], "--", color="tab:orange", lw=1, label="undeformed surface")
    peak, depth = hertz_axis_maximum(NU)
    ax.plot([0], [depth * a], "P", color="white", mec="black", ms=10, clip_on=False,
            label=f"Hertz: {peak:.2f} p0 at z = {depth:.2f} a")
    r_max = peak_radius(row)
    ax.plot([r_max], [f(row, "von_mises_max_z")], "X", color="red", mec="black", ms=9,
            label=f"ffeti: {vm_max / p0:.2f} p0 (centroid at r, z)")
    ax.set_xlim(0, 2.5 * a)
    ax.set_ylim(0, 2 * a)
    ax.set_aspect("equal")
    ax.set_xlabel("x (r for the ffeti marker) [mm]")
    ax.set_ylabel("z [mm]")
    ax.legend(fontsize=8, loc="upper right", framealpha=0.9)
    ax.set_title(f"The symmetry plane y = 0 near the contact: von Mises stress\n"
                 f"(Hertz: a = {a:.2f} mm, p0 = {p0:.1f} MPa)", fontsize=10)
    fig.colorbar(plt.cm.ScalarMappable(norm=linear, cmap="viridis"), ax=ax, label="von Mises stress [MPa]")
    # Right: the contact pressure at the contact face's nodes, Hertz's contact circle over it.
    ax = fig.add_subplot(1, 3, 3)
    contact = [face for face in faces if face["contact"] == "1"]
    index = {n: i for i, n in enumerate(sorted({face[k] for face in contact for k in ("n1", "n2", "n3")}))}
    ordered = sorted(index, key=index.get)
    triangulation = mtri.Triangulation([f(at[n], "x") for n in ordered], [f(at[n], "y") for n in ordered],
                                       [[index[face[k]] for k in ("n1", "n2", "n3")] for face in contact])
    shading = ax.tripcolor(triangulation, [f(at[n], "pressure") for n in ordered], shading="gouraud", cmap="viridis")
    angles = [math.pi / 2 * i / 100 for i in range(101)]
    ax.plot([a * math.cos(t) for t in angles], [a * math.sin(t) for t in angles], "--", color="tab:orange", lw=1,
            label=f"Hertz's contact radius a = {a:.2f} mm")
    ax.set_xlim(0, 1.5 * a)
    ax.set_ylim(0, 1.5 * a)
    ax.set_aspect("equal")
    ax.set_xlabel("x [mm]")
    ax.set_ylabel("y [mm]")
    ax.legend(fontsize=8, loc="upper right")
    ax.set_title("Contact pressure on the contact face\n(its nodes, projected on the plane z = 0)", fontsize=10)
    fig.colorbar(shading, ax=ax, label="contact pressure [MPa]")
    fig.suptitle(f"Sphere on a rigid plane, h = {row['h']} mm: the body drawn deformed, displacements at true scale "
                 "(magnification 1)")
    fig.subplots_adjust(left=0.02, right=0.97, bottom=0.1, top=0.84, wspace=0.25)
    fig.savefig(os.path.join(OUT, "three-dimensions-sphere-fields.png"), dpi=110)
    plt.close(fig)


def render():
    cubes, reference, factors, plane, sphere, profile, patch, gradients, indenter, search = (
        read_csv(PAGE, t) for t in ("cubes", "reference", "factors", "plane", "sphere", "sphere-pressure", "patch",
                                    "gradients", "indenter", "search"))
    mortar_search = [r for r in search if r["contact"] == "mortar"]
    write_profile(sphere, profile)
    on_plane = [r for r in sphere if r["support"] == "plane"]
    on_block = [r for r in sphere if r["support"] == "block"]
    pictured = next(r for r in on_plane if float(r["h"]) == PICTURE_H)
    write_fields(pictured, read_csv(PAGE, "sphere-surface-nodes"), read_csv(PAGE, "sphere-surface-faces"))
    sphere_run = read_csv(PAGE, "sphere-run")[0]
    peak, depth = hertz_axis_maximum(NU)
    a_p, p0_p = f(pictured, "a_hertz"), f(pictured, "p0_hertz")
    r_p = peak_radius(pictured)
    run_row = read_csv(PAGE, "run")[0]
    cubes_run = read_csv(PAGE, "cubes-run")[0]
    write_plot(cubes)
    counts = [f(r, "hessian") for r in cubes]
    decomposed = [f(r, "hessian") for r in cubes if f(r, "n") >= 2 * HH]  # n = H/h: one subdomain per cube
    refined = [f(r, "hessian") for r in cubes if f(r, "n") in (2 * HH, 4 * HH, 8 * HH, 16 * HH)]
    largest = cubes[-1]
    two, three = plane
    per_unknown = {key: (f(three, key) / f(three, "primal")) / (f(two, key) / f(two, "primal"))
                   for key in ("time_factor", "time_solve")}
    def factor_ratio(kind):  # per size, the kind's factorization time over the simplicial one's
        return [f(next(r for r in factors if r["n"] == n and r["factor"] == kind), "time_factor")
                / f(next(r for r in factors if r["n"] == n and r["factor"] == "simplicial"), "time_factor")
                for n in sorted({r["n"] for r in factors})]
    lines = [
        "# Three dimensions: 3D elasticity contact at scale, the seed's model problem as two cubes",
        "",
        "Generated by `scripts/benchmark.sh three-dimensions` (do not edit by hand) on:",
        machine_line(run_row),
        "The parts re-run on their own since say so, with their date, length and load.",
        "",
        *elasticity.headline(),
        "",
        "What exists in 3D: a third coordinate through the plugin (`fetiSetup(..., Z=)`) and ffeti-solve",
        "(gmsh volume meshes, [getdp.md](../getdp.md)), the six rigid modes of 3D elasticity among the",
        "kernel candidates, gluing, node-to-node contact on matching faces, node-to-face and mortar contact",
        "on non-matching ones, rigid planes and balls, the sensitivities of node-to-node, node-to-face,",
        "mortar, plane and ball rows, METIS parts of a `mesh3` (`ffetiMetis3`), P2 elements (node-to-face",
        "faces as sub-triangles), isotropic friction on every kind of contact ([friction](friction.md)),",
        "contact shape optimization (`edp/uniform-pressure-3d.edp`). Not yet: mortar on",
        "P2 faces, rigid surfaces from gmsh. The Hertz sphere",
        "writes its fields for ParaView and gmsh when asked (`-vtk`, `-gmsh`).",
        "",
        *elasticity.section(f(run_row, "memory_gib")),
        f"## Two cubes at H/h = {HH}: the seed's model problem",
        "",
        "`edp/model-problem-3d.edp`: two unit cubes,",
        "−Δu = f with the 2D problem's data extruded along z (K = 2 × the P1 Laplacian, f = −3 for",
        "y > 0.75 in the first cube, −1 for y < 0.25 in the second), u = 0 on x = 0, the second cube",
        "floating, u1 ≤ u2 on the shared face; each cube split into (n/H)³ boxes of H/h cells per side",
        "(`ffetiGrid3`, tetrahedra of `cube()`), FETI-1, the default options (tol = 1e-4). Peak MB: the",
        "FreeFEM process's resident set (assembly included). Raw",
        f"data: [{PAGE}-cubes.csv]({PAGE}-cubes.csv), [{PAGE}-reference.csv]({PAGE}-reference.csv),",
        f"[{PAGE}-factors.csv]({PAGE}-factors.csv),",
        f"[{PAGE}-plane.csv]({PAGE}-plane.csv). This part (these tables, the patch test, the 3D gradients",
        f"and the contact search below) ran on its own on {run_machine(cubes_run)}: {cubes_run['date']}, {float(cubes_run['elapsed_s']):.0f} s,",
        f"load average {float(cubes_run['load_at_start']):.1f} as it started, {float(cubes_run['load_at_end']):.1f} as it ended.",
        "",
        *markdown_table(cubes, CUBES),
        "",
        "![three dimensions](three-dimensions.png)",
        "",
        f"Reading: the Hessian count is {listing([int(v) for v in counts])} for n = {listing([r['n'] for r in cubes])}.",
        f"At n = {HH} each cube is one subdomain (H/h = {HH} leaves nothing to split); from n = {2 * HH} on, with",
        f"H/h fixed, it stays between {min(decomposed):.0f} and {max(decomposed):.0f}: over the three refinements to n = {16 * HH}",
        f"at most {max(refined) / refined[0]:.2f} times its n = {2 * HH} value (the aim is 1.5 over three refinements,",
        f"n = {2 * HH} to {int(max(f(r, 'n') for r in cubes))}). The largest problem,",
        f"{int(f(largest, 'primal')):,} unknowns in {largest['subdomains']} subdomains, is assembled by FreeFEM in",
        f"{f(largest, 'time_assembly'):.1f} s, set up by the plugin in {f(largest, 'time_plugin_setup'):.1f} s besides its factorizations",
        f"({f(largest, 'time_factor'):.1f} s) and solved in {f(largest, 'time_solve'):.1f} s: {f(largest, 'time_scene'):.1f} s in all, "
        f"in {f(largest, 'process_peak_mb') / 1024:.1f} GB.",
        *shared_factor_words(cubes),
        "",
        f"## Against the undivided cubes (tol = 1e-8, n ≤ {REFERENCE_UP_TO})",
        "",
        "The undivided cubes (one mesh each) solved by the primal-dual active set method with",
        "UMFPACK (`edp/active-set.idp`, which shares no code with the plugin) on the same discrete problem.",
        "",
        *markdown_table(reference, REFERENCE),
        "",
        f"Reading: the energies agree to {span([f(r, 'energy_error') for r in reference], '.0e')} and the contact",
        "sets are " + ("equal." if all(r["active"] == r["active_reference"] for r in reference) else "NOT equal."),
        "",
        "## Hertz for a sphere on a rigid plane and on an elastic block",
        "",
        "`edp/hertz-sphere.edp`: an elastic sphere (R = 10 mm, E = 1000 MPa, ν = 0.3) pressed on a rigid",
        "plane, a quarter model (x ≥ 0, y ≥ 0, sliding on both symmetry planes) meshed by gmsh",
        "(`meshes/hertz-sphere.geo`, size h within 2.5 mm of the contact point), loaded by a pressure on",
        "its cut z = R (F about 500 N on the whole sphere: the mesh's polygonal cut applies a little",
        "less, and the analytic values use what it applies), Total FETI over 4 connected METIS parts,",
        "the rigid plane as an obstacle, tol = 1e-6. With `-block 1` the sphere presses on a block of",
        "the same material (20 × 20 × 20 mm per quarter, held at its bottom, `meshes/hertz-sphere-block.geo`:",
        "9 subdomains, size 0.75 h at the contact, so the meshes do not match), mortar contact with the",
        "sphere's surface as the slave faces. Hertz: a = (3FR/(4E*))^(1/3), p0 = 3F/(2πa²), 1/E* = Σ (1 − ν²)/E",
        "over the bodies (the rigid plane adds nothing; the block is taken as a half-space).",
        "a: halfway between the outermost closed row and the nearest open one, by radius; the pressure",
        "per slave node: its force over its share of the surface (`fetiContactPressure`), p0 the",
        "central node's; the L2 error over the rows within 1.2 a, weighted by their shares. Raw data",
        f"per row: [{PAGE}-sphere-pressure.csv]({PAGE}-sphere-pressure.csv).",
        "",
        *markdown_table(sphere, SPHERE),
        "",
        "![sphere](three-dimensions-sphere.png)",
        "",
        f"Reading: on the plane a is within {span([f(r, 'a_relerr') for r in on_plane], '.2%')} of Hertz's (read off the",
        f"mesh, to about half a node spacing), p0 within {listing([f(r, 'p0_relerr') for r in on_plane], '.1%')} for h =",
        f"{listing([r['h'] for r in on_plane])} mm; the profile's L2 error is",
        f"{listing([f(r, 'pressure_l2_relerr') for r in on_plane], '.1%')}. On the block a is within",
        f"{listing([f(r, 'a_relerr') for r in on_block], '.1%')} and p0 within {listing([f(r, 'p0_relerr') for r in on_block], '.1%')},",
        f"the L2 error {listing([f(r, 'pressure_l2_relerr') for r in on_block], '.1%')}: falling with h, larger than on",
        "the plane (two meshes at the contact, and the mortar multipliers vary from node to node: the",
        "right panel's scatter). Constraints [s]: building B, with the mortar's search and integration",
        f"over {on_block[-1]['slave_faces']} slave and {on_block[-1]['master_faces']} master faces at h = {on_block[-1]['h']} mm",
        f"in {f(on_block[-1], 'time_constraints'):.2f} s. The contact forces",
        f"balance the load to {span([f(r, 'balance_error') for r in sphere], '.0e')} on both supports.",
        "",
        f"The rows above and the picture below come from one run of this section "
        f"(`three_dimensions_benchmark.py --sphere` runs it alone) on {run_machine(sphere_run)}: {sphere_run['date']}, "
        f"{float(sphere_run['elapsed_s']):.0f} s, load average {float(sphere_run['load_at_start']):.1f} as it started, "
        f"{float(sphere_run['load_at_end']):.1f} as it ended.",
        "",
        "![sphere: von Mises stress and contact pressure](three-dimensions-sphere-fields.png)",
        "",
        f"The run at h = {pictured['h']} mm, drawn from the gmsh file it wrote (`-gmsh`; `-vtk` writes the same",
        "fields for ParaView), the body deformed at true scale (magnification 1: the largest displacement is",
        f"{max(math.hypot(f(n, 'ux'), f(n, 'uy'), f(n, 'uz')) for n in read_csv(PAGE, 'sphere-surface-nodes')):.2f} mm,"
        " on a 10 mm radius).",
        "Left, the von Mises stress per tetrahedron on the surface of the quarter sphere, seen from the",
        "side of its two symmetry planes, on a log scale; middle, the symmetry plane y = 0 near the",
        "contact on a linear scale, with Hertz's maximum (the white cross) and the largest stress of the",
        "run (the red cross, at its tetrahedron's centroid's distance r from the axis and depth z); right,",
        "the contact pressure at the contact face's nodes with Hertz's contact circle. Raw data: the",
        f"surface's nodes and faces, [{PAGE}-sphere-surface-nodes.csv]({PAGE}-sphere-surface-nodes.csv),",
        f"[{PAGE}-sphere-surface-faces.csv]({PAGE}-sphere-surface-faces.csv).",
        "",
        f"Reading: Hertz's von Mises stress (ν = {NU}) is largest on the axis, below the surface, at",
        f"z = {depth:.2f} a with {peak:.3f} p0 (computed from his stresses on the axis, Johnson eq. 3.45). At",
        f"h = {pictured['h']} mm the largest von Mises stress of the run is {f(pictured, 'von_mises_max'):.1f} MPa = "
        f"{f(pictured, 'von_mises_max') / p0_p:.3f} p0, in the tetrahedron",
        f"whose centroid lies at z = {f(pictured, 'von_mises_max_z'):.2f} mm = {f(pictured, 'von_mises_max_z') / a_p:.2f} a,"
        f" r = {r_p:.2f} mm = {r_p / a_p:.2f} a from the axis",
        f"(a and p0 Hertz's). Over h = {listing([r['h'] for r in on_plane])} mm the largest value is",
        f"{listing([f(r, 'von_mises_max') / f(r, 'p0_hertz') for r in on_plane], '.3f')} p0 at depth",
        f"{listing([f(r, 'von_mises_max_z') / f(r, 'a_hertz') for r in on_plane], '.2f')} a and",
        f"r = {listing([peak_radius(r) / f(r, 'a_hertz') for r in on_plane], '.2f')} a:"
        " a stress per tetrahedron, read at tetrahedra of size h.",
        "",
        "## Hertz for a rigid ball pressed into the block",
        "",
        "`edp/hertz-indenter.edp`: the block above pushed up by 0.23 mm at its bottom against a rigid ball",
        "(R = 10 mm, `obstacleBall=`: each slave node against the tangent plane at its nearest point of",
        "the ball), FETI-1 over its 9 subdomains, tol = 1e-6; Hertz for the force F the solve finds",
        "(a rigid sphere on a half-space, E* = E/(1 − ν²)).",
        "",
        *markdown_table(indenter, INDENTER),
        "",
        f"Reading: a within {listing([f(r, 'a_relerr') for r in indenter], '.2%')} and p0 within",
        f"{listing([f(r, 'p0_relerr') for r in indenter], '.2%')} of Hertz's for h = {listing([r['h'] for r in indenter])} mm;",
        f"the profile's L2 error {listing([f(r, 'pressure_l2_relerr') for r in indenter], '.1%')}.",
        "",
        "## The contact patch test",
        "",
        "`tests/edp/patch-test-3d.edp`: a block pressed on another through a flat interface by a uniform",
        "pressure p on top, both sliding on x = 0 and y = 0, the lower one on its bottom: the exact",
        "solution is σ_zz = −p everywhere, which P1 elements hold. Matching meshes (6 cells across both)",
        "and non-matching ones (6 above, 4 below); node to face (the upper block's bottom nodes against",
        "the lower block's top faces) and mortar (its bottom faces as slave faces); then the upper block",
        "alone on a rigid plane. tol = 1e-10.",
        "",
        *markdown_table(patch, PATCH),
        "",
        "Reading: node to face passes on matching meshes only: on non-matching ones the forces reach",
        "the master nodes by the projection weights, and σ_zz is off by",
        f"{f(next(r for r in patch if r['case'] == 'non-matching' and r['formulation'] == 'node-to-face'), 'stress_error'):.0%}"
        " at the interface. Mortar passes on both, to",
        f"{max(f(r, 'stress_error') for r in patch if r['formulation'] == 'mortar'):.0e}. With P2 elements the faces",
        "come as 4 sub-triangles: node to face stays exact on matching meshes and on the plane (the",
        "corner rows carry no force, P2's consistent loads of a pressure being 0 there). Mortar on P2",
        "sub-triangles fails the test ([log](../log.md)) and is not run: the reference offers mortar on P1 faces.",
        "",
        "## The contact search as the faces grow",
        "",
        "`edp/contact-search.edp`: two thin plates (1 × 1 × 0.1) pressed together by a uniform pressure, the",
        "upper one of m × m × 1 cells on the lower one of 0.9 m × 0.9 m × 1 (non-matching), one subdomain",
        "each, tol = 1e-8; mortar (the upper plate's bottom faces) and node to face (its bottom nodes)",
        "against the lower plate's top faces. Constraints [s]: building B, the search through the",
        "master faces' grid and, for mortar, the clipping and integration of every overlapping pair.",
        "",
        *markdown_table(search, SEARCH),
        "",
        f"Reading: from {mortar_search[0]['slave_faces']} to {mortar_search[-1]['slave_faces']} slave faces the mortar rows take",
        f"{listing([f(r, 'time_constraints') for r in mortar_search], '.2f')} s,",
        f"{listing([1e6 * f(r, 'time_constraints') / f(r, 'slave_faces') for r in mortar_search], '.0f')} µs per slave face:",
        f"close to linear, the time per face growing {f(mortar_search[-1], 'time_constraints') / f(mortar_search[-1], 'slave_faces') / (f(mortar_search[0], 'time_constraints') / f(mortar_search[0], 'slave_faces')):.1f} times over",
        f"{f(mortar_search[-1], 'slave_faces') / f(mortar_search[0], 'slave_faces'):.0f} times the faces (the grid's cells hold a bounded number of faces;",
        "what makes the rest grow was not measured), and a small part of the set-up beside the",
        "factorization. Mortar stays exact on the patch test at every size;",
        "node to face's error falls with h on these plates, whose meshes differ only slightly.",
        "",
        "## Gradients in three dimensions",
        "",
        "`tests/edp/sensitivity-3d.edp` (the cubes' shared face bulging: node-to-node rows, which do not",
        "move) and `tests/edp/sensitivity-3d-faces.edp` (the patch-test blocks with the master top",
        "tilting: node-to-face rows; the upper block's bottom bulging on a rigid plane and on a rigid ball",
        "of radius 100, `obstacleBall=`): the compliance's",
        "derivative by the direct sensitivity and by the adjoint against central differences of",
        "re-solved moved meshes.",
        "",
        *markdown_table(gradients, GRADIENTS),
        "",
        "## Simplicial or supernodal factors for 3D subdomains",
        "",
        *markdown_table(factors, FACTORS),
        "",
        "Reading: 3D subdomains fill more than 2D ones of the same size, so that dense blocks pay",
        "sooner; here, with subdomains of 17³ nodes, the supernodal factor takes",
        f"{span(factor_ratio('supernodal'), '.2f')} times the simplicial one's time, and `\"auto\"` (the default:",
        "supernodal where CHOLMOD's analysis counts at least 120 flops per factor nonzero)",
        f"{span(factor_ratio('auto'), '.2f')} times. CHOLMOD's own threads inside a supernodal factor run",
        "serially when the plugin's thread works alone (they spun before: the log).",
        "",
        "## Beside the 2D model problem of about the same size",
        "",
        *markdown_table(plane, PLANE_COLUMNS),
        "",
        "Reading: the 3D problem's subdomains are smaller (729 unknowns at H/h = 8 against 4,225 at",
        "H/h = 64 in 2D) and five times as many; per unknown its factorization costs",
        f"{per_unknown['time_factor']:.1f} times the plane problem's and its solve {per_unknown['time_solve']:.1f} times",
        f"with {f(three, 'hessian') / f(two, 'hessian'):.2f} times the Hessian multiplications: each costs more per unknown.",
        "",
    ]
    save_page(f"{PAGE}.md", lines)


if __name__ == "__main__":
    main()
