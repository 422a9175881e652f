#!/usr/bin/env python3
"""What accuracy costs in time, on every scene: tol swept from 1e-2 to 1e-10 on one set-up per
scene (edp/tolerance-sweep.idp), each solve compared with the scene's solve at tol = 1e-12,
itself confirmed by an independent method (an active set solution of the unsplit problem,
Hertz's formulas, the force balance of the contact interfaces); then the same sweep of a
design gradient (the gap design's -sweep 1, edp/scenes/gap-design.idp: its reference checked
against central differences of the cost) and design loops run whole at several tols (their
final designs solved again at tol = 1e-12, against the loop at 1e-12 and the known optimum),
and transient runs whole at several tols (their answer against the run at 1e-10 and the exact
one). Writes the raw data of one run (docs/results/accuracy-and-time-references.csv,
accuracy-and-time-sweeps.csv, accuracy-and-time-gradients.csv,
accuracy-and-time-design-loops.csv, accuracy-and-time-transient.csv) and renders
docs/results/accuracy-and-time.md and its plots from it (--render: again from the CSVs;
--only transient|design-loops: that part alone, recorded as such on the page)."""
import argparse
import math
import os
import subprocess
import tempfile
import time

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from ffeti_bench import (OUT, ROOT, begin_run, end_run, f, forget_run, machine_line, markdown_table,  # noqa: E402
                         own_run_words, read_csv, run, save_page, write_csv)

# (label, script, arguments, kind of independent check)
SCENES = [
    ("model problem h = 1/128", "model-problem.edp", ["-n", 128], "active set"),
    ("model problem h = 1/256", "model-problem.edp", ["-n", 256], "active set"),
    ("model problem h = 1/512", "model-problem.edp", ["-n", 512], "active set"),
    ("Hertz h = 1 mm", "hertz.edp", ["-h", 1, "-meshes", os.path.join(ROOT, "meshes")], "Hertz"),
    ("Hertz h = 0.5 mm", "hertz.edp", ["-h", 0.5, "-meshes", os.path.join(ROOT, "meshes")], "Hertz"),
    ("multibody (3 bodies)", "multibody.edp", [], "balance"),
    ("large contact zone n = 80", "large-contact.edp", ["-n", 80], "active set"),
    ("3D Hertz sphere on a plane, node to face", "hertz-sphere.edp", ["-meshes", os.path.join(ROOT, "meshes")], "Hertz"),
    ("3D Hertz sphere on a block, mortar", "hertz-sphere.edp", ["-block", 1, "-meshes", os.path.join(ROOT, "meshes")],
     "Hertz"),
    ("Cattaneo–Mindlin, Coulomb friction (2D, step 2)", "cattaneo-mindlin.edp", ["-meshes", os.path.join(ROOT, "meshes")],
     "Mindlin"),
    ("Cattaneo–Mindlin, Coulomb friction (3D, node to face, h = 0.08 mm, step 2)", "cattaneo-mindlin-3d.edp",
     ["-h", 0.08, "-meshes", os.path.join(ROOT, "meshes")], "Mindlin"),
    # The 3D elasticity cubes of three-dimensions.md near a million unknowns (n = 48: 944,784);
    # no direct peer reaches this size: the load balance and the primal KKT residual confirm it.
    ("3D elasticity, two cubes n = 48", "cubes-elasticity-3d.edp", ["-n", 48], "load balance"),
    # A real mesh (real-meshes.md's scene: gmsh bodies, METIS parts, node to face), against the
    # undivided bodies solved by the primal-dual active set method (-peer 1).
    ("3D real mesh: crowned punch, node to face, METIS parts", "crowned-punch-3d.edp",
     ["-h", 0.7, "-peer", 1, "-DwithMUMPS=1", "-meshes", os.path.join(ROOT, "meshes")], "direct peer"),
]
# (label, script, arguments) of the gradient sweeps: the gap design of the known optimum at its
# start, the energy (its gradient from the contact forces) and the P-mean of the pressure (from
# their derivatives lambda'), in 2D and 3D.
GRADIENTS = [
    ("2D punch, energy", "uniform-pressure.edp", ["-cost", "energy"]),
    ("2D punch, pressure P-mean", "uniform-pressure.edp", ["-cost", "pressure"]),
    ("3D square punch, energy", "uniform-pressure-3d.edp", ["-cost", "energy"]),
    ("3D square punch, pressure P-mean", "uniform-pressure-3d.edp", ["-cost", "pressure"]),
]
# The design loops of the known optimum (edp/uniform-pressure.edp, uniform-pressure-3d.edp: IPOPT
# with adjoint gradients) run whole at each tol of DESIGN_TOLS and at DESIGN_REFERENCE; each
# stopped after DESIGN_CAP designs (-stopafter: the reference loops take tens to hundreds; a
# count, not a time, so that a loaded machine stops the same loops). (label, script, arguments)
DESIGN_LOOPS = [("2D punch, energy", "uniform-pressure.edp", ["-cost", "energy"]),
                ("2D punch, pressure P-mean", "uniform-pressure.edp", ["-cost", "pressure"]),
                ("3D square punch, energy", "uniform-pressure-3d.edp", ["-cost", "energy"]),
                ("3D square punch, pressure P-mean", "uniform-pressure-3d.edp", ["-cost", "pressure"])]
