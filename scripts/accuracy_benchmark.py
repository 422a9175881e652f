#!/usr/bin/env python3
"""What accuracy costs in time, on every scene: tol swept from 1e-2 to 1e-10 on one set-up per
scene (edp/tolerance-sweep.idp), each solve compared with the scene's solve at tol = 1e-12,
itself confirmed by an independent method (an active set solution of the unsplit problem,
Hertz's formulas, the force balance of the contact interfaces). Writes the raw data of one
run (docs/results/accuracy-and-time-references.csv, accuracy-and-time-sweeps.csv) and
renders docs/results/accuracy-and-time.md and its plots from it (--render: again from the
CSVs)."""
import argparse
import math
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from ffeti_bench import (OUT, ROOT, begin_run, end_run, f, machine_line, markdown_table, read_csv, run,  # noqa: E402
                         save_page, write_csv)

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
    ("Cattaneo–Mindlin, Coulomb friction (3D, node to face, step 2)", "cattaneo-mindlin-3d.edp",
     ["-meshes", os.path.join(ROOT, "meshes")], "Mindlin"),
]
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
    return {}


def confirmation(reference):
    """How the tol = 1e-12 reference is confirmed independently, as a sentence (from its CSV row)."""
    kind = reference["kind"]
    if kind == "active set":
        gap = abs(f(reference, "energy") - f(reference, "independent_energy")) / abs(f(reference, "independent_energy"))
        sentence = (f"energy {f(reference, 'energy'):.10g} against {f(reference, 'independent_energy'):.10g} from the "
                    f"primal-dual active set method on the unsplit meshes (relative difference {gap:.1e})")
        if reference.get("independent_active"):
            sentence += f"; contact {reference['independent_active']} couples there"
        return sentence
    if kind == "Hertz":
        return (f"contact half-width and peak pressure within {f(reference, 'a_relerr'):.1%} and "
                f"{f(reference, 'p0_relerr'):.1%} of Hertz's (discretization error of this mesh)")
    if kind == "Mindlin":
        return (f"stick zone c/a within {f(reference, 'stick_ratio_error'):.2%} of Mindlin's (discretization error "
                f"of this mesh), friction forces summing to Q to {f(reference, 'balance_error'):.0e}")
    return f"each contact interface carries the load above it to {f(reference, 'balance_error'):.1e}"


SWEEP = [("tol", ("tol", ".0e")), ("Hessian mult.", "hessian"), ("time [s]", ("seconds", ".3f")),
         ("energy error", ("energy_error", ".1e")), ("u error", ("u_error", ".1e")),
         ("contact mismatch", "contact_mismatch"), ("KKT", ("kkt", ".1e"))]
HERTZ = [("a error (Hertz)", ("a_relerr", ".2%")), ("p0 error (Hertz)", ("p0_relerr", ".2%"))]
MINDLIN = [("c/a error (Mindlin)", ("stick_ratio_error", ".2%")), ("Σλ_t vs Q", ("balance_error", ".0e")),
           ("Tresca solves", "fixed_point_iterations")]
STATUS = [("status", lambda r: "converged" if r["status"] == "0" else f"status {r['status']}")]


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--render", action="store_true", help="re-render the page from its CSVs, no run")
    if not parser.parse_args().render:
        begun = begin_run()
        references, sweeps = [], []
        for label, script, args, kind in SCENES:
            lines, reference, rows = sweep(script, args)
            references.append(dict(scene=label, kind=kind, **reference,
                                   **independent(script, args, kind, lines["RESULT"][0])))
            sweeps += [dict(scene=label, **r) for r in rows]
        write_csv(PAGE, "references", references)
        write_csv(PAGE, "sweeps", sweeps)
        end_run(PAGE, begun)
    render()


PICK_COLUMNS = [("scene", "scene")] + [(f"error ≤ {tol_text(t)}", f"target_{i}") for i, t in enumerate(TARGETS)]


def picks(rows):
    """For each target accuracy, 'tol (multiplications)' of the largest tol reaching it, or '-'."""
    chosen = {}
    for i, target in enumerate(TARGETS):
        good = [r for r in rows if f(r, "u_error") <= target and r["status"] == "0"]
        best = max(good, key=lambda r: f(r, "tol")) if good else None
        chosen[f"target_{i}"] = f"{tol_text(f(best, 'tol'))} ({best['hessian']})" if best else "-"
    return chosen


