#!/usr/bin/env python3
"""Contact shape optimization (the seed's second half): the two design loops, what a
gradient costs against an analysis, and the gradient checks. Writes the raw data of one run
on this machine (docs/results/shape-optimization-<table>.csv: loops, history, costs,
gradient-checks, and the uniform-pressure sections', plane and 3D) and renders
docs/results/shape-optimization.md and its plots from it (--render: again from the CSVs;
the spanner pictures come from the run's stress fields, not kept, and stay as they are).
--only-3d: measure the 3D section alone (development; with --render: from its CSVs) and
write it beside its CSVs as shape-optimization-3d-section.md, leaving the page as it is;
--only-lug: the same for the lug's section (shape-optimization-lug-section.md)."""
import argparse
import glob
import os
import subprocess
import tempfile
import time

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.collections import PolyCollection  # noqa: E402

from ffeti_bench import (OUT, ROOT, begin_run, end_run, f, forget_run, machine_line, markdown_table, read_csv,  # noqa: E402
                         run, save_page, write_csv)
import lug_section  # noqa: E402
import uniform_pressure_3d_section  # noqa: E402
import uniform_pressure_section  # noqa: E402

MESHES = os.path.join(ROOT, "meshes")
BUILD = os.environ.get("FFETI_BUILD", os.path.join(ROOT, "build"))
# (label, script, arguments): the .edp gradient tests, run where the build's freefem++.pref is.
GRADIENT_CHECKS = [
    ("membranes (scalar, FETI-1, floating membrane), 4 B-spline heights", "sensitivity-membrane.edp", []),
    ("elastic blocks, node-to-segment on non-matching meshes, moving master face", "sensitivity-elastic.edp",
     ["-scene", 0]),
    ("elastic block on a tilted rigid obstacle, moving slaves", "sensitivity-elastic.edp", ["-scene", 1]),
    ("spanner: p-norm of von Mises, elasticity-extension velocities", "sensitivity-spanner.edp",
     ["-meshes", MESHES]),
]
# (label, history name, arguments) of the spanner loops: the default, a second start, the
# default's optimum on a finer mesh (one analysis: IPOPT's first step is not taken) and the
# loop on that mesh from the drawn spanner, and the loop at about 50,000 unknowns.
SPANNER_LOOPS = [
    ("lc = 1.9 (default)", "coarse", []),
    ("lc = 1.9, second start (every variable -1 mm)", "second", ["-start", -1]),
    ("lc = 1.0: the lc = 1.9 optimum evaluated", "carried", ["-lc", 1.0, "-parts", 6, "-from", "{folder}/coarse.history",
                                                           "-maxiter", 0]),
    ("lc = 1.0", "finer", ["-lc", 1.0, "-parts", 6]),
    ("lc = 0.4: the lc = 1.9 optimum evaluated", "carried_fine", ["-lc", 0.4, "-parts", 8, "-from",
                                                               "{folder}/coarse.history", "-maxiter", 0]),
    ("lc = 0.4", "fine", ["-lc", 0.4, "-parts", 8]),
]
SPANNER_PICTURES = {"coarse": "shape-optimization-spanner.png", "fine": "shape-optimization-spanner-fine.png"}
# (label, script, arguments) of the cost measurements (-costs 1).
COSTS = [
    ("membranes h = 1/128", "membrane-shape.edp", ["-n", 128, "-Hh", 64]),
    ("membranes h = 1/256", "membrane-shape.edp", ["-n", 256, "-Hh", 64]),
    ("spanner lc = 1.9", "spanner-opt.edp", ["-meshes", MESHES]),
    ("spanner lc = 0.4", "spanner-opt.edp", ["-meshes", MESHES, "-lc", 0.4, "-parts", 8]),
]


def gradient_check(script, args):
    command = ["FreeFem++-nw", "-v", "0", os.path.join(ROOT, "tests", "edp", script), *map(str, args)]
    text = subprocess.run(command, cwd=os.path.join(BUILD, "edp-tests"), capture_output=True, text=True,
                          check=True).stdout
    result = next(line for line in text.splitlines() if line.startswith("RESULT "))
    return dict(kv.split("=", 1) for kv in result.split()[1:])


def history(path):
    """Cost and extra value (the spanner's true maximum stress) of each design step from a
    design-loop history file (columns: k design variables, cost, constraint, extra, ...;
    3 k + 7 in all)."""
    with open(path) as file:
        rows, columns = (int(v) for v in file.readline().split())
        values = [[float(v) for v in file.readline().split()] for _ in range(rows)]
    k = (columns - 7) // 3
    return [row[k] for row in values], [row[k + 2] for row in values]


