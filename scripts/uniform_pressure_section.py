"""The uniform-pressure part of docs/results/shape-optimization.md: the known optimum
(edp/uniform-pressure.edp) on two meshes and for both costs, the same loops with adjoint,
direct and finite-difference gradients side by side, and the gradient checks including
lambda'. Raw data: docs/results/shape-optimization-uniform-pressure.csv (one row per loop)
and shape-optimization-uniform-pressure-profiles.csv (pressure and profile per node)."""
import csv
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from ffeti_bench import OUT, f, run  # noqa: E402

SCRIPT = "uniform-pressure.edp"
LOOP_KEYS = ["cost_name", "gradient", "m", "k", "couples", "steps", "cost0", "cost", "pressure_cv0", "pressure_cv",
             "pressure_mean", "pressure_max0", "pressure_max", "volume0", "volume", "area_active", "area_multiplier",
             "stationarity", "factorizations", "sensitivity_solves", "time_analysis", "time_sensitivity",
             "time_total", "ipopt_status", "status"]
# (cost, m, k, gradient): the optimum of both costs on two meshes (12 variables), then the
# peers: the energy at 20 variables (m = 32: 33 contact nodes; more variables than nodes
# leaves the optimum non-unique), the pressure's P-mean at 12 (its loop takes about 200
# design steps, each 2k + 1 analyses with finite differences).
OPTIMA = [(cost, m, 12, "adjoint") for cost in ("energy", "pressure") for m in (16, 32)]
PEERS = [("energy", 32, 20, gradient) for gradient in ("adjoint", "direct", "fd")] + [
    ("pressure", 16, 12, gradient) for gradient in ("adjoint", "direct", "fd")]
LOOPS = OPTIMA + [loop for loop in PEERS if loop not in OPTIMA]


def run_loops(folder):
    """Runs every loop of LOOPS; returns their RESULT dicts and the profiles (per loop of
    the first four: rows of x, pressure0, pressure, profile0, profile)."""
    results, profiles = {}, {}
    for cost, m, k, gradient in LOOPS:
        name = f"{cost}-m{m}-k{k}-{gradient}"
        profile = os.path.join(folder, name + ".csv")
        r = run(SCRIPT, "-cost", cost, "-m", m, "-k", k, "-gradient", gradient,
                "-history", os.path.join(folder, name + ".history"), "-profile", profile)["RESULT"][0]
        results[(cost, m, k, gradient)] = r
        with open(profile) as file:
            profiles[(cost, m, k, gradient)] = [{key: float(v) for key, v in row.items()} for row in csv.DictReader(file)]
    return results, profiles


def write_raw(results, profiles):
    with open(os.path.join(OUT, "shape-optimization-uniform-pressure.csv"), "w", newline="") as file:
        writer = csv.writer(file)
        writer.writerow(LOOP_KEYS)
        for r in results.values():
            writer.writerow([r[key] for key in LOOP_KEYS])
    with open(os.path.join(OUT, "shape-optimization-uniform-pressure-profiles.csv"), "w", newline="") as file:
        writer = csv.writer(file)
        writer.writerow(["cost", "m", "k", "gradient", "x", "pressure0", "pressure", "profile0", "profile"])
        for (cost, m, k, gradient), rows in profiles.items():
            for row in rows:
                writer.writerow([cost, m, k, gradient] + [row[key] for key in
                                                          ("x", "pressure0", "pressure", "profile0", "profile")])


def picture(profiles, uniform, name):
    """Pressure before and after against the uniform pressure, and the profiles, from the
    raw profiles (the loops with adjoint gradients and 12 variables)."""
    fig, (top, bottom) = plt.subplots(2, 1, figsize=(7, 6.4), sharex=True)
    styles = {16: "-", 32: "--"}
    for cost, m, k, gradient in OPTIMA:
        rows = profiles[(cost, m, k, gradient)]
        x = [r["x"] for r in rows]
        colour = "C1" if cost == "energy" else "C2"
        if cost == "energy":
            top.plot(x, [r["pressure0"] for r in rows], "C0" + styles[m], marker=".", label=f"initial (crowned), m = {m}")
            bottom.plot(x, [1e3 * r["profile0"] for r in rows], "C0" + styles[m], label=f"initial, m = {m}")
        marker = "." if cost == "energy" else "x"
        top.plot(x, [r["pressure"] for r in rows], colour + styles[m], marker=marker, ms=5,
                 label=f"optimum of the {cost}, m = {m}")
        bottom.plot(x, [1e3 * r["profile"] for r in rows], colour + styles[m], label=f"optimum of the {cost}, m = {m}")
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


