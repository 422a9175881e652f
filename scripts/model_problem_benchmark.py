#!/usr/bin/env python3
"""Runs the model problem scripts under FreeFEM, parses their RESULT/DIRECT/IPOPT lines,
writes them as raw data (docs/results/model-problem-<table>.csv, one per table) and renders
docs/results/model-problem.md with tables and plots from those files (--render: again from
the CSVs, no run). Every figure in that page comes from this one run on this machine; the
reading (model-problem-reading.md, written by hand) is appended. Its last part, the dual
operator against the memory bandwidth (scripts/bandwidth_bound.py), runs at the end and
records its own load; --only bandwidth runs that part alone and re-renders the page."""
import argparse
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from ffeti_bench import (OUT, PHASES, READINGS, begin_run, end_run, f, machine_line, markdown_table,  # noqa: E402
                         model_problem, phase_table, read_csv, run, save_page, write_csv)
import bandwidth_bound  # noqa: E402

SIZES = [64, 128, 256, 512]
# The whole scene's phases at these sizes (FFETI_MODEL_PROBLEM_PHASE_SIZES overrides; --quick:
# the two largest quick sizes); a size among SIZES reuses its default run.
PHASE_SIZES = [int(n) for n in os.environ.get("FFETI_MODEL_PROBLEM_PHASE_SIZES", "512 1024").split()]
PAGE = "model-problem"
# The seed paper's published figures (inputs to compare with, not measured here): primal
# dimensions at n = 64 and 512; dual dimension, couples and active couples at n = 512; CG
# iterations at the smallest and largest size and the most at any size.
SEED = {"primal": {64: 8450, 512: 540800}, "dual": {512: 14975}, "couples": {512: 520}, "active": {512: "~350"},
        "cg": {64: 27, 512: 54}, "cg_range": (27, 65)}
KKT = ("kkt_equilibrium", "kkt_equality", "kkt_inequality", "kkt_complementarity")


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--quick", action="store_true", help="sizes up to 256, fewer tolerances")
    parser.add_argument("--render", action="store_true", help="re-render the page from its CSVs, no run")
    parser.add_argument("--only", choices=("bandwidth",), help="run this part alone, keep the other tables")
    options = parser.parse_args()
    if options.only == "bandwidth" and not options.render:
        bandwidth_bound.measure()
    elif not options.render:
        measure(SIZES[:3] if options.quick else SIZES, options.quick)
        bandwidth_bound.measure()  # last, on its own load record: the machine as quiet as it gets
    render()


def measure(sizes, quick):
    begun = begin_run()
    largest = sizes[-1]
    default = [model_problem(n) for n in sizes]
    write_csv(PAGE, "default", default)
    by_size = {int(r["n"]): r for r in default}
    phase_sizes = sizes[-2:] if quick and "FFETI_MODEL_PROBLEM_PHASE_SIZES" not in os.environ else PHASE_SIZES
    write_csv(PAGE, "phases", [by_size.get(n) or model_problem(n) for n in phase_sizes])
    write_csv(PAGE, "direct", [run("model-problem-direct.edp", "-n", n)["DIRECT"][0] for n in sizes])
    write_csv(PAGE, "ipopt", [run("model-problem-ipopt.edp", "-n", n, prefixes=("IPOPT",))["IPOPT"][0] for n in sizes])
    tight = [model_problem(n, tol="1e-8") for n in sizes]  # about IPOPT's accuracy
    write_csv(PAGE, "tight", tight)
    write_csv(PAGE, "accuracy-reference", [model_problem(n, tol="1e-10") for n in sizes[-2:]])
    tolerances = ["1e-2", "1e-3", "1e-4", "1e-6", "1e-8"] if not quick else ["1e-2", "1e-4", "1e-6"]
    write_csv(PAGE, "accuracy", [model_problem(n, tol=t) for n in sizes[-2:] for t in tolerances])
    variants = [
        ("FETI-1, SMALBE-M (default)", default[-1]),
        ("Total FETI, SMALBE-M", model_problem(largest, variant="tfeti")),
        ("FETI-1, seed Algorithm 3.1", model_problem(largest, algorithm="seed")),
        ("FETI-1, SMALBE-M, the seed's stopping test", model_problem(largest, stop="seed")),
        ("FETI-1, SMALBE-M, no preconditioner", model_problem(largest, preconditioner="none")),
        ("FETI-1, supernodal CHOLMOD (1 thread)", model_problem(largest, factor="supernodal")),
        ("FETI-1, fill-reducing ordering (solves read the whole factor)", model_problem(largest, ordering="fill")),
        ("FETI-1, one factorization per subdomain (no shared factors)", model_problem(largest, shareFactors="off")),
        ("FETI-1, tol 1e-8 (default ordering: the interface last)", tight[-1]),
        ("FETI-1, tol 1e-8, fill-reducing ordering", model_problem(largest, tol="1e-8", ordering="fill")),
        ("FETI-1, 1 OpenMP thread", model_problem(largest, threads=1)),
    ]
    write_csv(PAGE, "variants", [dict(case=name, **r) for name, r in variants])
    end_run(PAGE, begun)


