"""The three-dimensional part of docs/results/shape-optimization.md: the known optimum of
edp/uniform-pressure-3d.edp (a square punch on a block, quarter model, tensor-product
B-spline surface as the contact gap) on two meshes, the same loop with adjoint, direct
and finite-difference gradients side by side, and the gradient checks including lambda'.
measure() writes the raw data (docs/results/shape-optimization-uniform-pressure-3d.csv,
one row per loop; ...-3d-profiles.csv, pressure and surface per contact node; ...-3d-checks.csv,
the gradient checks; ...-3d-variants.csv, the Newton loops and the mortar punch, one row per
loop; ...-3d-mortar-checks.csv, the mortar punch's gradient checks); section() draws the
picture and renders the section from them.

Run alone for development (the page is written by scripts/shape_optimization_benchmark.py):
    FFETI_RUN_DIR=build/edp-tests FFETI_RESULTS=/tmp/so3d python3 scripts/shape_optimization_benchmark.py --only-3d
measures this part into FFETI_RESULTS and writes the section there as
shape-optimization-3d-section.md, leaving the page alone."""
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.tri import Triangulation  # noqa: E402

from ffeti_bench import OUT, f, markdown_table, read_csv, run, write_csv  # noqa: E402
from uniform_pressure_section import measure_loops  # noqa: E402

SCRIPT = "uniform-pressure-3d.edp"
PAGE, TABLE = "shape-optimization", "uniform-pressure-3d"
PICTURE = "shape-optimization-uniform-pressure-3d.png"
# (cost, m, k, gradient), k B-splines per direction (k x k variables): the energy's optimum
# on the default mesh (m = 8 cells across the contact zone) and on a finer one with more
# variables, the pressure's P-mean on the default mesh; the peers at 16 variables on the
# coarsest mesh (m = 4: about 140 design steps, each 33 analyses with finite differences).
OPTIMA = [("energy", 8, 4, "adjoint"), ("pressure", 8, 4, "adjoint"), ("energy", 12, 5, "adjoint")]
PEERS = [("energy", 4, 4, gradient) for gradient in ("adjoint", "direct", "fd")]
LOOPS = OPTIMA + [loop for loop in PEERS if loop not in OPTIMA]
CHECKS = [(cost, m) for cost in ("energy", "pressure") for m in (4, 8)]
# The Newton loop (-optimizer newton: the energy's exact Hessian from one direct sensitivity
# call per step, edp/design-newton.idp) on the energy's meshes of OPTIMA, beside IPOPT's.
NEWTON = [loop for loop in OPTIMA if loop[0] == "energy"]
# The punch on a block meshed apart (-contact mortar: m + 1 cells per 10 mm, mortar rows) on
# the default mesh, beside the node-to-node loop of OPTIMA[0]; its gradient checks on m = 4.
MORTAR = [OPTIMA[0]]
MORTAR_CHECKS = [(cost, 4) for cost in ("energy", "pressure")]


def key(r):
    """(cost, m, k, gradient) of a loop's row."""
    return r["cost_name"], int(r["m"]), int(r["k"]), r["gradient"]


def profile_rows(profiles, loop):
    """The profile rows of one loop (cost, m, k, gradient)."""
    return [r for r in profiles if (r["cost"], int(r["m"]), int(r["k"]), r["gradient"]) == loop]


def measure(folder):
    """Runs every loop of LOOPS and the gradient checks; writes their raw data (one row per
    loop, the pressure and surface per contact node and loop, one row per check)."""
    measure_loops(SCRIPT, TABLE, LOOPS, CHECKS, folder)
    measure_variants(folder)


def measure_variants(folder):
    """Runs the Newton loops and the mortar punch; writes ...-3d-variants.csv (one row per
    loop, `variant` newton or mortar) and ...-3d-mortar-checks.csv (its gradient checks)."""
    rows = []
    for variant, loops, options in (("newton", NEWTON, ("-optimizer", "newton")), ("mortar", MORTAR, ("-contact", "mortar"))):
        for cost, m, k, gradient in loops:
            history = os.path.join(folder, f"{TABLE}-{variant}-{cost}-m{m}-k{k}-{gradient}.history")
            rows.append(dict(variant=variant, **run(SCRIPT, *options, "-cost", cost, "-m", m, "-k", k, "-gradient", gradient,
                                                    "-history", history)["RESULT"][0]))
    write_csv(PAGE, f"{TABLE}-variants", rows)
    write_csv(PAGE, f"{TABLE}-mortar-checks", [
        run(SCRIPT, "-contact", "mortar", "-gradcheck", 1e-5, "-cost", cost, "-m", m, prefixes=("GRADCHECK",))["GRADCHECK"][0]
        for cost, m in MORTAR_CHECKS])


