#!/usr/bin/env python3
"""A large contact zone (edp/large-contact.edp: two clamped membranes stacked, every interior
node a contact couple, 9 subdomains whatever h, the MPRGP path, and H/h fixed): Hessian multiplications,
time and accuracy over h, for the expansion step (fixed step against projected CG, with CG
restarted or continued after it) and the
stopping test (the seed's against the relative KKT one), side by side in one run. Accuracy
is measured against a primal-dual active set solution of the unsplit problem (UMFPACK) up
to n = 160, and against ffeti at tol = 1e-10 beyond. Writes the raw data of one run
(docs/results/large-contact-cases.csv, large-contact-references.csv, large-contact-trace.csv)
and renders docs/results/large-contact.md and its plots from it (--render: again from the
CSVs, no run). FFETI_LARGE_CONTACT_SIZES overrides the sizes (default "40 80 160 320")."""
import argparse
import os
import re

import matplotlib

matplotlib.use("Agg")

from ffeti_bench import (OUT, begin_run, end_run, f, machine_line, markdown_table, plot_cost_over_unknowns,  # noqa: E402
                         read_csv, run, save_page, span, write_csv)

SIZES = [int(n) for n in os.environ.get("FFETI_LARGE_CONTACT_SIZES", "40 80 160 320").split()]
# At fixed H/h (option Hh) one more size, twice the largest (about 900,000 unknowns, 2048
# subdomains), without a reference: it costs seconds where the 9-subdomain cases cost minutes.
FIXED_H_EXTRA_SIZE = 2 * SIZES[-1]
LARGEST_REFERENCE = 160  # the active set reference takes 35 s at n = 160 and grows fast
# (label, options of edp/large-contact.edp)
CASES = [
    ("default: lumped preconditioner in face, CG continued, KKT stop", {}),
    ("the same, seed's stop", {"stop": "seed"}),
    ("no preconditioner, CG continued", {"preconditioner": "none"}),
    ("no preconditioner, CG restarted (before)", {"preconditioner": "none", "expansion": "projected-cg-restart"}),
    ("no preconditioner, fixed-step expansion", {"preconditioner": "none", "expansion": "fixed"}),
    ("no preconditioner, fixed-step expansion, seed's stop (first default)",
     {"preconditioner": "none", "expansion": "fixed", "stop": "seed"}),
    ("lumped preconditioner, CG restarted", {"expansion": "projected-cg-restart"}),
    ("default, started from the solution on n/2 (nested iteration), start settled", {"nested": 1}),
    ("the same, start not settled (settle=0, before)", {"nested": 1, "settle": 0}),
    ("default, nested over n/4, n/2, n", {"nested": 2}),
    ("nested over n/2, the plugin's nearest-couple transfer (fetiContactStart)", {"nested": 1, "transfer": "nearest"}),
    ("H/h = 20 fixed (squares of 20 cells), from zero", {"Hh": 20}),
    ("H/h = 20 fixed, nested over n/2", {"Hh": 20, "nested": 1}),
    ("H/h = 20 fixed, nested over n/2, not settled (before)", {"Hh": 20, "nested": 1, "settle": 0}),
    ("H/h = 20 fixed, nested from n = 40 (every level started from the one before)", {"Hh": 20, "nested": "from 40"}),
    ("glued: no contact, CG", {"glued": 1, "preconditioner": "none"}),
    ("glued, lumped preconditioner", {"glued": 1}),
]

# The cases of the figure (all are in the table): the first default, today's, nested
# iteration with and without settling, H/h fixed, and the operator without the bounds.
PLOTTED = [CASES[k][0] for k in (5, 0, 7, 8, 11, 12, 14, 16)]


