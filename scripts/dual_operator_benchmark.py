#!/usr/bin/env python3
"""Implicit against explicit local dual operators (option dualOperator), side by side in one run:
docs/results/dual-operator.md. Each scene runs with dualOperator = "implicit" (each K_s^+ by the
factor's triangular solves), "explicit" (a dense packed block of K_s^+ on the interface, formed
once after the factorization) and "auto" (explicit where the block holds at most the bytes one
pass of the solve reads), on one thread (like the bandwidth) and with -shareFactors off (every
subdomain its own factor and block, as distinct subdomains would have), interleaved (scene by
scene, each form in turn) and repeated, so that the machine's other load falls on all three
alike; the page gives the min and median of each time. Per multiplication of F: seconds, the
bytes one pass reads (`operator_bytes`: the factors' interface blocks or whole factors, or the
explicit blocks), and the bound = those bytes over STREAM's triad rate (build/tests/stream_triad,
measured at the start and the end of the run; the faster one). Also the seconds forming the
blocks against the factorization's, the memory the blocks hold against the factors', and the
answers (energy, Hessian multiplications), which must agree.
  scripts/dual_operator_benchmark.py [--repeats 3] [--render]
FFETI_DUAL_2D: "n:Hh ..." of edp/model-problem.edp (default "512:32 512:64 1024:64 512:128");
FFETI_DUAL_3D: n of edp/cubes-elasticity-3d.edp (default "16 32"); FFETI_DUAL_REAL: h of
edp/crowned-punch-3d.edp, METIS parts of 1000 nodes (default "1"); FFETI_RUN_DIR: the build's edp-tests folder."""
import argparse
import os
import statistics

from bandwidth_bound import bandwidth
from ffeti_bench import begin_run, end_run, f, machine_line, markdown_table, read_csv, run, save_page, write_csv

PAGE = "dual-operator"
FORMS = ("implicit", "explicit", "auto")
SIZES_2D = [tuple(int(v) for v in case.split(":")) for case in os.environ.get("FFETI_DUAL_2D", "512:32 512:64 1024:64 512:128").split()]
SIZES_3D = [int(n) for n in os.environ.get("FFETI_DUAL_3D", "16 32").split()]
SIZES_REAL = [float(h) for h in os.environ.get("FFETI_DUAL_REAL", "1").split()]


def scenes():
    """(problem, size label, script, arguments) of every case, in run order."""
    cases = [("2D model problem", f"n={n} H/h={Hh}", "model-problem.edp", ["-n", n, "-Hh", Hh]) for n, Hh in SIZES_2D]
    cases += [("3D elasticity cubes", f"n={n} H/h=8", "cubes-elasticity-3d.edp", ["-n", n]) for n in SIZES_3D]
    cases += [("crowned punch (real mesh)", f"h={h:g}, parts of 1000 nodes", "crowned-punch-3d.edp",
               ["-h", h, "-partNodes", 1000]) for h in SIZES_REAL]
    return cases


def measure(repeats):
    begun = begin_run()
    streams = [bandwidth()]
    rows = []
    for repeat in range(repeats):
        for problem, size, script, arguments in scenes():
            for form in FORMS:
                result = run(script, *arguments, "-threads", 1, "-shareFactors", "off", "-dualOperator", form)["RESULT"][0]
                result.setdefault("primal", result.get("unknowns", ""))  # the 3D scenes print unknowns
                applications = f(result, "dual_operator_applications")
                rows.append(dict(problem=problem, size=size, form=form, repeat=repeat, **result,
                                 t_operator=f(result, "time_dual_operator") / applications,
                                 t_solves=f(result, "time_factor_solves") / applications,
                                 t_hessian=f(result, "time_hessian") / f(result, "hessian")))
                print(problem, size, form, repeat, f"{1e3 * rows[-1]['t_operator']:.3f} ms", flush=True)
                write_csv(PAGE, "runs", rows)  # after every run: a run stopped midway keeps what it measured
    streams.append(bandwidth())
    write_csv(PAGE, "bandwidth", streams)
    write_csv(PAGE, "runs", rows)
    end_run(PAGE, begun)