def section(folder):
    """Runs the loops and the gradient checks; writes raw data and the picture; returns the
    Markdown lines of the section."""
    results, profiles = run_loops(folder)
    write_raw(results, profiles)
    uniform = f(results[OPTIMA[0]], "pressure_uniform")
    picture(profiles, uniform, "shape-optimization-uniform-pressure.png")
    checks = [run(SCRIPT, "-gradcheck", 1e-5, "-cost", cost, "-m", m, prefixes=("GRADCHECK",))["GRADCHECK"][0]
              for cost in ("energy", "pressure") for m in (16, 32)]
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
        "multiplier, over the free variables, relative to the largest at the start.",
        "",
        "| cost | mesh (cells across the zone) | k | design steps | cv before | cv after |"
        " max pressure before → after [MPa] | material / material0 | bound's multiplier [MPa] |"
        " stationarity | factorizations | total [s] | status |",
        "|---|---|---|---|---|---|---|---|---|---|---|---|---|",
    ]
    for r in (results[loop] for loop in OPTIMA):
        multiplier = (f"{f(r, 'area_multiplier'):.3f}" if r["cost_name"] == "energy" and r["area_active"] == "1"
                      else "– (the cost does not see the material)" if r["cost_name"] == "pressure" else "– (not active)")
        lines.append(
            f"| {r['cost_name']} | {r['m']} | {r['k']} | {r['steps']} | {f(r, 'pressure_cv0'):.3f} | "
            f"{f(r, 'pressure_cv'):.1e} | {f(r, 'pressure_max0'):.1f} → {f(r, 'pressure_max'):.2f} | "
            f"{f(r, 'volume') / f(r, 'volume0'):.4f} | {multiplier} | {f(r, 'stationarity'):.1e} | "
            f"{r['factorizations']} | {f(r, 'time_total'):.2f} | {r['status']} |")
    lines += [
        "",
        "![uniform pressure](shape-optimization-uniform-pressure.png)",
        "",
        "## The peer, side by side: what the semi-analytic gradients buy",
        "",
        "The same IPOPT loops with (a) the plugin's adjoint gradient (one adjoint solve per",
        "design step, then one product per variable), (b) direct sensitivities (the k",
        "directions in one `fetiSensitivity` call), (c) central finite differences of full",
        "re-solves (what a script without the plugin's sensitivities does: 2k analyses per",
        "gradient, step 1e-6 mm): the energy with k = 20 variables on the m = 32 mesh, the",
        "pressure's P-mean with k = 12 on m = 16. Same optimum: compare the final cost and cv.",
        "",
        "| cost | k | gradient | design steps | analyses (incl. gradients) | factorizations | sensitivity solves |"
        " total [s] | x (a)'s time | final cost | cv after | status |",
        "|---|---|---|---|---|---|---|---|---|---|---|---|",
    ]
    peers = [results[loop] for loop in PEERS]
    for r in peers:
        base = next(p for p in peers if p["cost_name"] == r["cost_name"] and p["gradient"] == "adjoint")
        k = int(r["k"])
        steps = int(r["steps"])
        analyses = steps * (1 + 2 * k) if r["gradient"] == "fd" else steps
        lines.append(
            f"| {r['cost_name']} | {k} | {r['gradient']} | {steps} | {analyses} | {r['factorizations']} | "
            f"{r['sensitivity_solves']} | {f(r, 'time_total'):.2f} | {f(r, 'time_total') / f(base, 'time_total'):.1f} | "
            f"{f(r, 'cost'):.8g} | {f(r, 'pressure_cv'):.1e} | {r['status']} |")
    lines += [
        "",
        "### Gradient checks of the gap design",
        "",
        "At the initial design (`-gradcheck`): the adjoint against the direct gradient, the",
        "direct gradient against central differences of re-solves, and lambda' (direct mode,",
        "`dLambda`) against central differences of the contact forces; errors relative to the",
        "largest entry (`ctest -R uniform_pressure_gradients` asserts them below 1e-5).",
        "",
        "| cost | m | k | active / contact rows | adjoint vs direct | direct vs finite differences |"
        " lambda' vs finite differences | status |",
        "|---|---|---|---|---|---|---|---|",
    ]
    for c in checks:
        lines.append(f"| {c['cost_name']} | {c['m']} | {c['k']} | {c['active']} / {c['rows']} | "
                     f"{f(c, 'adjoint_vs_direct'):.1e} | {f(c, 'direct_vs_fd'):.1e} | {f(c, 'dlambda_vs_fd'):.1e} | "
                     f"{c['status']} |")
    lines.append("")
    return lines
