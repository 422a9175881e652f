#!/usr/bin/env python3
"""Three dimensions, as far as they go (edp/model-problem-3d.edp): the seed's model problem as
two cubes at fixed H/h against the undivided cubes' active set solution, the Hessian count
and times as h falls to a problem above a million unknowns, CHOLMOD's simplicial against
supernodal factors on 3D subdomains, and the 2D model problem of about the same size beside
it. Writes docs/results/three-dimensions.md and its plot from one run on this machine."""
import argparse
import os
import tempfile

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from ffeti_bench import (OUT, ROOT, begin_run, end_run, f, listing, machine_line, markdown_table, read_csv,  # noqa: E402
                         run, save_page, span, write_csv)

PAGE = "three-dimensions"
HH = 8
SIZES = [8, 16, 32, 64, 80]
REFERENCE_UP_TO = 16  # the undivided cubes' sparse factorization grows fast in 3D
FACTOR_CASES = [(32, 16), (64, 16)]
PLANE = (640, 64)  # the 2D model problem (n, H/h) of about the size of the 3D n = 64
SPHERE_SIZES = [0.2, 0.1, 0.07]  # mesh size at the contact (mm), edp/hertz-sphere.edp

CUBES = [("n", "n"), ("subdomains", "subdomains"), ("unknowns", "primal"), ("dual", "dual"), ("couples", "couples"),
         ("active", "active"), ("Hessian mult.", "hessian"), ("outer", "outer"),
         ("set-up [s]", ("time_setup", ".2f")), ("factor [s]", ("time_factor", ".2f")),
         ("solve [s]", ("time_solve", ".2f")), ("peak MB", ("process_peak_mb", ".0f")),
         ("MB per subdomain", lambda r: f"{f(r, 'process_peak_mb') / f(r, 'subdomains'):.2f}"),
         ("energy", "energy"), ("status", "status")]
REFERENCE = [("n", "n"), ("unknowns", "primal"), ("couples", "couples"), ("active", "active"),
             ("active set method: active", "active_reference"), ("its iterations", "pdas_iterations"),
             ("energy", "energy"), ("active set method: energy", "energy_reference"),
             ("relative difference", ("energy_error", ".1e")), ("Hessian mult.", "hessian"), ("status", "status")]
FACTORS = [("n", "n"), ("H/h", "Hh"), ("subdomains", "subdomains"), ("unknowns", "primal"), ("factor", "factor"),
           ("factor nonzeros", "factor_nnz"), ("factor [s]", ("time_factor", ".2f")), ("solve [s]", ("time_solve", ".2f")),
           ("Hessian mult.", "hessian"), ("peak MB", ("process_peak_mb", ".0f"))]
SPHERE = [("h [mm]", "h"), ("unknowns", "unknowns"), ("couples", "couples"), ("active", "active"),
          ("a [mm]", ("a", ".4f")), ("a Hertz", ("a_hertz", ".4f")), ("error a", ("a_relerr", ".2%")),
          ("p0 [MPa]", ("p0", ".2f")), ("p0 Hertz", ("p0_hertz", ".2f")), ("error p0", ("p0_relerr", ".2%")),
          ("L2 error of p", ("pressure_l2_relerr", ".1%")),
          ("force balance", ("balance_error", ".0e")), ("Hessian mult.", "hessian"),
          ("solve [s]", ("time_solve", ".2f")), ("total [s]", ("time_total", ".2f")), ("status", "status")]