def mirrored(rows, column):
    """x, y and a column of the quarter's rows mirrored to the whole face (for the picture)."""
    points = {}
    for r in rows:
        for sx in (1, -1):
            for sy in (1, -1):
                points[(round(sx * f(r, "x"), 9), round(sy * f(r, "y"), 9))] = f(r, column)
    xs, ys = zip(*points)
    return list(xs), list(ys), list(points.values())


def picture(profiles, uniform, name):
    """The contact pressure over the whole face (the quarter mirrored) before and after (the
    energy's loop on the default mesh), on one colour scale centred on q, and the pressure
    along the diagonal and the mid-line of the quarter for every optimum."""
    rows = profile_rows(profiles, OPTIMA[0])
    fig, axes = plt.subplots(1, 3, figsize=(15, 4.4), layout="constrained", gridspec_kw={"width_ratios": [1, 1, 1.3]})
    fig.get_layout_engine().set(wspace=0.06)  # room between the colour bar's label and the right panel's
    top = max(f(r, "pressure0") for r in rows)
    spread = max(top - uniform, uniform)
    for ax, column, title in zip(axes[:2], ("pressure0", "pressure"), ("crowned start", "optimum of the energy")):
        x, y, p = mirrored(rows, column)
        shading = ax.tripcolor(Triangulation(x, y), p, cmap="RdBu_r", vmin=uniform - spread, vmax=uniform + spread,
                               shading="gouraud")
        ax.set_aspect("equal")
        ax.set_title(f"{title}: {min(p):.0f} to {max(p):.0f} MPa", fontsize=10)
        ax.set_xlabel("x [mm]")
    axes[0].set_ylabel("y [mm] (the whole face: the quarter mirrored)")
    fig.colorbar(shading, ax=axes[1], fraction=0.05, label="contact pressure [MPa] (white: q)")
    right = axes[2]
    for colour, (cost, m, k, gradient) in zip(("C1", "C2", "C3"), OPTIMA):
        loop = profile_rows(profiles, (cost, m, k, gradient))
        diagonal = sorted((f(r, "x"), r) for r in loop if abs(f(r, "x") - f(r, "y")) < 1e-9)
        if (cost, m, k) == OPTIMA[0][:3]:
            right.plot([x for x, _ in diagonal], [f(r, "pressure0") for _, r in diagonal], "C0.-",
                       label=f"crowned start, m = {m}")
        right.plot([x for x, _ in diagonal], [f(r, "pressure") for _, r in diagonal], colour, marker=".",
                   label=f"optimum of the {cost}, m = {m}, {k} x {k}")
    right.axhline(uniform, color="k", lw=0.8, ls=":", label=f"q = {uniform:g} MPa")
    right.set_xlabel("x = y [mm] (the diagonal, centre to corner)")
    right.set_ylabel("pressure [MPa]")
    right.legend(fontsize=7)
    right.set_title("along the diagonal", fontsize=10)
    fig.savefig(os.path.join(OUT, name), dpi=110)
    plt.close(fig)


def multiplier_error(r):
    """|multiplier / q - 1| of an energy loop (the RESULT line prints 8 digits: 0 is below 5e-8)."""
    if r["cost_name"] == "pressure":
        return "–"
    error = abs(f(r, "multiplier") / f(r, "pressure_uniform") - 1)
    return f"{error:.1e}" if error > 0 else "< 5e-8"


def optimum_columns():
    """The columns shared by the Newton and the mortar tables: the optimum each loop reached."""
    return [("cv before → after", lambda r: f"{f(r, 'pressure_cv0'):.3f} → {f(r, 'pressure_cv'):.1e}"),
            ("material / material0", ("material_ratio", ".4f")), ("bound's multiplier [MPa]", ("multiplier", ".4f")),
            ("\\|multiplier / q − 1\\|", multiplier_error), ("stationarity", ("stationarity", ".1e"))]