DESIGN_TOLS = [1e-3, 1e-4, 1e-5, 1e-7, 1e-9]
DESIGN_REFERENCE = 1e-12
DESIGN_CAP = 2000
UNIFORM_PRESSURE = 100.0  # q of edp/uniform-pressure.edp and uniform-pressure-3d.edp [MPa]: the known optimum's pressure
# Transient contact (edp/dynamics.idp): each scene run whole at each tol of TRANSIENT_TOLS and
# at TRANSIENT_REFERENCE (every time step's solve at that tol; 1e-12 stagnates at round-off
# in every step of the stiff rubber and cost 30,000 multiplications in 3D): (label, script,
# arguments, the RESULT key of its answer, the key of the exact value).
TRANSIENT = [("block sliding to rest, 2D Coulomb", "sliding-block.edp", ["-dim", 2], "stop_distance", "stop_distance_exact"),
             ("block sliding to rest, 3D Coulomb", "sliding-block.edp", ["-dim", 3], "stop_distance", "stop_distance_exact")]
TRANSIENT_TOLS = [1e-2, 1e-3, 1e-4, 1e-5, 1e-6, 1e-7, 1e-8]
TRANSIENT_REFERENCE = 1e-10
# The records of a part run on its own (--only transient, --only design-loops).
TRANSIENT_RUN = "transient-run"
DESIGN_RUN = "design-loops-run"
# The accuracies the first screen's table answers for: the largest tol whose solution error
# ||u - u_ref||_inf / ||u_ref||_inf is at most each.
TARGETS = [1e-2, 1e-4, 1e-6, 1e-8]
PREFIXES = ("RESULT", "SWEEP", "DIRECT", "RANK")


PAGE = "accuracy-and-time"


def tol_text(value):
    """1e-2, not 0.01 or 1e-02."""
    mantissa, exponent = f"{value:.0e}".split("e")
    return f"{mantissa}e{int(exponent)}"


def sweep(script, args):
    lines = run(script, *args, "-sweep", 1, prefixes=PREFIXES)
    rows = lines["SWEEP"]
    return lines, rows[0], rows[1:]


def independent(script, args, kind, result):
    """The independent check's own figures, beside the tol = 1e-12 reference: the active set
    method's energy (and contact couples) on the unsplit meshes."""
    if kind == "active set" and script == "model-problem.edp":
        direct = run("model-problem-direct.edp", args[0], args[1], prefixes=PREFIXES)["DIRECT"][0]
        return {"independent_energy": direct["energy"]}
    if kind == "active set":
        return {"independent_energy": result["energy_reference"], "independent_active": result["active_reference"]}
    if kind == "load balance":
        return {"unknowns": result["unknowns"], "couples": result["couples"]}
    if kind == "direct peer":
        return {"unknowns": result["unknowns"], "independent_energy": result["energy_peer"],
                "independent_active": result["active_peer"]}
    return {}


def relative_gap(reference):
    """|E - E_independent| / |E_independent| as words: both are printed to 10 digits, so a
    zero says they agree to every printed digit."""
    gap = abs(f(reference, "energy") - f(reference, "independent_energy")) / abs(f(reference, "independent_energy"))
    return f"relative difference {gap:.1e}" if gap > 0 else "equal to every printed digit"


def confirmation(reference):
    """How the tol = 1e-12 reference is confirmed independently, as a sentence (from its CSV row)."""
    kind = reference["kind"]
    if kind == "active set":
        sentence = (f"energy {f(reference, 'energy'):.10g} against {f(reference, 'independent_energy'):.10g} from the "
                    f"primal-dual active set method on the unsplit meshes ({relative_gap(reference)})")
        if reference.get("independent_active"):
            sentence += f"; contact {reference['independent_active']} couples there"
        return sentence
    if kind == "direct peer":
        return (f"energy {f(reference, 'energy'):.10g} against {f(reference, 'independent_energy'):.10g} from the "
                f"undivided bodies by the primal-dual active set method on the same contact rows "
                f"({relative_gap(reference)}; {reference['independent_active']} active rows there; "
                f"{int(f(reference, 'unknowns')):,} unknowns)")
    if kind == "Hertz":
        return (f"contact half-width and peak pressure within {f(reference, 'a_relerr'):.1%} and "
                f"{f(reference, 'p0_relerr'):.1%} of Hertz's (discretization error of this mesh)")
    if kind == "Mindlin":
        return (f"stick zone c/a within {f(reference, 'stick_ratio_error'):.2%} of Mindlin's (discretization error "
                f"of this mesh), friction forces summing to Q to {f(reference, 'balance_error'):.0e}")
    if kind == "load balance":
        return (f"the contact forces carry the applied load to {f(reference, 'balance_error'):.1e} and the KKT "
                f"residual recomputed in primal form is {f(reference, 'kkt'):.1e} ({int(f(reference, 'unknowns')):,} "
                f"unknowns, {reference['couples']} contact couples); no independent solution exists at this size "
                "(the direct peers of [three dimensions](three-dimensions.md) stop far below it), so these two are "
                "the check")
    return f"each contact interface carries the load above it to {f(reference, 'balance_error'):.1e}"