PLANE_COLUMNS = [("problem", "problem"), ("unknowns", "primal"), ("subdomains", "subdomains"),
                 ("unknowns per subdomain", lambda r: f"{f(r, 'primal') / f(r, 'subdomains'):.0f}"),
                 ("Hessian mult.", "hessian"), ("factor [s]", ("time_factor", ".2f")), ("solve [s]", ("time_solve", ".2f")),
                 ("peak MB", ("process_peak_mb", ".0f"))]


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--render", action="store_true", help="re-render the page from its CSVs, no run")
    if not parser.parse_args().render:
        begun = begin_run()
        cubes = [run("model-problem-3d.edp", "-n", n, "-Hh", HH, "-reference", 0)["RESULT"][0] for n in SIZES]
        reference = [run("model-problem-3d.edp", "-n", n, "-Hh", HH, "-tol", 1e-8)["RESULT"][0]
                     for n in SIZES if n <= REFERENCE_UP_TO]
        factors = [run("model-problem-3d.edp", "-n", n, "-Hh", hh, "-reference", 0, "-factor", kind)["RESULT"][0]
                   for n, hh in FACTOR_CASES for kind in ("simplicial", "supernodal")]
        plane = run("model-problem.edp", "-n", PLANE[0], "-Hh", PLANE[1])["RESULT"][0]
        sphere, profile = [], []
        with tempfile.TemporaryDirectory() as scratch:
            for h in SPHERE_SIZES:
                table = os.path.join(scratch, f"sphere-{h}.csv")
                sphere.append(run("hertz-sphere.edp", "-h", h, "-meshes", os.path.join(ROOT, "meshes"),
                                  "-table", table)["RESULT"][0])
                with open(table) as rows:
                    header = rows.readline().strip().split(",")
                    profile += [dict(h=h, **dict(zip(header, line.strip().split(",")))) for line in rows]
        write_csv(PAGE, "sphere", sphere)
        write_csv(PAGE, "sphere-pressure", profile)
        three = next(r for r in cubes if r["n"] == "64")
        write_csv(PAGE, "cubes", cubes)
        write_csv(PAGE, "reference", reference)
        write_csv(PAGE, "factors", factors)
        write_csv(PAGE, "plane", [dict(problem=f"2D, n = {PLANE[0]}, H/h = {PLANE[1]}", **plane),
                                  dict(problem=f"3D, n = 64, H/h = {HH}", **three)])
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
    for key, label in (("time_setup", "set-up (assembly included)"), ("time_factor", "factorization"),
                       ("time_solve", "solve")):
        ax[1].loglog(unknowns, [f(r, key) for r in cubes], "o-", label=label)
    ax[1].set_xlabel("unknowns")
    ax[1].set_ylabel("seconds")
    ax[1].legend(fontsize=8)
    ax[1].set_title("Times")
    fig.tight_layout()
    fig.savefig(os.path.join(OUT, "three-dimensions.png"), dpi=110)
    plt.close(fig)


def write_profile(sphere, profile):
    fig, ax = plt.subplots(figsize=(6.5, 4.2))
    finest = sphere[-1]
    a, p0 = f(finest, "a_hertz"), f(finest, "p0_hertz")
    rs = [1.5 * a * i / 300 for i in range(301)]
    ax.plot(rs, [p0 * max(0.0, 1 - (r / a) ** 2) ** 0.5 for r in rs], "k-", label="Hertz")
    for row, marker in zip(sphere[1:], ["s", "o"]):
        points = [p for p in profile if float(p["h"]) == float(row["h"])]
        ax.plot([f(p, "r") for p in points], [f(p, "pressure") for p in points], marker, ms=3,
                label=f"ffeti, h = {row['h']} mm")
    ax.set_xlabel("r [mm]")
    ax.set_ylabel("contact pressure [MPa]")
    ax.set_title("Sphere on a rigid plane: contact pressure per slave node")
    ax.legend()
    fig.tight_layout()
    fig.savefig(os.path.join(OUT, "three-dimensions-sphere.png"), dpi=110)
    plt.close(fig)