def total(r):
    """ffeti's set-up, solve and recovery, in seconds."""
    return f(r, "time_setup") + f(r, "time_solve") + f(r, "time_recovery")


def kkt(r):
    return max(f(r, k) for k in KKT)


def phase_reading(phases):
    """The largest size's whole time and its largest phase, said from the rows."""
    last = phases[-1]
    label, key = max(PHASES, key=lambda phase: f(last, phase[1]))
    return [f"Reading: at n = {last['n']} ({int(f(last, 'primal')):,} unknowns, {last['subdomains']} subdomains) the whole scene "
            f"takes {f(last, 'time_scene'):.1f} s, the largest phase being the {label} ({f(last, key):.1f} s, "
            f"{f(last, key) / f(last, 'time_scene'):.0%}); the plugin's own set-up is "
            f"{f(last, 'time_plugin_setup') / f(last, 'time_factor'):.2f} times its factorizations."]


def write_plots(default, direct, ipopt, accuracy, reference_energy):
    sizes = [int(r["n"]) for r in default]
    fig, (left, right) = plt.subplots(1, 2, figsize=(11, 4.2))
    left.plot(sizes, [f(r, "hessian") for r in default], "o-", label="ffeti: Hessian multiplications")
    left.plot(sizes, [f(r, "cg") for r in default], "s--", label="ffeti: CG steps")
    seed_sizes = sorted(SEED["cg"])
    left.plot(seed_sizes, [SEED["cg"][n] for n in seed_sizes], "k^", label="seed: CG iterations (smallest, largest)")
    left.axhline(SEED["cg_range"][1], color="gray", lw=0.8, ls=":",
                 label=f"seed: most CG iterations ({SEED['cg_range'][1]})")
    left.set_xscale("log", base=2)
    left.set_xlabel("n (h = 1/n), H/h = 64")
    left.set_ylabel("count")
    left.set_title("Numerical scalability")
    left.legend(fontsize=8)
    right.loglog(sizes, [total(r) for r in default], "o-", label="ffeti: factorization + dual solve + recovery")
    right.loglog(sizes, [f(r, "time_assembly") for r in default], "s--", label="FreeFEM assembly of the subdomain data")
    right.loglog(sizes, [f(r, "time_last_solve") for r in direct], "d-.", label="UMFPACK, final contact set fixed")
    right.loglog(sizes, [f(r, "time_pdas") for r in direct], "x:", label="primal-dual active set + UMFPACK")
    right.loglog(sizes, [f(r, "time") for r in ipopt], "v-", label="IPOPT (ff-Ipopt), tol 1e-8")
    right.set_xscale("log", base=2)
    right.set_xlabel("n (h = 1/n)")
    right.set_ylabel("seconds")
    right.set_title("Time on this machine")
    right.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(OUT, "model-problem-scaling.png"), dpi=110)
    plt.close(fig)

    fig, ax = plt.subplots(figsize=(6, 4.2))
    for n in reference_energy:
        rows = [r for r in accuracy if r["n"] == n]
        # Energies are printed with 12 digits: smaller differences are not resolved.
        errors = [max(abs(f(r, "energy") - reference_energy[n]) / abs(reference_energy[n]), 1e-12) for r in rows]
        times = [f(r, "time_solve") for r in rows]
        ax.loglog(times, errors, "o-", label=f"n = {n}")
        for r, t, e in zip(rows, times, errors):
            ax.annotate(f"{float(r['tol']):.0e}", (t, e), fontsize=7, xytext=(3, 3), textcoords="offset points")
    ax.set_xlabel("dual solve time [s]")
    ax.set_ylabel("relative energy error (floor 1e-12: printed digits)")
    ax.set_title("What accuracy costs (labels: tol)")
    ax.legend()
    fig.tight_layout()
    fig.savefig(os.path.join(OUT, "model-problem-accuracy.png"), dpi=110)
    plt.close(fig)