SWEEP = [("tol", ("tol", ".0e")), ("Hessian mult.", "hessian"), ("time [s]", ("seconds", ".3f")),
         ("energy error", ("energy_error", ".1e")), ("u error", ("u_error", ".1e")),
         ("contact mismatch", "contact_mismatch"), ("KKT", ("kkt", ".1e"))]
HERTZ = [("a error (Hertz)", ("a_relerr", ".2%")), ("p0 error (Hertz)", ("p0_relerr", ".2%"))]
MINDLIN = [("c/a error (Mindlin)", ("stick_ratio_error", ".2%")), ("Σλ_t vs Q", ("balance_error", ".0e")),
           ("Tresca solves", "fixed_point_iterations")]
BALANCE = [("Σλ vs load", ("balance_error", ".1e"))]
STATUS = [("status", lambda r: "converged" if r["status"] == "0" else f"status {r['status']}")]


def transient_runs():
    """Each transient scene run whole at the reference tol and at each of TRANSIENT_TOLS: one
    row per scene and tol (status 0: every step converged)."""
    rows = []
    for label, script, args, key, exact in TRANSIENT:
        for reference, tol in [(1, TRANSIENT_REFERENCE)] + [(0, t) for t in TRANSIENT_TOLS]:
            started = time.time()
            result = run(script, *args, "-tol", tol)["RESULT"][0]
            rows.append(dict(scene=label, tol=tol, reference=reference, value=result[key], exact=result[exact],
                             hessian_total=result["hessian_total"], seconds=repr(time.time() - started),
                             status="0" if result["status"] == "converged" else result["status"]))
    return rows


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--render", action="store_true", help="re-render the page from its CSVs, no run")
    parser.add_argument("--only", choices=["transient", "design-loops"],
                        help="run this part alone, the rest of the page as it was")
    options = parser.parse_args()
    if options.only == "transient":
        begun = begin_run()
        write_csv(PAGE, "transient", transient_runs())
        end_run(PAGE, begun, TRANSIENT_RUN)
    elif options.only == "design-loops":
        begun = begin_run()
        write_csv(PAGE, "design-loops", design_loops())
        end_run(PAGE, begun, DESIGN_RUN)
    elif not options.render:
        begun = begin_run()
        references, sweeps = [], []
        for label, script, args, kind in SCENES:
            lines, reference, rows = sweep(script, args)
            references.append(dict(scene=label, kind=kind, **reference,
                                   **independent(script, args, kind, lines["RESULT"][0])))
            sweeps += [dict(scene=label, **r) for r in rows]
        write_csv(PAGE, "references", references)
        write_csv(PAGE, "sweeps", sweeps)
        gradients = []
        for label, script, args in GRADIENTS:
            _, reference, rows = sweep(script, args)
            gradients += [dict(scene=label, **r) for r in [reference] + rows]
        write_csv(PAGE, "gradients", gradients)
        write_csv(PAGE, "design-loops", design_loops())
        write_csv(PAGE, "transient", transient_runs())
        forget_run(PAGE, TRANSIENT_RUN)
        forget_run(PAGE, DESIGN_RUN)
        end_run(PAGE, begun)
    render()


def transient_error(reference):
    """|d - d_ref| / |d_ref| against the run at the reference tol."""
    return lambda r: abs(f(r, "value") - f(reference, "value")) / abs(f(reference, "value"))


def transient_reading(transients):
    """What a whole transient run's answer asks of tol, as a sentence from its rows."""
    loosest = [(label, max(rows, key=lambda r: f(r, "tol")), transient_error(reference))
               for label, reference, rows in transients]
    worst = ", ".join(f"{error(r):.0%} ({label.split(', ')[-1]})" for label, r, error in loosest)
    at_1e4 = max(transient_error(reference)(r) for _, reference, rows in transients for r in rows if f(r, "tol") == 1e-4)
    return (f"A transient run accumulates its steps' errors: at tol = {tol_text(f(loosest[0][1], 'tol'))} the block's "
            f"stop distance was off by {worst}: a loose tol is no cheap approximation here. At tol = 1e-4 it was "
            f"within {at_1e4:.1e}; for a tighter accuracy the table above gives the tol, beside the time step's "
            "own error (the last column of each transient table).")


def transient_section(transients):
    lines = ["## Transient contact: a whole run at each tol", "",
             f"`sliding-block.edp -dim 2|3 -tol TOL`: a rubber block started at v0 on a rigid floor and stopped by "
             f"Coulomb friction (μ = 0.3, stabilized Newmark, [dynamics](dynamics.md)); every time step's solve at "
             f"tol; the stop distance against the run at tol = {tol_text(TRANSIENT_REFERENCE)} (the reference) and "
             "against the exact v0²/(2μg) (the time discretization's error beside the solves'). Hessian "
             f"multiplications over all steps. From {own_run_words(PAGE, TRANSIENT_RUN, 'the page’s run')}. "
             f"Raw data: [{PAGE}-transient.csv]({PAGE}-transient.csv).", ""]
    for label, reference, rows in transients:
        error = transient_error(reference)
        shown = [dict(r, error=("-" if r["reference"] == "1" else f"{error(r):.1e}"),
                      exact_error=f"{abs(f(r, 'value') - f(r, 'exact')) / f(r, 'exact'):.1e}")
                 for r in [reference] + rows]
        lines += [f"### {label}", "", *markdown_table(shown, TRANSIENT_COLUMNS), ""]
    return lines