def summary(rows, triad):
    """One row per scene and form: min and median of the times over the repeats."""
    groups = {}
    for r in rows:
        groups.setdefault((r["problem"], r["size"], r["form"]), []).append(r)
    out = []
    for (problem, size, form), group in groups.items():
        first = group[0]
        row = dict(problem=problem, size=size, form=form, repeats=len(group), **{
            k: first[k] for k in ("primal", "subdomains", "hessian", "energy", "explicit_operators", "factor_bytes",
                                  "operator_bytes", "explicit_bytes", "factorizations", "interface_factors",
                                  "supernodal_factors")})
        for key in ("t_operator", "t_solves", "t_hessian", "time_explicit", "time_factor", "time_solve"):
            values = [f(r, key) for r in group]
            row[key + "_min"], row[key + "_median"] = min(values), statistics.median(values)
        row["t_bound"] = f(first, "operator_bytes") / (triad * 1e9)
        row["energies"] = {r["energy"] for r in group}
        out.append(row)
    return out


def ms(key):
    return lambda r: f"{1e3 * r[key]:.3f}"


def section_table(summaries):
    mib = 1e6
    return markdown_table(summaries, [
        ("problem", "problem"), ("size", "size"), ("unknowns", "primal"), ("subdomains", "subdomains"),
        ("form", "form"), ("explicit", lambda r: f"{r['explicit_operators']} of {r['subdomains']}"),
        ("factor MB", lambda r: f"{float(r['factor_bytes']) / mib:.1f}"),
        ("blocks MB", lambda r: f"{float(r['explicit_bytes']) / mib:.1f}"),
        ("read per pass MB", lambda r: f"{float(r['operator_bytes']) / mib:.1f}"),
        ("F min [ms]", ms("t_operator_min")), ("F median [ms]", ms("t_operator_median")),
        ("bound [ms]", ms("t_bound")), ("F min / bound", lambda r: f"{r['t_operator_min'] / r['t_bound']:.2f}"),
        ("Hessian min [ms]", ms("t_hessian_min")),
        ("Hessian mult.", "hessian"),
        ("dual solve min [s]", lambda r: f"{r['time_solve_min']:.3f}"),
        ("factorization min [s]", lambda r: f"{r['time_factor_min']:.3f}"),
        ("forming blocks min [s]", lambda r: f"{r['time_explicit_min']:.3f}")])


def render():
    stream_rows = read_csv(PAGE, "bandwidth")
    stream = max(stream_rows, key=lambda r: f(r, "triad_gb_s"))
    triad = f(stream, "triad_gb_s")
    rates = ", ".join(f"{f(r, 'triad_gb_s'):.2f}" for r in stream_rows)
    rows = read_csv(PAGE, "runs")
    summaries = summary(rows, triad)
    run_row = read_csv(PAGE, "run")[0]
    same = all(len({r["hessian"] for r in rows if r["problem"] == s["problem"] and r["size"] == s["size"]}) == 1
               for s in summaries)
    reading_path = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "docs", "results",
                                "dual-operator-reading.md")
    reading = open(reading_path).read().splitlines() if os.path.exists(reading_path) else []
    lines = [
        "# Explicit local dual operators",
        "",
        f"Machine: {machine_line(run_row)}",
        "",
        "Generated by `scripts/dual_operator_benchmark.py` from "
        f"[{PAGE}-runs.csv]({PAGE}-runs.csv) (every run) and [{PAGE}-bandwidth.csv]({PAGE}-bandwidth.csv).",
        f"STREAM triad on one thread: {rates} GB/s "
        f"(start, end of the run); the bound uses the faster, {triad:.2f} GB/s.",
        "",
        *reading,
        "",
        "## Implicit, explicit and auto side by side",
        "",
        "`F` the dual operator per application (`time_dual_operator / dual_operator_applications`: gathers,",
        "B_s', the solves or dense products, B_s and the sum), min and median over the repeats (interleaved",
        "runs); `bound` the bytes one pass reads over the triad rate (the implicit solve reads them twice, L",
        "then L', where the factor does not stay in cache); `Hessian` the solver's whole multiplication (F",
        "and the coarse projections). `forming blocks`: `time_explicit`, apart from `factorization`",
        "(`time_factor`). Hessian multiplications "
        + ("are the same for the three forms in every scene." if same else "DIFFER between forms somewhere: see the CSV."),
        "",
        *section_table(summaries),
        "",
    ]
    save_page(f"{PAGE}.md", lines)
    print("\n".join(lines))


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--render", action="store_true", help="render the page from the CSVs, no run")
    parser.add_argument("--repeats", type=int, default=3)
    arguments = parser.parse_args()
    if not arguments.render:
        measure(arguments.repeats)
    render()


if __name__ == "__main__":
    main()