def triangles(prefix):
    """Triangles, von Mises stresses and cost masks of a field written by spanner-opt.edp."""
    polygons, values, masks = [], [], []
    for name in sorted(glob.glob(prefix + "-*.txt")):
        with open(name) as field:
            for line in field:
                v = [float(x) for x in line.split()]
                polygons.append([(v[0], v[1]), (v[2], v[3]), (v[4], v[5])])
                values.append(v[6])
                masks.append(v[7])
    return polygons, values, masks


def spanner_picture(folder, name):
    """Initial and optimized spanner (and nut), colours clipped at 1.2 times the largest
    stress the cost measures: the contact corners of the slot go far beyond it."""
    fields = [triangles(os.path.join(folder, "spanner-" + which)) for which in ("initial", "final")]
    measured = [max(v for v, m in zip(values, masks) if m > 0) for _, values, masks in fields]
    fig, axes = plt.subplots(2, 1, figsize=(8, 5.2))
    for ax, (polygons, values, _), peak, title in zip(axes, fields, measured, ["initial", "optimized"]):
        patches = PolyCollection(polygons, array=values, cmap="turbo", edgecolors="face", linewidths=0.1)
        patches.set_clim(0, 1.2 * max(measured))
        ax.add_collection(patches)
        ax.set_xlim(-92, 12)
        ax.set_ylim(-17, 17)
        ax.set_aspect("equal")
        ax.set_title(f"{title} design: von Mises [MPa], max {peak:.1f} away from the slot")
        fig.colorbar(patches, ax=ax, fraction=0.02, extend="max")
    fig.tight_layout()
    fig.savefig(os.path.join(OUT, name), dpi=120)
    plt.close(fig)


PAGE = "shape-optimization"
# The seed paper's spanner (published figures, not measured here): its design steps (a
# feasible direction method) and seconds per analysis in ODESSY, and in ANSYS (minutes).
SEED_SPANNER = {"steps": 79, "odessy_s": 13, "ansys_min": 12}
MEMBRANE_LOOP = "membranes, h = 1/128"


def history_plot(history_rows, name):
    """Left: cost over its initial value per design step (the membranes' loop and the
    pictured spanner loops); right: the spanners' true maximum von Mises stress (not the
    aggregate the loop minimizes) per design step. From shape-optimization-history.csv."""
    fig, (left, right) = plt.subplots(1, 2, figsize=(11, 3.8))
    loops = list(dict.fromkeys(r["loop"] for r in history_rows))
    for loop in loops:
        rows = [r for r in history_rows if r["loop"] == loop]
        costs = [f(r, "cost") for r in rows]
        label = loop if loop == MEMBRANE_LOOP else "spanner, " + loop
        left.plot(range(1, len(costs) + 1), [c / costs[0] for c in costs], "o-", ms=3, label=label)
        if loop != MEMBRANE_LOOP:
            right.plot(range(1, len(rows) + 1), [f(r, "true_max") for r in rows], "o-", ms=3, label=loop)
    left.set_xlabel("design step (analysis)")
    left.set_ylabel("cost / initial cost")
    left.set_title("Cost history")
    left.legend(fontsize=8)
    right.set_xlabel("design step (analysis)")
    right.set_ylabel("largest von Mises stress away from the slot [MPa]")
    right.set_title("Spanner: the true maximum")
    right.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(OUT, name), dpi=110)
    plt.close(fig)


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--render", action="store_true",
                        help="re-render the page from its CSVs, no run (the spanner pictures are kept)")
    parser.add_argument("--only-3d", action="store_true",
                        help="measure the 3D section alone and write it as shape-optimization-3d-section.md (not the page)")
    parser.add_argument("--only-lug", action="store_true",
                        help="measure the lug's section alone and write it as shape-optimization-lug-section.md")
    arguments = parser.parse_args()
    if arguments.only_lug:
        begun = begin_run()
        if not arguments.render:
            with tempfile.TemporaryDirectory() as folder:
                lug_section.measure(folder)
            end_run(PAGE, begun, "lug-run")
        save_page("shape-optimization-lug-section.md", lug_section.section())
        print(f"lug section: {time.time() - begun['started']:.0f} s")
        return
    if arguments.only_3d:
        begun = begin_run()
        if not arguments.render:
            with tempfile.TemporaryDirectory() as folder:
                uniform_pressure_3d_section.measure(folder)
        save_page("shape-optimization-3d-section.md", uniform_pressure_3d_section.section())
        print(f"3D section: {time.time() - begun['started']:.0f} s")
        return
    if not arguments.render:
        measure()
    render()