def render():
    cubes, reference, factors, plane, sphere, profile = (
        read_csv(PAGE, t) for t in ("cubes", "reference", "factors", "plane", "sphere", "sphere-pressure"))
    write_profile(sphere, profile)
    run_row = read_csv(PAGE, "run")[0]
    write_plot(cubes)
    counts = [f(r, "hessian") for r in cubes]
    decomposed = [f(r, "hessian") for r in cubes if f(r, "n") >= 2 * HH]  # n = H/h: one subdomain per cube
    refined = [f(r, "hessian") for r in cubes if 2 * HH <= f(r, "n") <= 64]
    largest = cubes[-1]
    two, three = plane
    per_unknown = {key: (f(three, key) / f(three, "primal")) / (f(two, key) / f(two, "primal"))
                   for key in ("time_factor", "time_solve")}
    ratio = {n: f(next(r for r in factors if r["n"] == n and r["factor"] == "supernodal"), "time_factor")
             / f(next(r for r in factors if r["n"] == n and r["factor"] == "simplicial"), "time_factor")
             for n in {r["n"] for r in factors}}
    lines = [
        "# Three dimensions: the seed's model problem as two cubes",
        "",
        "Generated by `scripts/benchmark.sh three-dimensions` (do not edit by hand) on:",
        machine_line(run_row),
        "",
        "What exists in 3D so far: a third coordinate through the plugin (`fetiSetup(..., Z=)`), the six",
        "rigid modes of 3D elasticity among the kernel candidates, gluing, node-to-node contact on",
        "matching faces, node-to-face contact and rigid planes, sensitivities of node-to-node rows;",
        "ffeti-solve's 3D meshes, VTK output and a mortar contact are not done (issue 29).",
        "`edp/model-problem-3d.edp`: two unit cubes,",
        "−Δu = f with the 2D problem's data extruded along z (K = 2 × the P1 Laplacian, f = −3 for",
        "y > 0.75 in the first cube, −1 for y < 0.25 in the second), u = 0 on x = 0, the second cube",
        "floating, u1 ≤ u2 on the shared face; each cube split into (n/H)³ boxes of H/h cells per side",
        "(`ffetiGrid3`, tetrahedra of `cube()`), FETI-1, the default options (tol = 1e-4). Peak MB: the",
        "FreeFEM process's resident set (assembly included). Raw",
        f"data: [{PAGE}-cubes.csv]({PAGE}-cubes.csv), [{PAGE}-reference.csv]({PAGE}-reference.csv),",
        f"[{PAGE}-factors.csv]({PAGE}-factors.csv),",
        f"[{PAGE}-plane.csv]({PAGE}-plane.csv).",
        "",
        f"## Two cubes at H/h = {HH}",
        "",
        *markdown_table(cubes, CUBES),
        "",
        "![three dimensions](three-dimensions.png)",
        "",
        f"Reading: the Hessian count is {listing([int(v) for v in counts])} for n = {listing([r['n'] for r in cubes])}.",
        f"At n = {HH} each cube is one subdomain (H/h = {HH} leaves nothing to split); from n = {2 * HH} on, with",
        f"H/h fixed, it stays between {min(decomposed):.0f} and {max(decomposed):.0f}: over the two refinements to n = 64",
        f"at most {max(refined) / refined[0]:.2f} times its n = {2 * HH} value (the aim is 1.5 over three; the third,",
        "n = 128, would take 8,192 subdomains and 6 million unknowns, not run here). The largest problem,",
        f"{int(f(largest, 'primal')):,} unknowns in {largest['subdomains']} subdomains, is set up in",
        f"{f(largest, 'time_setup'):.1f} s (most of it FreeFEM's assembly of the subdomain matrices), factorized in",
        f"{f(largest, 'time_factor'):.1f} s and solved in {f(largest, 'time_solve'):.1f} s, in {f(largest, 'process_peak_mb') / 1024:.1f} GB.",
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
        "## Hertz for a sphere on a rigid plane",
        "",
        "`edp/hertz-sphere.edp`: an elastic sphere (R = 10 mm, E = 1000 MPa, ν = 0.3) pressed on a rigid",
        "plane, a quarter model (x ≥ 0, y ≥ 0, sliding on both symmetry planes) meshed by gmsh",
        "(`meshes/hertz-sphere.geo`, size h within 2.5 mm of the contact point), loaded by a pressure on",
        "its cut z = R (F about 500 N on the whole sphere: the mesh's polygonal cut applies a little",
        "less, and the analytic values use what it applies), Total FETI over 4 bands of z, the rigid",
        "plane as an obstacle, tol = 1e-6. Hertz: a = (3FR/(4E*))^(1/3), p0 = 3F/(2πa²), E* = E/(1 − ν²).",
        "a: halfway between the outermost closed row and the nearest open one, by radius; the pressure",
        "per slave node: its force over its share of the surface (`fetiContactPressure`), p0 the",
        "central node's; the L2 error over the rows within 1.2 a, weighted by their shares. Raw data",
        f"per row: [{PAGE}-sphere-pressure.csv]({PAGE}-sphere-pressure.csv).",
        "",
        *markdown_table(sphere, SPHERE),
        "",
        "![sphere](three-dimensions-sphere.png)",
        "",
        f"Reading: a is within {span([f(r, 'a_relerr') for r in sphere], '.2%')} of Hertz's (read off the mesh, to",
        f"about half a node spacing), p0 within {listing([f(r, 'p0_relerr') for r in sphere], '.1%')} for h =",
        f"{listing([r['h'] for r in sphere])} mm: within the 5 % aimed at and falling with h; the profile's L2 error",
        f"is {listing([f(r, 'pressure_l2_relerr') for r in sphere], '.1%')}. The contact forces",
        f"balance the load to {span([f(r, 'balance_error') for r in sphere], '.0e')}.",
        "",
        "## Simplicial or supernodal factors for 3D subdomains",
        "",
        *markdown_table(factors, FACTORS),
        "",
        "Reading: 3D subdomains fill more than 2D ones of the same size, where supernodal factors",
        "usually pay off; here, with subdomains of 17³ nodes, the supernodal factor takes",
        f"{span(list(ratio.values()), '.1f')} times the simplicial one's time (it runs on one thread, for Debian's",
        "serial BLAS, against the simplicial factors' threads over subdomains) and holds more",
        "nonzeros. The default stays simplicial in 3D too.",
        "",
        "## Beside the 2D model problem of about the same size",
        "",
        *markdown_table(plane, PLANE_COLUMNS),
        "",
        "Reading: the 3D problem's subdomains are smaller (729 unknowns at H/h = 8 against 4,225 at",
        f"H/h = 64 in 2D) and five times as many; per unknown its factorization costs",
        f"{per_unknown['time_factor']:.1f} times the plane problem's and its solve {per_unknown['time_solve']:.1f} times",
        f"with {f(three, 'hessian') / f(two, 'hessian'):.2f} times the Hessian multiplications: each costs more per unknown.",
        "",
    ]
    save_page(f"{PAGE}.md", lines)


if __name__ == "__main__":
    main()