def design_loops():
    """Each design loop run whole at each tol (the reference's first), its final design solved
    again at tol = 1e-12 (-finaltol): one row per loop and tol; a loop stopped at DESIGN_CAP
    designs is a row with status 'design cap'."""
    rows = []
    with tempfile.TemporaryDirectory() as folder:
        for label, script, args in DESIGN_LOOPS:
            for tol in [DESIGN_REFERENCE] + DESIGN_TOLS:
                common = dict(loop=label, script=script, tol=repr(tol), reference=int(tol == DESIGN_REFERENCE))
                history = os.path.join(folder, f"loop-{len(rows)}.history")
                try:
                    result = run(script, *args, "-tol", tol, "-finaltol", DESIGN_REFERENCE,
                                 "-history", history, "-stopafter", DESIGN_CAP)["RESULT"][0]
                    rows.append(dict(common, **result))
                except subprocess.CalledProcessError:
                    # -stopafter kills the process (its last lines unflushed); the history it
                    # rewrites after each design says how many it ran (its first number).
                    designs = 0
                    if os.path.exists(history):
                        with open(history) as file:
                            designs = int(file.readline().split()[0])
                    if designs < DESIGN_CAP:
                        raise
                    rows.append(dict(common, status="design cap", steps=designs))
    return rows


PICK_COLUMNS = [("scene", "scene")] + [(f"error ≤ {tol_text(t)}", f"target_{i}") for i, t in enumerate(TARGETS)]


def picks(rows):
    """For each target accuracy, 'tol (multiplications)' of the largest tol reaching it, or '-'."""
    chosen = {}
    for i, target in enumerate(TARGETS):
        good = [r for r in rows if f(r, "u_error") <= target and r["status"] == "0"]
        best = max(good, key=lambda r: f(r, "tol")) if good else None
        chosen[f"target_{i}"] = f"{tol_text(f(best, 'tol'))} ({best['hessian']})" if best else "-"
    return chosen


def safe_picks(rows, error, cost):
    """For each target accuracy, 'tol (cost)' of the largest tol of rows from which on every
    tighter tol also reaches it with status 0 (a loop may reach a target at one tol and miss it
    at the next tighter one), or '-'. error, cost: functions of a row."""
    chosen = {}
    tightest_first = sorted(rows, key=lambda r: f(r, "tol"))
    for i, target in enumerate(TARGETS):
        best = None
        for r in tightest_first:
            if r["status"] != "0" or error(r) > target:
                break
            best = r
        chosen[f"target_{i}"] = f"{tol_text(f(best, 'tol'))} ({cost(best)})" if best else "-"
    return chosen


def decades_needed(rows_per_case, error):
    """Per (case, target) pair some tol reached: log10(target / the largest tol reaching it)."""
    decades = []
    for rows in rows_per_case:
        for target in TARGETS:
            good = [f(r, "tol") for r in rows if error(r) <= target and r["status"] == "0"]
            if good:
                decades.append(round(math.log10(target / max(good))))
    return decades


def settled_from(rows, key):
    """The largest tol from which on every tighter tol of the sweep gives the reference's value of
    `key` (an error against an analytic value) to 1% of it, or None."""
    best = None
    for r in sorted(rows, key=lambda r: f(r, "tol")):
        if abs(f(r, key) - f(r, "reference_value")) > 0.01 * abs(f(r, "reference_value")):
            break
        best = r
    return best


def gradient_error(r):
    return f(r, "gradient_error")


def gradient_cost(r):
    """Multiplications of one gradient: the state solve's and the adjoint's (or the direct
    fallback's)."""
    return int(f(r, "hessian") + f(r, "hessian_adjoint"))


def loop_error(reference):
    """The final design's cost (solved again at 1e-12) against the reference loop's, relative."""
    def error(r):
        if r["status"] != "0" or r.get("final_status", "") != "0":
            return math.inf
        return abs(f(r, "final_cost") - f(reference, "final_cost")) / abs(f(reference, "final_cost"))
    return error