def measure():
    begun = begin_run()
    os.makedirs(OUT, exist_ok=True)
    with tempfile.TemporaryDirectory() as folder:
        loops, history_rows = [], []
        membrane = run("membrane-shape.edp", "-history", os.path.join(folder, "m.history"))["RESULT"][0]
        loops.append(dict(case="membranes h = 1/128", kind="membranes", **membrane))
        costs, _ = history(os.path.join(folder, "m.history"))
        history_rows += [dict(loop=MEMBRANE_LOOP, step=k + 1, cost=c) for k, c in enumerate(costs)]
        for label, name, args in SPANNER_LOOPS:
            path = os.path.join(folder, name + ".history")
            out = ["-out", os.path.join(folder, "spanner")] if name in SPANNER_PICTURES else []
            args = [a.replace("{folder}", folder) if isinstance(a, str) else a for a in args]
            r = run("spanner-opt.edp", "-meshes", MESHES, *args, "-history", path, *out)["RESULT"][0]
            loops.append(dict(case=label, kind="spanner", **r))
            if name in SPANNER_PICTURES:
                # The stress fields are drawn from the run's own files (tens of thousands of
                # triangles: not kept); the cost history of the pictured loops is kept.
                spanner_picture(folder, SPANNER_PICTURES[name])
                costs, true_max = history(path)
                history_rows += [dict(loop=label, step=k + 1, cost=c, true_max=m)
                                 for k, (c, m) in enumerate(zip(costs, true_max))]
        uniform_pressure_section.measure(folder)
        uniform_pressure_3d_section.measure(folder)
        lug_section.measure(folder)
    write_csv(PAGE, "loops", loops)
    write_csv(PAGE, "history", history_rows)
    write_csv(PAGE, "gradient-checks", [dict(case=label, **gradient_check(script, args))
                                        for label, script, args in GRADIENT_CHECKS])
    write_csv(PAGE, "costs", [dict(case=label, **run(script, *args, "-costs", 1, prefixes=("COSTS",))["COSTS"][0])
                              for label, script, args in COSTS])
    forget_run(PAGE, "lug-run")  # the lug's section is this run's now, not an earlier run's on its own
    end_run(PAGE, begun)


def maximum(r):
    if r["kind"] != "spanner":
        return "–"
    before, after = f(r, "vonmises_max0"), f(r, "vonmises_max")
    return f"{before:.1f} → {after:.1f} ({100 * (1 - after / before):.1f} %)"


def loop_label(r):
    if r["kind"] == "spanner":
        return f"spanner {r['case']}, {r['unknowns']} unknowns, {r['couples']} couples, {r['subdomains']} subdomains"
    return f"{r['case']} ({r.get('design', '').count(',') + 1} variables)"


LOOPS = [("loop", loop_label), ("design steps", "steps"),
         ("cost before → after", lambda r: f"{f(r, 'cost0'):.5g} → {f(r, 'cost'):.5g}"),
         ("max von Mises [MPa]", maximum), ("area / area0", lambda r: f"{f(r, 'volume') / f(r, 'volume0'):.6f}"),
         ("factorizations", "factorizations"), ("sensitivity solves", "sensitivity_solves"),
         ("analysis [s/step]", lambda r: f"{f(r, 'time_analysis') / int(r['steps']):.3f}"),
         ("gradient [s/step]", lambda r: f"{f(r, 'time_sensitivity') / int(r['steps']):.3f}"),
         ("total [s]", ("time_total", ".1f")), ("IPOPT status", "ipopt_status"), ("status", "status")]
COST_COLUMNS = [
    ("scene", "case"), ("unknowns", "unknowns"), ("subdomains", "subdomains"), ("k", "variables"),
    ("analysis [s]", ("analysis", ".3f")),
    ("direct, per variable [s] (x analysis)", lambda c: f"{f(c, 'direct_all') / f(c, 'variables'):.3f} "
                                                        f"({f(c, 'direct_all') / f(c, 'variables') / f(c, 'analysis'):.2f})"),
    ("of which plugin [s]", lambda c: f"{f(c, 'direct_plugin') / f(c, 'variables'):.4f}"),
    ("adjoint, all k [s] (x analysis)", lambda c: f"{f(c, 'adjoint_all'):.3f} ({f(c, 'adjoint_all') / f(c, 'analysis'):.2f})"),
    ("of which plugin [s]", ("adjoint_plugin", ".4f")), ("finite differences [s]", ("fd_all", ".2f")),
    ("Hessian mult.: state / direct, all k / adjoint", lambda c: " / ".join(
        str(int(f(c, key))) for key in ("state_hessian", "direct_hessian", "adjoint_hessian")))]
