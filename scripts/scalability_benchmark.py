#!/usr/bin/env python3
"""Numerical scalability of the model problem at fixed H/h = 64: where the dual operator
applications go as h shrinks, with contact (SMALBE-M, MPRGP inside) and without it (the
same decomposition glued, the right membrane fixed: projected CG, plain and with the
Dirichlet preconditioner). Writes the raw data of one run (docs/results/scalability-cases.csv)
and renders docs/results/scalability.md and its plot from it (--render: again from the CSV).
FFETI_SCALABILITY_SIZES (e.g. "64 128 256") overrides the sizes (default up to n = 2048,
8.6 million unknowns, 12 GB)."""
import argparse
import os

import matplotlib

matplotlib.use("Agg")

from ffeti_bench import (begin_run, end_run, f, machine_line, markdown_table, model_problem,  # noqa: E402
                         plot_cost_over_unknowns, read_csv, save_page, write_csv)

SIZES = [int(n) for n in os.environ.get("FFETI_SCALABILITY_SIZES", "64 128 256 512 1024 2048").split()]
# The seed paper's CG iterations (published figures, not measured here).
SEED_CG = {64: "27", 128: "27..65", 256: "27..65", 512: "54"}
# (label, options of edp/model-problem.edp)
CASES = [
    ("contact (default: lumped preconditioner in face)", {}),
    ("contact, seed's stopping test", {"stop": "seed"}),
    ("contact, Dirichlet preconditioner in face", {"preconditioner": "dirichlet"}),
    ("contact, no preconditioner", {"preconditioner": "none"}),
    ("contact, no preconditioner, CG restarted after expansions (before)",
     {"preconditioner": "none", "expansion": "projected-cg-restart"}),
    ("contact, all of G penalized, CG restarted (before the free rows)",
     {"preconditioner": "none", "coarse": "penalty", "expansion": "projected-cg-restart"}),
    ("glued, no preconditioner", {"glued": 1, "preconditioner": "none"}),
    ("glued, lumped preconditioner (default)", {"glued": 1}),
    ("glued, Dirichlet preconditioner", {"glued": 1, "preconditioner": "dirichlet"}),
]


PAGE = "scalability"


def peak_memory(result):
    return max(float(r.get("peak_memory_mb", 0)) for r in result["ranks_detail"]) if result["ranks_detail"] else 0.0


def per_multiplication(result, seconds):
    multiplications = int(result["hessian"])
    return f"{1000 * seconds / multiplications:.2f}" if multiplications else "-"


def rest_of_dual_solve(result):
    """The dual solve's time outside F, the preconditioner and the stopping test's checks."""
    parts = ("time_dual_operator", "time_preconditioner", "time_primal_checks")
    return f(result, "time_dual_solve") - sum(f(result, key) for key in parts)


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--render", action="store_true", help="re-render the page from its CSVs, no run")
    if not parser.parse_args().render:
        begun = begin_run()
        rows = []
        for n in SIZES:
            for label, options in CASES:
                r = model_problem(n, **options)
                rows.append(dict(case=label, **r, peak_memory_mb=peak_memory(r)))
        write_csv(PAGE, "cases", rows)
        end_run(PAGE, begun)
    render()


def headline(runs):
    """The first screen: what was solved, the headline figure, what it means."""
    default, glued = runs[CASES[0][0]], runs.get("glued, lumped preconditioner (default)", [])
    counts = ", ".join(r["hessian"] for r in default)
    sizes = f"n = {default[0]['n']} .. {default[-1]['n']}"
    largest = default[-1]
    lines = [
        "**What was solved.** The seed's model problem: two membranes, one floating, in contact",
        f"along a line, split into squares of H/h = 64 cells, {sizes} cells per side (up to",
        f"{int(largest['primal']):,} unknowns and {largest['subdomains']} subdomains), tol = 1e-4, default options.",
        "",
        f"**Headline.** With default options the dual solve takes {counts} Hessian multiplications",
        f"(dual operator applications) for {sizes}: bounded as h falls at fixed H/h, as FETI theory",
        f"predicts; the seed reports 27 to 65 CG iterations on the same problem (54 at its largest, n = 512).",
    ]
    if glued:
        added = [int(d["hessian"]) - int(g["hessian"]) for d, g in zip(default, glued)]
        lines += [f"Without contact (\"glued\", projected CG) the same decompositions take {', '.join(r['hessian'] for r in glued)}:",
                  f"contact and the floating membrane's balance add {min(added)} to {max(added)}."]
    lines += [
        "",
        "**What it means.** At fixed H/h a finer mesh brings more subdomains, each solve costing",
        "the same, so the time per multiplication grows with the unknowns while the number of",
        "multiplications does not. The table below shows where the multiplications and the time go per variant",
        "(preconditioners, stopping tests, expansion steps); the reading is in",
        "[scalability-reading.md](scalability-reading.md).",
    ]
    return lines


