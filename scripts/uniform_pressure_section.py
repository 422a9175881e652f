"""The uniform-pressure part of docs/results/shape-optimization.md: the known optimum
(edp/uniform-pressure.edp) on two meshes and for both costs, the same loops with adjoint,
direct and finite-difference gradients side by side, and the gradient checks including
lambda'. measure() writes the raw data (docs/results/shape-optimization-uniform-pressure.csv,
one row per loop; ...-profiles.csv, pressure and profile per node; ...-checks.csv, the
gradient checks); section() draws the picture and renders the section from them."""
import csv
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from ffeti_bench import OUT, f, markdown_table, read_csv, run, write_csv  # noqa: E402

SCRIPT = "uniform-pressure.edp"
PAGE, TABLE = "shape-optimization", "uniform-pressure"
# (cost, m, k, gradient): the optimum of both costs on two meshes (12 variables), then the
# peers: the energy at 20 variables (m = 32: 33 contact nodes; more variables than nodes
# leaves the optimum non-unique), the pressure's P-mean at 12 (its loop takes about 200
# design steps, each 2k + 1 analyses with finite differences).
OPTIMA = [(cost, m, 12, "adjoint") for cost in ("energy", "pressure") for m in (16, 32)]
PEERS = [("energy", 32, 20, gradient) for gradient in ("adjoint", "direct", "fd")] + [
    ("pressure", 16, 12, gradient) for gradient in ("adjoint", "direct", "fd")]
LOOPS = OPTIMA + [loop for loop in PEERS if loop not in OPTIMA]


def key(r):
    """(cost, m, k, gradient) of a loop's row."""
    return r["cost_name"], int(r["m"]), int(r["k"]), r["gradient"]


def measure(folder):
    """Runs every loop of LOOPS and the gradient checks; writes their raw data:
    shape-optimization-uniform-pressure.csv (one row per loop),
    shape-optimization-uniform-pressure-profiles.csv (pressure and profile per node and loop)
    and shape-optimization-uniform-pressure-checks.csv (one row per gradient check)."""
    measure_loops(SCRIPT, TABLE, LOOPS, [(cost, m) for cost in ("energy", "pressure") for m in (16, 32)], folder)


def measure_loops(script, table, loops, checks, folder):
    """Runs the design loops (cost, m, k, gradient) of a uniform-pressure scene with -profile
    and its gradient checks (cost, m); writes shape-optimization-<table>.csv (one row per
    loop), ...-profiles.csv (the profile file's rows per loop) and ...-checks.csv."""
    results, profiles = [], []
    for cost, m, k, gradient in loops:
        name = f"{table}-{cost}-m{m}-k{k}-{gradient}"
        profile = os.path.join(folder, name + ".csv")
        results.append(run(script, "-cost", cost, "-m", m, "-k", k, "-gradient", gradient,
                           "-history", os.path.join(folder, name + ".history"), "-profile", profile)["RESULT"][0])
        with open(profile) as file:
            profiles += [dict(cost=cost, m=m, k=k, gradient=gradient, **row) for row in csv.DictReader(file)]
    write_csv(PAGE, table, results)
    write_csv(PAGE, f"{table}-profiles", profiles)
    write_csv(PAGE, f"{table}-checks", [
        run(script, "-gradcheck", 1e-5, "-cost", cost, "-m", m, prefixes=("GRADCHECK",))["GRADCHECK"][0]
        for cost, m in checks])


def picture(profiles, uniform, name):
    """Pressure before and after against the uniform pressure, and the profiles, from the
    raw profiles (the loops with adjoint gradients and 12 variables)."""
    fig, (top, bottom) = plt.subplots(2, 1, figsize=(7, 6.4), sharex=True)
    styles = {16: "-", 32: "--"}
    for cost, m, k, gradient in OPTIMA:
        rows = [r for r in profiles if (r["cost"], int(r["m"]), int(r["k"]), r["gradient"]) == (cost, m, k, gradient)]
        x = [f(r, "x") for r in rows]
        colour = "C1" if cost == "energy" else "C2"
        if cost == "energy":
            top.plot(x, [f(r, "pressure0") for r in rows], "C0" + styles[m], marker=".", label=f"initial (crowned), m = {m}")
            bottom.plot(x, [1e3 * f(r, "profile0") for r in rows], "C0" + styles[m], label=f"initial, m = {m}")
        marker = "." if cost == "energy" else "x"
        top.plot(x, [f(r, "pressure") for r in rows], colour + styles[m], marker=marker, ms=5,
                 label=f"optimum of the {cost}, m = {m}")
        bottom.plot(x, [1e3 * f(r, "profile") for r in rows], colour + styles[m], label=f"optimum of the {cost}, m = {m}")
    top.axhline(uniform, color="k", lw=0.8, ls=":", label=f"uniform pressure q = {uniform:g} MPa")
    top.set_ylabel("contact pressure [MPa]")
    top.set_title("Contact pressure and punch profile, before and after (half model)")
    top.legend(fontsize=7, ncol=2)
    bottom.set_xlabel("x [mm] (the punch's half width is 10 mm)")
    bottom.set_ylabel("profile h(x) [µm]")
    bottom.legend(fontsize=7, ncol=2)
    fig.tight_layout()
    fig.savefig(os.path.join(OUT, name), dpi=110)
    plt.close(fig)


def multiplier(r):
    if r["cost_name"] == "pressure":
        return "– (the cost does not see the material)"
    return f"{f(r, 'area_multiplier'):.3f}" if r["area_active"] == "1" else "– (not active)"