def pick_reading(data, gradients, loops):
    """What this run shows about the tol each accuracy needs: the solution's, the gradient's and the
    design loops' (computed from the rows)."""
    decades = decades_needed([rows for _, rows in data], lambda r: f(r, "u_error"))
    same = sum(1 for d in decades if d == 0)
    one = sum(1 for d in decades if d == 1)
    text = (f"Reading: of {len(decades)} (scene, target) pairs a sweep reached, {same} need tol = the target "
            f"itself and {one} one decade tighter{'' if same + one == len(decades) else ', the rest more'}: "
            "pick tol equal to the relative accuracy of u you want, a decade below it to be safe.")
    friction = []
    for reference, rows in data:
        if reference["kind"] == "Mindlin":
            rows = [dict(r, reference_value=reference["stick_ratio_error"]) for r in rows]
            settled = settled_from(rows, "stick_ratio_error")
            if settled:
                friction.append(f"{tol_text(f(settled, 'tol'))} ({reference['scene'].split('(')[1].split(',')[0]})")
    if friction:
        text += (" With friction a derived quantity needs its own tol: the stick zone's c/a settles at its "
                 f"reference value (its mesh's error against Mindlin) from tol = {' and '.join(friction)}.")
    gradient_decades = decades_needed([rows for _, _, rows in gradients], gradient_error)
    if gradient_decades:
        most = max(gradient_decades)
        text += (f"\n\nA design gradient needs tighter solves: of {len(gradient_decades)} (scene, target) pairs its "
                 f"sweep reached, {sum(1 for d in gradient_decades if d == 0)} need tol = the target, "
                 f"{sum(1 for d in gradient_decades if d == 1)} one decade tighter and "
                 f"{sum(1 for d in gradient_decades if d >= 2)} two or more (up to {most}): pick tol "
                 f"{most} decade{'s' if most != 1 else ''} below the gradient's accuracy you want.")
    fell = [(label, r) for label, _, rows in gradients for r in rows if r["fallback"] == "1"]
    if fell:
        adjoint = [f(r, "hessian_adjoint") for _, _, rows in gradients for r in rows if r["fallback"] == "0"]
        cost = [f(r, "hessian_adjoint") for _, r in fell]
        text += (" Where the state's tol is loose its contact rows are classed with a loose threshold (activeTol = "
                 "10 tol, at most 1e-2): some then count as weakly active, the adjoint falls back to the direct "
                 f"mode, and a gradient costs {min(cost):.0f} to {max(cost):.0f} multiplications instead of an "
                 f"adjoint's {min(adjoint):.0f} to {max(adjoint):.0f} ("
                 + "; ".join(f"{label} at tol = {', '.join(tol_text(f(r, 'tol')) for lab, r in fell if lab == label)}"
                             for label in dict.fromkeys(lab for lab, _ in fell)) + ").")
    for label, reference, rows in loops:
        error = loop_error(reference)
        good = [r for r in rows if error(r) <= 1e-6]
        cheapest = min(good, key=lambda r: f(r, "hessian_total")) if good else None
        failed = [r for r in rows if r["status"] != "0" or r.get("ipopt_status") not in ("0", "1")]
        text += (f" Design loop, {label}: at tol = {tol_text(f(reference, 'tol'))} {reference['steps']} designs and "
                 f"{int(f(reference, 'hessian_total')):,} multiplications")
        if cheapest:
            text += (f"; the cheapest loop whose final design's cost is within 1e-6 of it ran at tol = "
                     f"{tol_text(f(cheapest, 'tol'))}: {cheapest['steps']} designs, "
                     f"{int(f(cheapest, 'hessian_total')):,} multiplications")
        if failed:
            text += "; " + ", ".join(f"tol = {tol_text(f(r, 'tol'))} {loop_outcome(r)}"
                                     + (f", its final design's cost {error(r):.1e} off the reference's, the pressure's "
                                        f"cv {f(r, 'final_pressure_cv'):.1e} (the reference's "
                                        f"{f(reference, 'final_pressure_cv'):.1e})"
                                        if error(r) < math.inf else "") for r in failed)
        text += "."
    return text


def loop_outcome(r):
    """How a loop that did not end well ended, in words."""
    if r["status"] == "design cap":
        return f"stopped at the cap of {r['steps']} designs"
    if r["status"] != "0":
        return f"ended with status {r['status']} (IPOPT {r.get('ipopt_status', '?')})"
    return f"ended with IPOPT status {r['ipopt_status']} (stationarity {f(r, 'stationarity'):.0e})"


GRADIENT_PICK_COLUMNS = [("scene", "scene"), ("quantity", "quantity")] + PICK_COLUMNS[1:]
TRANSIENT_COLUMNS = [("tol", ("tol", ".0e")), ("Hessian mult. (all steps)", "hessian_total"),
                     ("time [s]", ("seconds", ".1f")), ("stop distance [m]", "value"), ("error", "error"),
                     ("error against the exact stop", "exact_error"),
                     ("status", lambda r: "converged" if r["status"] == "0" else r["status"])]
GRADIENT_SWEEP = [("tol", ("tol", ".0e")), ("state mult.", "hessian"), ("adjoint mult.", "hessian_adjoint"),
                  ("fell back to direct", lambda r: "yes" if r["fallback"] == "1" else "no"),
                  ("direct mult. (all directions)", "hessian_direct"),
                  ("state + adjoint [s]", lambda r: f"{f(r, 'seconds') + f(r, 'seconds_adjoint'):.3f}"),
                  ("cost error", ("cost_error", ".1e")), ("gradient error (adjoint)", ("gradient_error", ".1e")),
                  ("gradient error (direct)", ("gradient_error_direct", ".1e")), ("KKT", ("kkt", ".1e"))]