def seed(kind, r):
    n = int(r["n"])
    return f"{r[kind]} ({SEED[kind].get(n, '-')})"


def render():
    default, direct, ipopt, tight, accuracy, references, variants, phases = (
        read_csv(PAGE, table) for table in ("default", "direct", "ipopt", "tight", "accuracy", "accuracy-reference",
                                            "variants", "phases"))
    run_row = read_csv(PAGE, "run")[0]
    reference_energy = {r["n"]: f(r, "energy") for r in references}
    write_plots(default, direct, ipopt, accuracy, reference_energy)
    by_n = {r["n"]: r for r in direct}
    for rows in (default, tight, ipopt):  # the energy error against PDAS, per solve
        for r in rows:
            d = by_n[r["n"]]
            r["energy_error"] = abs(f(r, "energy") - f(d, "energy")) / abs(f(d, "energy"))
    for r in accuracy:
        error = abs(f(r, "energy") - reference_energy[r["n"]]) / abs(reference_energy[r["n"]])
        r["energy_error"] = f"{error:.1e}" if error >= 1e-12 else "< 1e-12"
    peers = [dict(n=r["n"], unknowns=by_n[r["n"]]["unknowns"], default=r, tight=t, direct=by_n[r["n"]], ipopt=p)
             for r, t, p in zip(default, tight, ipopt)]
    norm_estimate = sorted({r["hessian_norm_estimate"] for r in default + tight + accuracy + variants})
    seed_cg = f"{SEED['cg_range'][0]}..{SEED['cg_range'][1]}"
    lines = [
        "# The seed's model problem: reproduced",
        "",
        "Generated by `scripts/benchmark.sh model-problem` (do not edit by hand) on:",
        f"{machine_line(run_row)} Every number below comes from that one run.",
        "",
        "Problem: the two membranes of the seed paper (`edp/model-problem.edp`), P1 on regular",
        "grids, h = 1/n, H/h = 64, FETI-1 (Dirichlet eliminated inside K_s, as the seed),",
        "SMALBE-M with MPRGP inside, tol = 1e-4 (the seed's value) with the default stopping test",
        "(every relative KKT residual of the returned solution at most tol; the seed's own test,",
        "||gP|| <= tol ||b||, is among the variants), no options passed. Times are wall-clock",
        "seconds; `hessian` counts every application of the dual operator inside the solve (the",
        f"{' or '.join(norm_estimate)} of the norm estimate are reported apart). Raw data: one CSV per table,",
        f"[{PAGE}-default.csv]({PAGE}-default.csv) (default options), [{PAGE}-direct.csv]({PAGE}-direct.csv)",
        f"(UMFPACK and PDAS), [{PAGE}-ipopt.csv]({PAGE}-ipopt.csv), [{PAGE}-tight.csv]({PAGE}-tight.csv)",
        f"(tol = 1e-8), [{PAGE}-accuracy.csv]({PAGE}-accuracy.csv) with its tol = 1e-10 references",
        f"[{PAGE}-accuracy-reference.csv]({PAGE}-accuracy-reference.csv), [{PAGE}-variants.csv]({PAGE}-variants.csv),",
        f"[{PAGE}-phases.csv]({PAGE}-phases.csv) (the whole scene per phase).",
        "",
        "## Numerical scalability, beside the seed's figures",
        "",
        *markdown_table(default, [
            ("n", "n"), ("subdomains", "subdomains"), ("primal (seed)", lambda r: seed("primal", r)),
            ("dual (seed)", lambda r: seed("dual", r)), ("couples (seed)", lambda r: seed("couples", r)),
            ("active (seed)", lambda r: seed("active", r)), ("outer", "outer"), ("Hessian mult.", "hessian"),
            ("CG steps", "cg"), ("seed CG iterations", lambda r: SEED["cg"].get(int(r["n"]), seed_cg))]),
        "",
        "![scaling](model-problem-scaling.png)",
        "",
        "## Time per phase and the direct-solver floor",
        "",
        "`assembly`: FreeFEM builds the subdomain meshes, K_s, f_s, coordinates and condition lists",
        "(interpreted script). `setup`: constraints, kernels, CHOLMOD factorizations, coarse space,",
        "dual data. `solve`: norm estimate and SMALBE. `UMFPACK floor`: one factorization and solve",
        "of the unsplit glued problem with the final contact set fixed (what any contact solver",
        "pays at least); `PDAS`: the whole primal-dual active set method with UMFPACK.",
        "",
        *markdown_table(peers, [
            ("n", "n"), ("unknowns (unsplit)", "unknowns"),
            ("assembly", lambda p: f"{f(p['default'], 'time_assembly'):.3f}"),
            ("setup", lambda p: f"{f(p['default'], 'time_setup'):.3f}"),
            ("solve", lambda p: f"{f(p['default'], 'time_solve'):.3f}"),
            ("recovery", lambda p: f"{f(p['default'], 'time_recovery'):.3f}"),
            ("ffeti total (setup+solve+recovery)", lambda p: f"{total(p['default']):.3f}"),
            ("UMFPACK floor", lambda p: f"{f(p['direct'], 'time_last_solve'):.3f}"),
            ("ratio to floor", lambda p: f"{total(p['default']) / f(p['direct'], 'time_last_solve'):.2f}"),
            ("PDAS (iterations)", lambda p: f"{f(p['direct'], 'time_pdas'):.2f} ({p['direct']['pdas_iterations']})"),
            ("energy ffeti", lambda p: f"{f(p['default'], 'energy'):.8f}"),
            ("energy PDAS", lambda p: f"{f(p['direct'], 'energy'):.8f}")]),
        "",
        "## The whole scene, phase by phase",
        "",
        "The scene from its first line to its last (`edp/model-problem.edp`, default options), each phase",
        "as `edp/ffeti-phases.idp` names it: `assembly` the script's own work before `fetiSetup`;",
        "`plugin set-up` `fetiSetup` without its factorizations (the input's conversion and checks,",
        "constraints, the coarse problem, dual data), of which `coarse` the coarse problem;",
        "`factorization` the subdomains' kernels and CHOLMOD factorizations (identical subdomains",
        "share one) and the preconditioner's set-up; `dual solve` the norm estimate and SMALBE-M;",
        "`recovery` the primal solution (0 where the stopping test's last check recovered it, inside",
        "the dual solve). Whole scene: their sum; peak MB: the process's resident set.",
        f"Raw data: [{PAGE}-phases.csv]({PAGE}-phases.csv).",
        "",
        *phase_table(phases, (("n", "n"), ("unknowns", "primal"), ("subdomains", "subdomains"),
                              ("Hessian mult.", "hessian"))),
        "",
        *phase_reading(phases),
        "",
        "## Peers on the same meshes",
        "",
        "What FreeFEM users do for contact today, IPOPT through ff-Ipopt (`edp/model-problem-ipopt.edp`:",
        "the unsplit problem, the quadratic energy and the non-penetration rows passed as matrices,",
        "IPOPT's default tol = 1e-8), the primal-dual active set method with UMFPACK and the floor,",
        "beside ffeti at its default tol = 1e-4 and at tol = 1e-8. Times in seconds: ffeti set-up +",
        "solve + recovery; IPOPT its solve (A and B assembled); PDAS its whole method with assembly.",
        "Peak memory: the FreeFEM process's resident set, assembly included, in MB. Energy error",
        "against PDAS; violation: the largest penetration relative to max|u| (ffeti: the largest",
        "relative KKT residual).",
        "",
        *markdown_table(peers, [
            ("n", "n"), ("unknowns", "unknowns"), ("ffeti tol 1e-4 [s]", lambda p: f"{total(p['default']):.3f}"),
            ("ffeti tol 1e-8 [s]", lambda p: f"{total(p['tight']):.3f}"),
            ("IPOPT [s]", lambda p: f"{f(p['ipopt'], 'time'):.3f}"),
            ("PDAS [s]", lambda p: f"{f(p['direct'], 'time_pdas'):.2f}"),
            ("floor [s]", lambda p: f"{f(p['direct'], 'time_last_solve'):.3f}"),
            ("IPOPT / ffeti 1e-8", lambda p: f"{f(p['ipopt'], 'time') / total(p['tight']):.1f}"),
            ("peak MB: ffeti / IPOPT / PDAS", lambda p: " / ".join(
                f"{f(p[k], 'process_peak_mb'):.0f}" for k in ("default", "ipopt", "direct"))),
            ("energy error: ffeti 1e-4 / ffeti 1e-8 / IPOPT", lambda p: " / ".join(
                f"{p[k]['energy_error']:.1e}" for k in ("default", "tight", "ipopt"))),
            ("violation: ffeti 1e-4 / 1e-8 / IPOPT",
             lambda p: f"{kkt(p['default']):.1e} / {kkt(p['tight']):.1e} / {f(p['ipopt'], 'violation'):.1e}")]),
        "",
        "## What accuracy costs",
        "",
        "Relative energy error against a solve at tol = 1e-10 of the same discrete problem",
        "(energies are printed with 12 significant digits).",
        "",
        *markdown_table(accuracy, [
            ("n", "n"), ("tol", "tol"), ("outer", "outer"), ("Hessian mult.", "hessian"),
            ("solve [s]", ("time_solve", ".3f")), ("relative energy error", "energy_error"),
            ("KKT equilibrium", ("kkt_equilibrium", ".1e")), ("KKT non-penetration", ("kkt_inequality", ".1e"))]),
        "",
        "![accuracy](model-problem-accuracy.png)",
        "",
        f"## Variants at n = {variants[0]['n']}",
        "",
        *markdown_table(variants, [
            ("variant", "case"), ("dual", "dual"), ("outer", "outer"), ("Hessian mult.", "hessian"),
            ("norm estimate", "hessian_norm_estimate"),
            ("factorizations", "factorizations"),
            ("setup [s]", ("time_setup", ".3f")), ("of which factorization [s]", ("time_factor", ".3f")),
            ("solve [s]", ("time_solve", ".3f")),
            ("F per application [ms]", lambda r: f"{1e3 * f(r, 'time_dual_operator') / f(r, 'dual_operator_applications'):.2f}"),
            ("factors [MB]", lambda r: f"{f(r, 'factor_bytes') / 1e6:.0f}"),
            ("read per pass of F [MB]", lambda r: f"{f(r, 'operator_bytes') / 1e6:.0f}"),
            ("energy", ("energy", ".8f")), ("status", "status")]),
        "",
        *bandwidth_bound.section(),
    ]
    with open(os.path.join(READINGS, "model-problem-reading.md")) as reading:
        lines.append(reading.read())
    save_page(f"{PAGE}.md", lines)


if __name__ == "__main__":
    main()