def arguments(n, options):
    args = ["-n", n]
    for key, value in options.items():
        if value == "from 40":  # levels 40, 80, ..., n: nested over log2(n / 40) coarser levels
            value = (n // 40).bit_length() - 1
        args += [f"-{key}", value]
    return args


def scene(n, **options):
    return run("large-contact.edp", *arguments(n, options))["RESULT"][0]


PROGRESS = re.compile(r"ffeti (?:mprgp|settle)\s+\d+\s+hessian\s+(\d+)\s+\|\|gP\|\|\s+(\S+).*contact\s+(\d+)")


def trace(n, **options):
    """Progress lines of the (finest) solve, MPRGP's and those settling its start:
    [(Hessian mult., ||gP||, couples in contact)]."""
    output = run("large-contact.edp", *arguments(n, dict(options, reference=0)), "-v", 1)["output"]
    return [(int(h), float(g), int(c)) for h, g, c in PROGRESS.findall(output)]


PAGE = "large-contact"
TOL = "1e-4"  # the scene's default, every case
# The traces of the second figure, in drawing order (the settled run last: on top of the
# unsettled one where they overlap).
TRACES = [("default (cold start)", {}), ("nested over n/2, not settled (before)", {"nested": 1, "settle": 0}),
          ("nested over n/2, start settled", {"nested": 1})]


def plot_traces(trace_rows, contact, n, subdomains, name):
    """Couples in contact and ||gP|| against the Hessian multiplications, one line per trace."""
    import matplotlib.pyplot as plt

    fig, axes = plt.subplots(1, 2, figsize=(11, 4.6))
    for label, _ in TRACES:
        points = [p for p in trace_rows if p["trace"] == label]
        hessian = [int(p["hessian"]) for p in points]
        axes[0].plot(hessian, [int(p["contact"]) for p in points], ".-", label=label)
        axes[1].semilogy(hessian, [f(p, "gP") for p in points], ".-", label=label)
    axes[0].axhline(contact, color="k", linestyle="--", linewidth=0.8, label="contact set of the solution")
    axes[0].set_ylabel("couples in contact")
    axes[1].set_ylabel("||gP||_2")
    for ax in axes:
        ax.set_xlabel("Hessian multiplications")
        ax.grid(True, alpha=0.3)
    axes[0].legend(fontsize=8)
    fig.suptitle(f"Large contact zone, n = {n}, {subdomains} subdomains: how MPRGP finds the contact set")
    fig.tight_layout()
    fig.savefig(os.path.join(OUT, name), dpi=110)
    plt.close(fig)


def ring_summary(reference):
    """The active set reference starts with every couple in contact and releases couples until
    the set repeats: couples released per iteration, beside the edge of the contact zone (a
    square-like zone of c nodes has about 4 sqrt(c) on its edge)."""
    contact = int(reference["active_reference"])
    released = (int(reference["couples"]) - contact) / max(int(reference["pdas_iterations"]) - 1, 1)
    return (f"n = {reference['n']}: {reference['pdas_iterations']} active set iterations, "
            f"{f(reference, 'time_reference'):.1f} s, {released:.0f} couples released per iteration "
            f"(edge of the zone: {4 * contact ** 0.5:.0f} nodes)")


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--render", action="store_true", help="re-render the page from its CSVs, no run")
    if not parser.parse_args().render:
        measure()
    render()


def measure():
    begun = begin_run()
    references, cases = [], []
    for n in SIZES:
        if n <= LARGEST_REFERENCE:
            references.append(dict(kind="active set", **scene(n, reference=1)))  # also the default case
        else:
            references.append(dict(kind="ffeti tol 1e-10", **scene(n, reference=0, tol=1e-10)))
        cases += [dict(case=label, **scene(n, reference=0, **options)) for label, options in CASES]
    cases += [dict(case=label, **scene(FIXED_H_EXTRA_SIZE, reference=0, **options))
              for label, options in CASES if "Hh" in options]
    write_csv(PAGE, "references", references)
    write_csv(PAGE, "cases", cases)
    largest = SIZES[-1]
    write_csv(PAGE, "trace", [dict(trace=label, n=largest, hessian=h, gP=g, contact=c)
                              for label, options in TRACES for h, g, c in trace(largest, **options)])
    end_run(PAGE, begun)


def headline(cases):
    """The first screen: what was solved, the headline figures, what they mean."""
    def series(label):
        return [r for r in cases if r["case"] == label]

    # CASES[5] is the first default (fixed-step expansion, seed's stop), CASES[7] nested iteration
    default, first, nested = series(CASES[0][0]), series(CASES[5][0]), series(CASES[7][0])
    sizes = ", ".join(r["n"] for r in default)
    def violation(r):  # the largest relative KKT residual of the returned solution
        return max(f(r, "kkt_equality"), f(r, "kkt_inequality"))

    violations, first_violations = [violation(r) for r in default], [violation(r) for r in first]
    lines = [
        "**What was solved.** Two clamped membranes pressed together over their whole area: every",
        f"interior node a contact couple ({int(default[0]['couples']):,} to {int(default[-1]['couples']):,} couples for n = {sizes}, about",
        f"half in contact), 9 subdomains, tol = {TOL}: contact set finding at its hardest.",
        "",
        f"**Headline.** The default solver needs {', '.join(r['hessian'] for r in default)} Hessian multiplications for",
        f"n = {sizes}, where the first defaults needed {', '.join(r['hessian'] for r in first)}; its answers violate the",
        f"constraints by {min(violations):.1e} to {max(violations):.1e} relative (tol = {TOL}), the first defaults' by",
        f"{min(first_violations):.1e} to {max(first_violations):.1e}.",
    ]
    if nested:
        lines.append(f"Started from the solution on n/2 (nested iteration) the finest level needs {', '.join(r['hessian'] for r in nested)}.")
    lines += [
        "",
        "**What it means.** The count from zero grows with the contact zone's edge (the contact set",
        "is found about one ring of couples per expansion), not with the dual operator's",
        "conditioning; a start near the answer removes most of that work. The reading:",
        "[large-contact-reading.md](large-contact-reading.md).",
    ]
    return lines


def render():
    references, cases, trace_rows = (read_csv(PAGE, table) for table in ("references", "cases", "trace"))
    run_row = read_csv(PAGE, "run")[0]
    by_n = {r["n"]: r for r in references}
    for r in cases:  # the energy error against the reference and the reference's contact set
        reference = by_n.get(r["n"])
        if reference is None or r["glued"] == "1":
            continue  # no reference at the extra size; glued: another problem, no energy to compare
        active_set = reference["kind"] == "active set"
        q_ref = f(reference, "energy_reference") if active_set else f(reference, "energy")
        r["error_vs_reference"] = (f(r, "energy") - q_ref) / abs(q_ref)
        r["active_reference"] = reference["active_reference"] if active_set else reference["active"]
    plotted = {label: [r for r in cases if r["case"] == label] for label in PLOTTED}
    plot_cost_over_unknowns(plotted, f"Large contact zone (every interior node a couple), tol = {TOL}",
                            "large-contact.png", legend_columns=2)
    largest = references[-1]
    trace_n = trace_rows[0]["n"]
    subdomains = next(r["subdomains"] for r in cases if r["n"] == trace_n and r["case"] == CASES[0][0])
    plot_traces(trace_rows, int(largest["active_reference"] if largest["kind"] == "active set" else largest["active"]),
                trace_n, subdomains, "large-contact-trace.png")
    order = {label: k for k, (label, _) in enumerate(CASES)}
    rows = sorted(cases, key=lambda r: (int(r["n"]), order[r["case"]]))
    seed_stop = [max(f(r, "kkt_equality"), f(r, "kkt_inequality")) / float(TOL) for r in cases
                 if r["stop"] == "seed" and r["glued"] == "0"]
    lines = [
        "# A large contact zone: expansion steps and the stopping test",
        "",
        "Generated by `scripts/benchmark.sh large-contact` (do not edit by hand) on:",
        machine_line(run_row),
        "",
        *headline(cases),
        "",
        "## The scene and the cases",
        "",
        "The scene (`edp/large-contact.edp`): two membranes stacked over the unit square, both clamped",
        "on their whole boundary, the upper one (load -1) pressed onto the lower one across a gap of",
        "0.01; every interior node is a contact couple, about half end up in contact. The split is",
        "fixed, 9 subdomains whatever h (H/h grows with n), none floats: the dual problem is bound",
        f"constrained and MPRGP solves it. tol = {TOL} in every case. Raw data:",
        f"[{PAGE}-cases.csv]({PAGE}-cases.csv) (every solve), [{PAGE}-references.csv]({PAGE}-references.csv)",
        f"(the reference solves), [{PAGE}-trace.csv]({PAGE}-trace.csv) (the progress lines of the second figure).",
        "",
        "- *H/h = 20 fixed* (`-Hh 20`): instead each membrane in squares of 20 cells per side, as the",
        "  seed measures scalability (H/h fixed as h shrinks); the inner squares float (the SMALBE-M",
        "  path with the free-rows projector; \"outer\": its multiplier updates). These cases also",
        f"  run at n = {FIXED_H_EXTRA_SIZE}, without a reference.",
        "- *stop*: the default KKT test `||gP||_inf <= tol ||u||_inf` bounds the relative constraint",
        "  violation (gluing jumps, penetration) of the primal solution; the seed's `||gP||_2 <= tol ||b||_2`",
        "  sums over all rows, so with thousands of couples it stops with violations",
        f"  {span(seed_stop, '.1f')} times tol in this run.",
        "- *expansion*: the fixed step (`expansion=\"fixed\"`) moves each multiplier by at most",
        "  abar |phi_i| per expansion; the projected CG step takes the whole CG step and",
        "  projects it, kept if it decreases the cost at least as much as the fixed step is",
        "  guaranteed to (otherwise the fixed step: \"fallbacks\"). After a kept one the default",
        "  goes on with the CG recurrence in the new face (`expansion=\"projected-cg\"`); before, CG",
        "  restarted from the free gradient (`expansion=\"projected-cg-restart\"`).",
        "- *nested*: the scene first solved on n/2 (or n/4, then n/2) cells per side, each solve",
        "  started (`fetiSolve(..., start=)`) from the contact pressure of the one before, sampled",
        "  at the finer couples (`largeContactStart` in `edp/scenes/large-contact.idp`), or with the",
        "  plugin's transfer for any scene (`fetiContactStart`: each couple the force of the",
        "  nearest coarser couple, shared among the couples nearest to it). Each start is settled",
        "  first (`fetiSolve(..., settle=2)`, the default): up to two face solves, conjugate",
        "  gradients on the start's contact set with the bounds ignored, then projected, each kept",
        "  if it lowers the cost (their CG steps: \"settle\"); `settle=0` starts MPRGP from the",
        "  transferred multipliers as they are. \"Hessian mult.\" and \"solve\" are the finest",
        "  level's; the coarser levels' multiplications, the same weighted by each level's unknowns",
        "  over the finest's (\"finest equiv.\": their cost in multiplications of the finest level),",
        "  and their whole time (assembly, set-up, solve, transfer) are in their own column.",
        "",
        "Energy error: relative to the reference (a primal-dual active set solution of the unsplit",
        f"problem up to n = {LARGEST_REFERENCE}, ffeti at tol 1e-10 beyond); negative means below the minimum, which",
        "only a solution that violates the constraints can reach. \"violation\": the largest",
        "relative KKT residual of the returned solution (equality, inequality; fetiInfo). Contact:",
        "couples with a positive multiplier, and in the reference. \"glued\": both membranes one",
        "body, every couple a gluing row (`-glued 1`): the same dual operator without the bounds,",
        "solved by CG, to separate its conditioning (H/h grows with n; for contact over an area the",
        "dual operator is an inverse Laplacian on the contact nodes) from the work of finding the",
        "contact set. Every interior node is a couple, so no subdomain has interior dofs and the",
        "Dirichlet preconditioner is the lumped one (the default), at no factorization.",
        "",
        *markdown_table(rows, [
            ("n", "n"), ("unknowns", "primal"), ("couples", "couples"), ("subdomains", "subdomains"), ("case", "case"),
            ("outer", "outer"), ("Hessian mult.", "hessian"), ("expansions", "expansion"),
            ("fallbacks", "expansion_fallback"), ("CG steps", "cg"), ("settle", "settle"),
            ("solve [s]", ("time_solve", ".3f")),
            ("coarser levels: mult. (finest equiv.), [s]", lambda r: (
                f"{r['nested_hessian']} ({f(r, 'nested_work'):.0f}), {f(r, 'time_nested'):.2f}"
                if f(r, "nested") > 0 else "-")),
            ("energy error", ("error_vs_reference", ".1e")),
            ("violation", lambda r: f"{max(f(r, 'kkt_equality'), f(r, 'kkt_inequality')):.1e}"),
            ("contact (reference)", lambda r: f"{r['active']} ({r['active_reference']})" if "error_vs_reference" in r
             else "-")]),
        "",
        "Reference solutions (from every couple in contact): " + "; ".join(
            ring_summary(r) for r in references if r["kind"] == "active set") + ".",
        "",
        "![large contact zone](large-contact.png)",
        "",
        f"MPRGP's progress at n = {trace_n} ({subdomains} subdomains): couples in contact and the projected gradient",
        "after each step (and each round settling a nested start), against the Hessian multiplications so far.",
        "",
        "![how the contact set is found](large-contact-trace.png)",
        "",
    ]
    save_page(f"{PAGE}.md", lines)


if __name__ == "__main__":
    main()