def pick_reading(data):
    """How far the tol a target needs lies from the target, over every scene and target."""
    decades = []
    for _, rows in data:
        for target in TARGETS:
            good = [f(r, "tol") for r in rows if f(r, "u_error") <= target and r["status"] == "0"]
            if good:
                decades.append(round(math.log10(target / max(good))))
    same = sum(1 for d in decades if d == 0)
    one = sum(1 for d in decades if d == 1)
    return (f"Reading: of {len(decades)} (scene, target) pairs a sweep reached, {same} need tol = the target "
            f"itself and {one} one decade tighter{'' if same + one == len(decades) else ', the rest more'}: "
            "pick tol equal to the relative accuracy of u you want, a decade below it to be safe. "
            "With friction a derived quantity needs more: the stick zone's c/a (Cattaneo–Mindlin below) "
            "reaches its mesh's accuracy only from a tol near its error. Not yet swept here: the 3D boxes near "
            "a million unknowns, sensitivities and design loops ([friction](friction.md), [shape optimization](shape-optimization.md)).")


def render():
    references, sweeps, run_row = read_csv(PAGE, "references"), read_csv(PAGE, "sweeps"), read_csv(PAGE, "run")[0]
    data = [(r, [s for s in sweeps if s["scene"] == r["scene"]]) for r in references]
    tols = [f(s, "tol") for s in sweeps]
    reference_tols = {tol_text(f(r, "tol")) for r in references}
    tol_range = f"{tol_text(max(tols))} .. {tol_text(min(tols))}"
    plot(data, tol_range)
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
        f"Raw data: [{PAGE}-references.csv]({PAGE}-references.csv) (the references, with the independent",
        f"checks' figures), [{PAGE}-sweeps.csv]({PAGE}-sweeps.csv) (every solve of the sweeps).",
        "",
        "Which tol for what accuracy: per scene, the largest tol of the sweep whose solution error",
        "is at most the target, and its Hessian multiplications (\"-\": no tol of the sweep reached it).",
        "",
        *markdown_table([dict(scene=r["scene"], **pick) for r, rows in data for pick in [picks(rows)]], PICK_COLUMNS),
        "",
        pick_reading(data),
        "",
        "![KKT residual against tol](accuracy-tolerance.png)",
        "",
        "![accuracy against time](accuracy-and-time.png)",
        "",
    ]
    for reference, rows in data:
        columns = SWEEP + {"Hertz": HERTZ, "Mindlin": MINDLIN}.get(reference["kind"], [])
        if any(r["status"] != "0" for r in rows):
            columns = columns + STATUS
        lines += [f"## {reference['scene']}", "",
                  f"Reference (tol = {tol_text(f(reference, 'tol'))}): {reference['hessian']} Hessian multiplications, "
                  f"{f(reference, 'seconds'):.3f} s, KKT {f(reference, 'kkt'):.1e}"
                  + (" (status 2: stagnated at round-off, the residual above its tol is the best the data allow)"
                     if reference["status"] == "2" else "")
                  + f"; confirmed: {confirmation(reference)}.", "",
                  *markdown_table(rows, columns), ""]
    save_page(f"{PAGE}.md", lines)


def plot(data, tol_range):
    fig, ax = plt.subplots(figsize=(6, 4.6))
    for reference, rows in data:
        ax.loglog([f(r, "tol") for r in rows], [f(r, "kkt") for r in rows], "o-", label=reference["scene"], ms=4)
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

    fig, axes = plt.subplots(1, 2, figsize=(12, 4.6))
    for reference, rows in data:
        error = [max(f(r, "u_error"), 1e-16) for r in rows]
        axes[0].loglog([f(r, "seconds") for r in rows], error, "o-", label=reference["scene"], ms=4)
        axes[1].semilogy([f(r, "hessian") for r in rows], error, "o-", label=reference["scene"], ms=4)
    axes[0].set_xlabel("dual solve and recovery [s]")
    axes[1].set_xlabel("Hessian multiplications")
    for ax in axes:
        ax.set_ylabel("solution error ||u - u_ref||_inf / ||u_ref||_inf")
        ax.grid(True, which="both", alpha=0.3)
    axes[1].legend(fontsize=7)
    fig.suptitle(f"Accuracy against cost, tol = {tol_range} (one point per tol)")
    fig.tight_layout()
    fig.savefig(os.path.join(OUT, "accuracy-and-time.png"), dpi=110)
    plt.close(fig)


if __name__ == "__main__":
    main()