def section():
    """Draws the picture and returns the Markdown lines of the section, from the CSVs."""
    results = {key(r): r for r in read_csv(PAGE, TABLE)}
    profiles, checks = read_csv(PAGE, f"{TABLE}-profiles"), read_csv(PAGE, f"{TABLE}-checks")
    uniform = f(results[OPTIMA[0]], "pressure_uniform")
    picture(profiles, uniform, "shape-optimization-uniform-pressure.png")
    peers = [results[loop] for loop in PEERS]
    for r in peers:
        base = next(p for p in peers if p["cost_name"] == r["cost_name"] and p["gradient"] == "adjoint")
        r["analyses"] = int(r["steps"]) * (1 + 2 * int(r["k"])) if r["gradient"] == "fd" else int(r["steps"])
        r["time_ratio"] = f(r, "time_total") / f(base, "time_total")
    energy_peer, pressure_peer = PEERS[0], PEERS[-1]
    lines = [
        "## A known optimum: uniform contact pressure",
        "",
        "`edp/uniform-pressure.edp`: an elastic punch (half width 10 mm, 2 x 2 subdomains) pressed",
        f"by a uniform pressure q = {uniform:g} MPa onto an elastic foundation (3 x 2 subdomains),",
        "plane strain steel, half model, Total FETI, the punch floating (SMALBE-M). The design is",
        "the punch's bottom profile, a cubic B-spline entering each contact row as its gap",
        "(`contactGap`); the bound: the material the profile removes not above the initial",
        "(crowned) punch's. Minimizing the potential energy at equal material has the uniform",
        "pressure as its exact discrete optimum, with the material's multiplier equal to that",
        "pressure (docs/algorithms.md, \"A known optimum\"). The P-mean of the pressure (P = 8, the",
        "smooth stand-in for its maximum; its gradient needs lambda') has the same optimum.",
        "Pressure: force over the node's share of the contact line (`fetiContactPressure`);",
        "cv: its coefficient of variation over the nodes in contact without the outermost one",
        "(share-weighted); stationarity: the largest gradient component left after the bound's",
        "multiplier, over the free variables, relative to the largest at the start;",
        "factorizations: those the loop made after its first set-up's (each design's new gaps are",
        "solved on that set-up's factorizations, `-resolve 1`, the default: none). Raw data:",
        f"[{PAGE}-{TABLE}.csv]({PAGE}-{TABLE}.csv) (one row per loop), [{PAGE}-{TABLE}-profiles.csv]({PAGE}-{TABLE}-profiles.csv)",
        f"(pressure and profile per node), [{PAGE}-{TABLE}-checks.csv]({PAGE}-{TABLE}-checks.csv) (the gradient checks).",
        "",
        *markdown_table([results[loop] for loop in OPTIMA], [
            ("cost", "cost_name"), ("mesh (cells across the zone)", "m"), ("k", "k"), ("design steps", "steps"),
            ("cv before", ("pressure_cv0", ".3f")), ("cv after", ("pressure_cv", ".1e")),
            ("max pressure before → after [MPa]", lambda r: f"{f(r, 'pressure_max0'):.1f} → {f(r, 'pressure_max'):.2f}"),
            ("material / material0", lambda r: f"{f(r, 'volume') / f(r, 'volume0'):.4f}"),
            ("bound's multiplier [MPa]", multiplier), ("stationarity", ("stationarity", ".1e")),
            ("factorizations", "factorizations"), ("total [s]", ("time_total", ".2f")), ("status", "status")]),
        "",
        "![uniform pressure](shape-optimization-uniform-pressure.png)",
        "",
        "## The peer, side by side: what the semi-analytic gradients buy",
        "",
        "The same IPOPT loops with (a) the plugin's adjoint gradient (one adjoint solve per",
        "design step, then one product per variable), (b) direct sensitivities (the k",
        "directions in one `fetiSensitivity` call), (c) central finite differences of full",
        "re-solves (what a script without the plugin's sensitivities does: 2k analyses per",
        f"gradient, step 1e-6 mm): the energy with k = {energy_peer[2]} variables on the m = {energy_peer[1]} mesh, the",
        f"pressure's P-mean with k = {pressure_peer[2]} on m = {pressure_peer[1]}. Same optimum: compare the final cost and cv.",
        "",
        *markdown_table(peers, [
            ("cost", "cost_name"), ("k", "k"), ("gradient", "gradient"), ("design steps", "steps"),
            ("analyses (incl. gradients)", "analyses"), ("factorizations", "factorizations"),
            ("sensitivity solves", "sensitivity_solves"), ("total [s]", ("time_total", ".2f")),
            ("x (a)'s time", ("time_ratio", ".1f")), ("final cost", ("cost", ".8g")), ("cv after", ("pressure_cv", ".1e")),
            ("status", "status")]),
        "",
        "### Gradient checks of the gap design",
        "",
        "At the initial design (`-gradcheck`): the adjoint against the direct gradient, the",
        "direct gradient against central differences of re-solves, and lambda' (direct mode,",
        "`dLambda`) against central differences of the contact forces; errors relative to the",
        "largest entry (`ctest -R uniform_pressure_gradients` asserts them below 1e-5).",
        "",
        *markdown_table(checks, [
            ("cost", "cost_name"), ("m", "m"), ("k", "k"), ("active / contact rows", lambda c: f"{c['active']} / {c['rows']}"),
            ("adjoint vs direct", ("adjoint_vs_direct", ".1e")), ("direct vs finite differences", ("direct_vs_fd", ".1e")),
            ("lambda' vs finite differences", ("dlambda_vs_fd", ".1e")), ("status", "status")]),
        "",
    ]
    return lines