def render():
    rows, run_row = read_csv(PAGE, "cases"), read_csv(PAGE, "run")[0]
    runs = {label: [r for r in rows if r["case"] == label] for label, _ in CASES}
    plot_cost_over_unknowns(runs, "Model problem, H/h = 64, tol = 1e-4", "scalability.png")
    lines = [
        "# Numerical scalability: where the dual operator applications go",
        "",
        "Generated by `scripts/benchmark.sh scalability` (do not edit by hand) on:",
        machine_line(run_row),
        "",
        *headline(runs),
        "",
        "## What the cases mean",
        "",
        "The seed's model problem (`edp/model-problem.edp`), H/h = 64, tol = 1e-4, default options",
        "otherwise (the default stopping test bounds the relative constraint violation of the primal",
        "solution by tol; \"seed's stopping test\" is `||gP||_2 <= tol ||b||_2`, the test the seed's",
        "iteration counts were measured with). \"glued\" is the same decomposition without contact, the right membrane fixed at",
        "x = 2 (`-glued 1`): equality constraints only, so the solve is projected CG and its",
        "iterations measure the conditioning of the projected dual operator alone. The default",
        "preconditioner is the lumped one (`preconditioner=\"lumped\"`: M = A (sum_s B_s K_s B_s') A,",
        "no factorization), applied in face on the contact path. By default",
        "(`coarse=\"free-rows\"`) the balance of each floating subdomain is kept by moving gluing",
        "multipliers and SMALBE-M handles only the floating membrane's one balance equation; \"all of G",
        "penalized, CG restarted (before the free rows)\" is the formulation of the seed and of the default before",
        "(`coarse=\"penalty\"`, SMALBE-M on every subdomain's balance, M0 = 100 ||A||), with MPRGP's",
        "conjugate gradients restarted after every expansion as they were then; \"CG restarted after",
        "expansions (before)\" is the free-rows formulation before MPRGP went on with the CG recurrence",
        "after a projected expansion (`expansion=\"projected-cg-restart\"`). Hessian",
        "multiplications count every application of F in the solve (the norm estimate's apart);",
        "with a preconditioner each CG step also applies it (\"precond.\"; Dirichlet: one K_ii solve per",
        "subdomain, about the cost of F; lumped: a sparse product; in face on the contact path: MPRGP's conjugate gradient",
        "steps take their directions from it restricted to the free set). Times in seconds: set-up",
        "factorizations (K_s, and K_ii for the preconditioner), solve (norm estimate, building the",
        "free-rows projector, dual solve). The dual solve's time split, in milliseconds per Hessian",
        "multiplication: applying F (`time_dual_operator`: the subdomain solves and the sum over",
        "subdomains), applying the preconditioner (`time_preconditioner`), the stopping test's",
        "primal checks (`time_primal_checks`, \"checks\": how many, each a primal recovery), and the",
        "rest (coarse projections, MPRGP's vector work). Raw data: [scalability-cases.csv](scalability-cases.csv).",
        "",
        *markdown_table(rows, [
            ("n", "n"), ("subdomains", "subdomains"), ("unknowns", "primal"), ("case", "case"), ("outer", "outer"),
            ("Hessian mult.", "hessian"), ("precond.", "preconditioner_applications"), ("CG steps", "cg"),
            ("expansion", "expansion"), ("proportioning", "proportioning"),
            ("factorizations [s]", ("time_setup_factor", ".2f")), ("solve [s]", ("time_solve", ".2f")),
            ("F [ms/mult.]", lambda r: per_multiplication(r, f(r, "time_dual_operator"))),
            ("precond. [ms/mult.]", lambda r: per_multiplication(r, f(r, "time_preconditioner"))),
            ("checks", "scale_evaluations"),
            ("checks [ms/mult.]", lambda r: per_multiplication(r, f(r, "time_primal_checks"))),
            ("rest [ms/mult.]", lambda r: per_multiplication(r, rest_of_dual_solve(r))),
            ("peak memory [MB]", ("peak_memory_mb", ".0f")),
            ("seed CG iterations", lambda r: SEED_CG.get(int(r["n"]), "-") if r["case"] == CASES[0][0] else "")]),
    ]
    lines += ["", "![scalability](scalability.png)", ""]
    save_page(f"{PAGE}.md", lines)


if __name__ == "__main__":
    main()