LOOP_COLUMNS = [("tol", ("tol", ".0e")), ("designs", "steps"), ("Hessian mult.", "hessian_total"),
                ("loop [s]", ("time_total", ".2f")), ("final cost (at 1e-12)", "final_cost"),
                ("cost error", "cost_error"), ("max pressure [MPa]", ("final_pressure_max", ".3f")),
                ("cv", ("final_pressure_cv", ".1e")), ("bound's multiplier [MPa]", "multiplier"),
                ("stationarity", ("stationarity", ".0e")), ("IPOPT", "ipopt_status"), ("status", "status")]


def design_words(r):
    """'m = 16, 12 variables' (and the contact) of a gap design's SWEEP row."""
    variables = r.get("variables") or r["k"]
    words = f"m = {r['m']}, {variables} variables"
    return words + (f", {r['contact']} contact" if r.get("contact") else "")


def gradient_section(label, reference, rows):
    lines = [f"## Gradient: {label}", "",
             f"`{'uniform-pressure-3d.edp' if reference.get('contact') else 'uniform-pressure.edp'} "
             f"-cost {reference['cost_name']} -sweep 1` ({design_words(reference)}), at the start design. "
             f"Reference (tol = {tol_text(f(reference, 'tol'))}): state {reference['hessian']} + adjoint "
             f"{reference['hessian_adjoint']} Hessian multiplications (direct: {reference['hessian_direct']} for all "
             f"directions), KKT {f(reference, 'kkt'):.1e}, |g|_inf = {f(reference, 'gradient_max'):.4g}"
             + (f" (status {reference['status']})" if reference["status"] != "0" else "")
             + "; confirmed: central differences of the cost (re-solves at tol = 1e-12) agree with its adjoint "
             f"gradient to {f(reference, 'fd0_vs_adjoint'):.1e} at step {f(reference, 'fd0_step'):.0e} mm and "
             f"{f(reference, 'fd1_vs_adjoint'):.1e} at {f(reference, 'fd1_step'):.0e} mm (the differences' own "
             f"error, falling as the step squared), with the direct one to {f(reference, 'fd1_vs_direct'):.1e}"
             + ("" if reference["fd0_status"] == reference["fd1_status"] == "0" else " (a re-solve did not converge)")
             + ".", ""]
    columns = GRADIENT_SWEEP + (STATUS if any(r["status"] != "0" for r in rows) else [])
    return lines + markdown_table(rows, columns) + [""]


def loops_section(loops):
    final = tol_text(DESIGN_REFERENCE)
    scenes = []
    for script in dict.fromkeys(reference["script"] for _, reference, _ in loops):
        first = next(r for _, r, _ in loops if r["script"] == script)
        scenes.append(f"`{script} -cost energy|pressure -tol TOL -finaltol {final}` ({design_words(first)})")
    lines = ["## Design loops: the known optimum (2D and 3D punch)", "",
             f"{' and '.join(scenes)}, IPOPT with adjoint gradients, one set-up for the loop: the whole loop at "
             f"each tol, its gradients' solves at the same tol, each loop stopped after {DESIGN_CAP} designs. Its "
             f"final design solved again at tol = {final}: final cost and its error against the loop at tol = {final} "
             "(the reference), the largest pressure beside the P-mean (in 3D over every node, the punch's edges "
             "and corner included, where the pressure stays singular: [shape optimization]"
             "(shape-optimization.md#in-three-dimensions-a-square-punch)), the pressure's coefficient of variation "
             "cv. The known optimum ([shape optimization](shape-optimization.md)): a uniform pressure "
             f"q = {UNIFORM_PRESSURE:g} MPa, the energy's material bound active with its multiplier equal to q. "
             "Designs: the analyses IPOPT asked for; Hessian multiplications: every state solve and gradient of the "
             "loop (the norm estimate, once, not counted); status 0: every solve converged and the final design is "
             f"stationary. From {own_run_words(PAGE, DESIGN_RUN, 'the page’s run')}. "
             f"Raw data: [{PAGE}-design-loops.csv]({PAGE}-design-loops.csv).", ""]
    for label, reference, rows in loops:
        error = loop_error(reference)
        shown = [dict(r, cost_error=("-" if r["reference"] == "1" else
                                     f"{error(r):.1e}" if error(r) < math.inf else "-"),
                      multiplier=(f"{f(r, 'area_multiplier' if r.get('area_multiplier') else 'multiplier'):.4f}"
                                  if r.get("cost_name") == "energy" and r.get("status") != "design cap" else "-"))
                 for r in [reference] + rows]
        lines += [f"### {label}", "", *markdown_table(shown, LOOP_COLUMNS), ""]
    return lines