BLOCK_COLUMNS = [
    ("scene", "case"), ("unknowns", "unknowns"), ("subdomains", "subdomains"), ("k", "variables"),
    ("Hessian mult. per direction", lambda c: f"{f(c, 'direct_hessian') / f(c, 'variables'):.0f}"),
    ("plugin, one call each [s]", ("direct_plugin_one_by_one", ".4f")),
    ("plugin, one call for all k [s]", ("direct_plugin", ".4f")),
    ("speed-up", lambda c: f"{f(c, 'direct_plugin_one_by_one') / f(c, 'direct_plugin'):.2f}"),
    ("plugin share of the direct mode", lambda c: f"{f(c, 'direct_plugin') / f(c, 'direct_all'):.0%}"),
    ("difference", ("one_by_one_difference", ".1e"))]


def render():
    loops, history_rows, checks, costs = (read_csv(PAGE, table) for table in ("loops", "history", "gradient-checks",
                                                                              "costs"))
    run_row = read_csv(PAGE, "run")[0]
    history_plot(history_rows, "shape-optimization-history.png")
    uniform = uniform_pressure_section.section() + uniform_pressure_3d_section.section()
    write_page(uniform, loops, checks, costs, run_row)


def write_page(uniform, loops, checks, costs, run_row):
    by_name = {r["case"]: r for r in loops}
    spanners = [r for r in loops if r["kind"] == "spanner"]
    membrane = next(r for r in loops if r["kind"] == "membranes")
    carried, finer, carried_fine, fine = (by_name[label] for label, _, _ in SPANNER_LOOPS[2:6])
    same_design = abs(f(carried, "vonmises_max0") / f(finer, "vonmises_max") - 1)
    same_design_fine = abs(f(carried_fine, "vonmises_max0") / f(fine, "vonmises_max") - 1)
    one_per_subdomain = all(int(r["factorizations"]) == int(r["steps"]) * int(r["subdomains"]) for r in spanners)
    extra_solves = [r for r in loops if int(r["sensitivity_solves"]) != int(r["steps"])]
    membrane_change = abs(1 - f(membrane, "cost") / f(membrane, "cost0"))
    lines = [
        "# Contact shape optimization",
        "",
        "Generated by `scripts/benchmark.sh shape-optimization` (do not edit by hand) on:",
        machine_line(run_row),
        "",
        "The seed's second half: semi-analytic sensitivities (seed eq. 12) on the state's",
        "factorizations, and design loops driven by IPOPT (FreeFEM's ff-Ipopt, L-BFGS) with",
        "the plugin's adjoint gradients. One design step = one analysis (one factorization per",
        "subdomain) + one gradient. First the loop whose optimum is known (a uniform contact",
        "pressure), with the finite-difference peer beside it; then the seed's loops, and a lug",
        "in three dimensions whose design moves the mesh.",
        "",
        *uniform,
        "## The seed's loops",
        "",
        "`edp/spanner-opt.edp`: the spanner gripping a nut (`meshes/spanner.geo`, steel, plane",
        "stress, frictionless node-to-segment contact), the p-norm (p = 24) of the von Mises",
        "stress away from the slot minimized over the whole outer outline of the head and the",
        "head-handle transition (upper and lower curves from x = -45 mm, in the handle, to the",
        "jaw tips: 2 x 8 B-spline bumps, |alpha| <= 3 mm), area not above the drawn spanner's;",
        "the moved mesh is remeshed where an element keeps less than 0.2 of its area. \"max von",
        "Mises\" is the true maximum of the element stresses away from the slot, the quantity",
        "the p-norm stands in for. Is it an optimum: IPOPT's optimality test (status 0), the",
        "same design from a second start, and the same design on a finer mesh: the lc = 1.9",
        "optimum evaluated on the lc = 1.0 and 0.4 meshes has a true maximum within",
        f"{100 * same_design:.1f} % and {100 * same_design_fine:.1f} % of those loops' own optima (the",
        "element stresses' maximum itself still grows under refinement: it is a peak resolved",
        "by P1 elements). `edp/membrane-shape.edp`: the seed's membranes,",
        "minimal compliance over the bottom of membrane 1 (10 B-spline heights). Raw data:",
        f"[{PAGE}-loops.csv]({PAGE}-loops.csv) (one row per loop), [{PAGE}-history.csv]({PAGE}-history.csv) (the",
        "plotted loops' cost and true maximum per design step); the spanner pictures are drawn",
        "from the run's stress fields, which are not kept.",
        "",
        *markdown_table(spanners + [membrane], LOOPS),
        "",
        ("Factorizations equal the design steps times the subdomains in every spanner loop: one"
         if one_per_subdomain else "Factorizations are not the design steps times the subdomains in every spanner loop: one"),
        "factorization per subdomain and design step, whatever the number of design variables;",
        "sensitivity solves are one adjoint solve per step"
        + ("." if not extra_solves else ", except in " + ", ".join(
            f"{r['case']} ({r['sensitivity_solves']} for {r['steps']} steps)" for r in extra_solves) + "."),
        f"The seed needed {SEED_SPANNER['steps']} design steps for its spanner (a feasible direction method)",
        f"and {SEED_SPANNER['odessy_s']} s per analysis in ODESSY (ANSYS: {SEED_SPANNER['ansys_min']} minutes). The",
        "\"evaluated\" rows take the lc = 1.9 optimum as their start and stop there (IPOPT at its",
        "iteration limit, hence their status): their \"before\" is that design on the finer mesh.",
        "",
        "The membranes' loop stays as the seed's example of the gradient machinery on a scalar",
        "problem, not as a design result: the bottom curve of membrane 1 hardly controls its",
        f"compliance (the loop moves it by {100 * membrane_change:.1f} %). The",
        "contact design that a reader cares about, the contact pressure, is the uniform-pressure",
        "scene above, which replaces it as the demonstration.",
        "",
        "![spanner](shape-optimization-spanner.png)",
        "",
        "![spanner, fine mesh](shape-optimization-spanner-fine.png)",
        "",
        "![history](shape-optimization-history.png)",
        "",
        *lug_section.section(),
        "## What a gradient costs",
        "",
        "At the initial design (`-costs 1`): one analysis (assembly, set-up, solve), the k",
        "direct sensitivities (per variable K' and f' by central differences of assembled",
        "matrices on moved meshes, then the k sensitivity QPs in one call), the adjoint gradient,",
        "and the central finite-difference gradient (2k analyses). Adjoint, membranes: one",
        "adjoint solve, then per variable K', f' by central differences and a product",
        "(`fetiAdjointGradient`); spanner: one adjoint solve, then the exact P1 shape",
        "derivatives as one nodal shape gradient per subdomain (two varfs), each variable a dot",
        "product with its velocity. \"plugin\" is the part spent in the plugin's solves; the rest",
        f"is FreeFEM (assembly of K', the cost's derivatives). Raw data: [{PAGE}-costs.csv]({PAGE}-costs.csv).",
        "",
        *markdown_table(costs, COST_COLUMNS),
        "",
        "## Many directions at once",
        "",
        "The direct mode hands all k design directions to one `fetiSensitivity` call: their",
        "dual CG runs go in lockstep, and each step applies F to the block of their search",
        "directions (one CHOLMOD solve with several right-hand sides per subdomain, one pass over",
        "each factor). The same k directions, then solved one call each on the same state, give",
        "the comparison (same Hessian multiplications per direction; \"difference\": largest",
        "|z_block - z_single| over the largest |z|, at the solve's tolerance).",
        "",
        *markdown_table(costs, BLOCK_COLUMNS),
        "",
        "## Gradient checks",
        "",
        "The regression tests (`ctest -R sensitivity`) compare the semi-analytic gradient with",
        "central finite differences of full re-solves (tol = 1e-10 to 1e-12, the contact set",
        "checked unchanged), and the adjoint with the direct mode; errors relative to the",
        f"largest gradient component. Raw data: [{PAGE}-gradient-checks.csv]({PAGE}-gradient-checks.csv).",
        "",
        *markdown_table(checks, [("scene", "case"), ("J", ("J", ".6g")), ("direct vs finite differences", ("fd_error", ".1e")),
                                 ("adjoint vs direct", ("adjoint_error", ".1e"))]),
        "",
    ]
    save_page(f"{PAGE}.md", lines)


if __name__ == "__main__":
    main()