def variant_lines(results):
    """The Markdown lines of the Newton-against-IPOPT and the mortar tables, from the variants'
    CSV and the loops of OPTIMA in results (their IPOPT and node-to-node counterparts)."""
    variants = read_csv(PAGE, f"{TABLE}-variants")
    mortar_checks = read_csv(PAGE, f"{TABLE}-mortar-checks")
    pairs = []
    for r in variants:
        if r["variant"] == "newton":
            pairs += [results[key(r)], r]
    mortar = []
    for r in variants:
        if r["variant"] == "mortar":
            mortar += [results[key(r)], r]
    return [
        "### Newton against IPOPT",
        "",
        "The energy's loops of the table above again with `-optimizer newton`",
        "(`edp/design-newton.idp`): a trust-region Newton loop on the energy's exact Hessian,",
        "H = −Φ'λ' with all k x k columns λ' from one direct `fetiSensitivity` call per Hessian",
        "(docs/algorithms.md); IPOPT uses L-BFGS on the adjoint gradients. Designs: the analyses",
        "the loop asked for (each with its adjoint gradient); sensitivity solves: the adjoint's",
        "and the Hessians' directions. Newton stops at stationarity 1e-6 (`-newtontol`), IPOPT",
        "at its own tolerance. The dual Hessian multiplications are not recorded per loop.",
        "",
        *markdown_table(pairs, [
            ("optimizer", "optimizer"), ("m", "m"), ("variables", lambda r: f"{r['k']} x {r['k']}"),
            ("designs", "steps"), ("Newton steps / Hessians", lambda r: f"{r['newton_steps']} / {r['hessians']}"
                                   if r["optimizer"] == "newton" else "–"),
            ("sensitivity solves", lambda r: int(r["sensitivity_solves"]) + int(r.get("hessian_solves") or 0)),
            ("total [s]", ("time_total", ".1f")), ("of it Hessians [s]", ("time_hessian", ".1f")),
            ("final cost", ("cost", ".8g")), *optimum_columns(), ("status", "status")]),
        "",
        "### Mortar contact on a block meshed apart",
        "",
        "`-contact mortar`: the block meshed with m + 1 cells per 10 mm, so that its top's nodes",
        "lie off the punch's (but on the symmetry planes and the punch's edges), mortar rows",
        "(`contactSlaveFaces`: the punch's bottom, the coarser side, as slave). A mortar row's gap",
        "is its normal gap weighted over the slave node's support and divided by the support's",
        "integral, plus the design gap weighted alike, (M h)_n / w_n (`contactGap`; M the punch",
        "bottom's mass matrix, w_n its row sums, h the surface at the nodes): at the optimum the",
        "projection of the traction on the design space is uniform (docs/algorithms.md). The",
        "pressure is the row's force over the node's share of the punch's face, the nodal value",
        "of the linear traction the rows transmit. Same start surface, same loop (IPOPT, adjoint",
        "gradients) as the node-to-node row beside it. The optimum's conditions hold alike (the",
        "multiplier q, stationarity); the nodal traction keeps a ripple at the mesh's scale that",
        "the 4 x 4 surface does not reach, so its cv after is the larger (its consistent nodal",
        "forces over the shares are nearly as even as node to node's: docs/log.md, 2026-11-27).",
        "",
        *markdown_table(mortar, [
            ("contact", lambda r: "mortar, non-matching" if r["contact"] == "mortar" else "node to node, matching"),
            ("block cells per 10 mm", "block_cells"), ("m", "m"), ("variables", lambda r: f"{r['k']} x {r['k']}"),
            ("contact rows", "couples"), ("designs", "steps"), *optimum_columns(),
            ("total [s]", ("time_total", ".1f")), ("status", "status")]),
        "",
        "Its gradient checks at the crowned start (`-contact mortar -gradcheck`; `ctest -R",
        "uniform_pressure_3d_gradients_mortar` asserts 1e-5 on the energy's):",
        "",
        *checks_table(mortar_checks),
        "",
    ]


def checks_table(rows):
    """The gradient checks' table (node to node's and mortar's alike)."""
    return markdown_table(rows, [
        ("cost", "cost_name"), ("m", "m"), ("variables", "variables"),
        ("active / contact rows", lambda c: f"{c['active']} / {c['rows']}"),
        ("adjoint vs direct", ("adjoint_vs_direct", ".1e")), ("direct vs finite differences", ("direct_vs_fd", ".1e")),
        ("lambda' vs finite differences", ("dlambda_vs_fd", ".1e")), ("status", "status")])