def render():
    references, sweeps, run_row = read_csv(PAGE, "references"), read_csv(PAGE, "sweeps"), read_csv(PAGE, "run")[0]
    gradient_rows, loop_rows = read_csv(PAGE, "gradients"), read_csv(PAGE, "design-loops")
    transient_rows = read_csv(PAGE, "transient")
    transients = [(label, [r for r in transient_rows if r["scene"] == label and r["reference"] == "1"][0],
                   [r for r in transient_rows if r["scene"] == label and r["reference"] == "0"])
                  for label in dict.fromkeys(r["scene"] for r in transient_rows)]
    data = [(r, [s for s in sweeps if s["scene"] == r["scene"]]) for r in references]
    gradients = [(label, [r for r in gradient_rows if r["scene"] == label and r["reference"] == "1"][0],
                  [r for r in gradient_rows if r["scene"] == label and r["reference"] == "0"])
                 for label in dict.fromkeys(r["scene"] for r in gradient_rows)]
    loops = [(label, [r for r in loop_rows if r["loop"] == label and r["reference"] == "1"][0],
              [r for r in loop_rows if r["loop"] == label and r["reference"] == "0"])
             for label in dict.fromkeys(r["loop"] for r in loop_rows)]
    tols = [f(s, "tol") for s in sweeps]
    reference_tols = {tol_text(f(r, "tol")) for r in references}
    tol_range = f"{tol_text(max(tols))} .. {tol_text(min(tols))}"
    plot(data, tol_range)
    plot_gradients(gradients, loops)
    second = ([dict(scene=f"gradient: {label}", quantity="gradient", **safe_picks(rows, gradient_error, gradient_cost))
               for label, _, rows in gradients]
              + [dict(scene=f"design loop: {label}", quantity="final design's cost",
                      **safe_picks(rows, loop_error(reference), lambda r: f"{int(f(r, 'hessian_total')):,}"))
                 for label, reference, rows in loops]
              + [dict(scene=f"transient: {label}", quantity="stop distance",
                      **safe_picks(rows, transient_error(reference), lambda r: f"{int(f(r, 'hessian_total')):,}"))
                 for label, reference, rows in transients])
    lines = [
        "# What accuracy costs in time, on every scene",
        "",
        "Generated by `scripts/benchmark.sh accuracy` (do not edit by hand) on:",
        machine_line(run_row),
        "",
        "Each scene is set up once (factorizations reused) and solved with default options at",
        f"tol = {' / '.join(sorted(reference_tols))}, the reference, then at tol = {tol_range} (`-sweep 1` of its script,",
        "`edp/tolerance-sweep.idp`). Per solve: Hessian multiplications (the machine-independent",
        "cost; the norm estimate, computed once per set-up, is not counted), seconds of dual solve",
        "and recovery, the energy error |E - E_ref| / |E_ref|, the solution error",
        "max_s ||u_s - u_ref,s||_inf / ||u_ref||_inf, the contact couples whose state (force or none)",
        "differs from the reference's, and the largest relative KKT residual of the returned",
        "solution (equilibrium, equality, inequality, complementarity, recomputed in primal form).",
        "Design gradients and design loops follow the scenes ([below](#gradient-2d-punch-energy)).",
        f"Raw data: [{PAGE}-references.csv]({PAGE}-references.csv) (the references, with the independent",
        f"checks' figures), [{PAGE}-sweeps.csv]({PAGE}-sweeps.csv) (every solve of the sweeps),",
        f"[{PAGE}-gradients.csv]({PAGE}-gradients.csv) (the gradient sweeps, references included),",
        f"[{PAGE}-design-loops.csv]({PAGE}-design-loops.csv) (one row per design loop).",
        "",
        "Which tol for what accuracy: per scene, the largest tol of the sweep whose solution error",
        "is at most the target, and its Hessian multiplications (\"-\": no tol of the sweep reached it).",
        "",
        *markdown_table([dict(scene=r["scene"], **pick) for r, rows in data for pick in [picks(rows)]], PICK_COLUMNS),
        "",
        "The same for a design gradient (its error max_j |g_j - g_ref,j| / max_j |g_ref,j| against the gradient at",
        "tol = 1e-12; multiplications of the state and adjoint solves), for a design loop (its final design's cost",
        "against the loop's at tol = 1e-12, both solved again at 1e-12; multiplications of the whole loop) and for a",
        f"transient run (its answer against the run at tol = {tol_text(TRANSIENT_REFERENCE)}; multiplications of all its",
        "steps, [below](#transient-contact-a-whole-run-at-each-tol)). Here the",
        "largest tol from which on every tighter tol of the sweep reaches the target with status converged: a loop",
        "may reach it at one tol and miss it at the next tighter one, and a run whose tightest tol ended",
        "`stagnated` (a solve stopped at round-off, reported) shows `-` throughout.",
        "",
        *markdown_table(second, GRADIENT_PICK_COLUMNS),
        "",
        pick_reading(data, gradients, loops),
        "",
        transient_reading(transients),
        "",
        "![KKT residual against tol](accuracy-tolerance.png)",
        "",
        "![accuracy against time](accuracy-and-time.png)",
        "",
        "![gradients and design loops against tol](accuracy-gradients.png)",
        "",
    ]
    for reference, rows in data:
        columns = SWEEP + {"Hertz": HERTZ, "Mindlin": MINDLIN, "load balance": BALANCE}.get(reference["kind"], [])
        if any(r["status"] != "0" for r in rows):
            columns = columns + STATUS
        lines += [f"## {reference['scene']}", "",
                  f"Reference (tol = {tol_text(f(reference, 'tol'))}): {reference['hessian']} Hessian multiplications, "
                  f"{f(reference, 'seconds'):.3f} s, KKT {f(reference, 'kkt'):.1e}"
                  + (" (status 2: stagnated at round-off, the residual above its tol is the best the data allow)"
                     if reference["status"] == "2" else "")
                  + f"; confirmed: {confirmation(reference)}.", "",
                  *markdown_table(rows, columns), ""]
    for label, reference, rows in gradients:
        lines += gradient_section(label, reference, rows)
    lines += loops_section(loops)
    lines += transient_section(transients)
    save_page(f"{PAGE}.md", lines)


def plot_gradients(gradients, loops):
    """Left: the gradient's error against tol per gradient sweep; right: each design loop's final
    cost error against its tol, each point labelled with its designs and multiplications."""
    fig, axes = plt.subplots(1, 2, figsize=(12, 4.6))
    for label, _, rows in gradients:
        axes[0].loglog([f(r, "tol") for r in rows], [max(gradient_error(r), 1e-16) for r in rows], "o-", label=label,
                       ms=4)
    tols = [f(r, "tol") for _, _, rows in gradients for r in rows]
    axes[0].loglog([min(tols), max(tols)], [min(tols), max(tols)], "k--", lw=1, label="error = tol")
    axes[0].set_xlabel("tol")
    axes[0].set_ylabel("gradient error max|g - g_ref| / max|g_ref|")
    axes[0].set_title("Design gradient against tol")
    labels = []
    for label, reference, rows in loops:
        error = loop_error(reference)
        done = [r for r in rows if error(r) < math.inf]
        line, = axes[1].loglog([f(r, "tol") for r in done], [max(error(r), 1e-16) for r in done], "o-", label=label,
                               ms=4)
        labels += [(f(r, "tol"), max(error(r), 1e-16), f"{r['steps']} / {int(f(r, 'hessian_total')):,}",
                    line.get_color()) for r in done]
    axes[1].set_ylim(bottom=1e-18)  # room for the labels of the loops that reached every digit
    annotate_apart(axes[1], labels)
    axes[1].set_xlabel("tol of the whole loop")
    axes[1].set_ylabel("final design's cost error (1e-16: the same digits)")
    axes[1].set_title("Design loops against the loop at 1e-12 (designs / multiplications)")
    for ax in axes:
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(os.path.join(OUT, "accuracy-gradients.png"), dpi=110)
    plt.close(fig)


def annotate_apart(ax, labels, gap_points=9):
    """Each (x, y, text, colour) written beside its point, moved down where it would overlap
    a label already written at the same x (points of different loops meet or nearly meet)."""
    ax.figure.canvas.draw()  # fixes the axes' limits, hence where each point lands
    to_points = 72 / ax.figure.dpi
    taken = {}
    for x, y, text, colour in sorted(labels, key=lambda item: -item[1]):
        at = ax.transData.transform((x, y))[1] * to_points + 4
        for other in sorted(taken.get(x, []), reverse=True):
            if abs(at - other) < gap_points:
                at = other - gap_points
        taken.setdefault(x, []).append(at)
        offset = at - ax.transData.transform((x, y))[1] * to_points
        ax.annotate(text, (x, y), fontsize=7, xytext=(3, offset), textcoords="offset points", color=colour)


def style(k):
    """The k-th scene's line style: the colour cycle has 10 colours, past it another style."""
    return "o-" if k < 10 else "s--"


def plot(data, tol_range):
    fig, ax = plt.subplots(figsize=(6, 4.6))
    for k, (reference, rows) in enumerate(data):
        ax.loglog([f(r, "tol") for r in rows], [f(r, "kkt") for r in rows], style(k), label=reference["scene"], ms=4)
    tols = [f(r, "tol") for _, rows in data for r in rows]
    ax.loglog([min(tols), max(tols)], [min(tols), max(tols)], "k--", lw=1, label="KKT = tol")
    ax.set_xlabel("tol")
    ax.set_ylabel("largest relative KKT residual")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=7)
    ax.set_title("One tolerance, one meaning: KKT residual against tol")
    fig.tight_layout()
    fig.savefig(os.path.join(OUT, "accuracy-tolerance.png"), dpi=110)
    plt.close(fig)

    fig, axes = plt.subplots(1, 2, figsize=(12, 6.2))
    for k, (reference, rows) in enumerate(data):
        error = [max(f(r, "u_error"), 1e-16) for r in rows]
        axes[0].loglog([f(r, "seconds") for r in rows], error, style(k), label=reference["scene"], ms=4)
        axes[1].semilogy([f(r, "hessian") for r in rows], error, style(k), label=reference["scene"], ms=4)
    axes[0].set_xlabel("dual solve and recovery [s]")
    axes[1].set_xlabel("Hessian multiplications")
    for ax in axes:
        ax.set_ylabel("solution error ||u - u_ref||_inf / ||u_ref||_inf")
        ax.grid(True, which="both", alpha=0.3)
    # Below both panels: inside one it hid that panel's curves at small errors.
    handles, labels = axes[1].get_legend_handles_labels()
    fig.legend(handles, labels, fontsize=7, ncol=3, loc="lower center")
    fig.suptitle(f"Accuracy against cost, tol = {tol_range} (one point per tol)")
    fig.tight_layout(rect=(0, 0.16, 1, 1))
    fig.savefig(os.path.join(OUT, "accuracy-and-time.png"), dpi=110)
    plt.close(fig)


if __name__ == "__main__":
    main()