def section():
    """Draws the picture and returns the Markdown lines of the section, from the CSVs."""
    results = {key(r): r for r in read_csv(PAGE, TABLE)}
    profiles, checks = read_csv(PAGE, f"{TABLE}-profiles"), read_csv(PAGE, f"{TABLE}-checks")
    uniform = f(results[OPTIMA[0]], "pressure_uniform")
    picture(profiles, uniform, PICTURE)
    peers = [results[loop] for loop in PEERS]
    base = results[PEERS[0]]
    for r in peers:
        r["analyses"] = int(r["steps"]) * (1 + 2 * int(r["variables"])) if r["gradient"] == "fd" else int(r["steps"])
        r["time_ratio"] = f(r, "time_total") / f(base, "time_total")
    lines = [
        "## In three dimensions: a square punch",
        "",
        "`edp/uniform-pressure-3d.edp`: an elastic punch of square cross-section (half width 10",
        f"mm, height 10 mm) pressed by q = {uniform:g} MPa onto an elastic block (half width 20 mm,",
        "depth 10 mm, clamped below), steel, a quarter model (frictionless symmetry planes x = 0",
        "and y = 0), 2 x 2 subdomains per body, Total FETI, the punch floating, node-to-node",
        "contact on matching faces. The design is the punch's bottom surface, a tensor product of",
        "the plane scene's cubic B-splines (k x k variables) entering each contact row as its gap;",
        "the bound: the material the surface removes (the volume under the piecewise linear",
        "face, the nodes' shares of the face as weights) not above the crowned start's. The 2D",
        "argument carries over (docs/algorithms.md, \"In three dimensions\"): the energy's optimum",
        "has a uniform pressure over the whole face and the bound's multiplier equal to q. cv:",
        "over the nodes in contact off the contact zone's boundary (the punch's edges, and any",
        "node next to one out of contact); max: over every node, edges and corner included;",
        "factorizations: those made after the loop's first set-up (none: new gaps re-solve on it).",
        f"Raw data: [{PAGE}-{TABLE}.csv]({PAGE}-{TABLE}.csv) (one row per loop),",
        f"[{PAGE}-{TABLE}-profiles.csv]({PAGE}-{TABLE}-profiles.csv) (pressure and surface per contact node),",
        f"[{PAGE}-{TABLE}-checks.csv]({PAGE}-{TABLE}-checks.csv) (the gradient checks).",
        "",
        *markdown_table([results[loop] for loop in OPTIMA], [
            ("cost", "cost_name"), ("mesh (cells across the zone)", "m"),
            ("variables", lambda r: f"{r['k']} x {r['k']}"), ("design steps", "steps"),
            ("cv before", ("pressure_cv0", ".3f")), ("cv after", ("pressure_cv", ".1e")),
            ("max pressure before → after [MPa]", lambda r: f"{f(r, 'pressure_max0'):.1f} → {f(r, 'pressure_max'):.1f}"),
            ("material / material0", ("material_ratio", ".4f")),
            ("bound's multiplier [MPa]", lambda r: "– (held equal: the cost does not see it)" if r["cost_name"] == "pressure"
             else f"{f(r, 'multiplier'):.4f}" if r["material_active"] == "1" else "– (not active)"),
            ("\\|multiplier / q − 1\\|", multiplier_error),
            ("stationarity", ("stationarity", ".1e")), ("factorizations", "factorizations"),
            ("total [s]", ("time_total", ".1f")), ("status", "status")]),
        "",
        f"![uniform pressure in 3D]({PICTURE})",
        "",
        "### The peer in three dimensions",
        "",
        f"The energy's loop on the m = {base['m']} mesh at {base['variables']} variables with adjoint gradients (one adjoint solve, then one",
        "product per variable), direct sensitivities (all directions in one `fetiSensitivity`",
        "call) and central differences of full re-solves (2 x variables analyses per gradient).",
        "Same optimum: compare the final cost, cv and multiplier.",
        "",
        *markdown_table(peers, [
            ("gradient", "gradient"), ("variables", "variables"), ("design steps", "steps"),
            ("analyses (incl. gradients)", "analyses"), ("factorizations", "factorizations"),
            ("total [s]", ("time_total", ".1f")), ("x adjoint's time", ("time_ratio", ".1f")),
            ("final cost", ("cost", ".8g")), ("cv after", ("pressure_cv", ".1e")),
            ("multiplier [MPa]", ("multiplier", ".4f")), ("status", "status")]),
        "",
        *variant_lines(results),
        "### Gradient checks in three dimensions",
        "",
        "At the crowned start (`-gradcheck`), as in the plane: adjoint against direct, direct",
        "against central differences of re-solves, lambda' against differences of the contact",
        "forces; relative to the largest entry (`ctest -R uniform_pressure_3d` asserts 1e-5 on m = 4).",
        "",
        *checks_table(checks),
        "",
    ]
    return lines
