#!/usr/bin/env python3
"""3D elasticity at scale (edp/cubes-elasticity-3d.edp): weak scaling at H/h = 8 (n = 16, 32,
64 cells per cube side; FFETI_ELASTICITY_3D_SIZES overrides), the whole scene's phases
(FreeFEM's assembly, the plugin's set-up, factorization, solve, recovery) and peak memory,
the coarse problem at H/h = 4 (8 times the subdomains), the preconditioners and CHOLMOD's
factor kinds side by side at n = 32, and the direct peers (the undivided cubes by the
primal-dual active set method with UMFPACK and with MUMPS, each run alone) at n = 8, 16
(FFETI_ELASTICITY_3D_PEER_SIZES); the H/h = 4 cases at n = 16, 32 (FFETI_ELASTICITY_3D_COARSE_SIZES). Writes docs/results/elasticity-3d.md and its plot from one
run (--render: again from the CSVs)."""
import argparse
import os
import subprocess

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from ffeti_bench import (OUT, begin_run, end_run, f, machine_line, markdown_table, read_csv, run,  # noqa: E402
                         save_page, write_csv)

PAGE = "elasticity-3d"
SIZES = [int(n) for n in os.environ.get("FFETI_ELASTICITY_3D_SIZES", "16 32 64").split()]
VARIANT_SIZE = 32 if 32 in SIZES else SIZES[-1]
PEER_SIZES = [int(n) for n in os.environ.get("FFETI_ELASTICITY_3D_PEER_SIZES", "8 16").split()]
COARSE_SIZES = [int(n) for n in os.environ.get("FFETI_ELASTICITY_3D_COARSE_SIZES", "16 32").split()]
PEERS = [("UMFPACK", []), ("MUMPS", ["-DwithMUMPS=1"])]
PRECONDITIONERS = ["lumped", "dirichlet", "none"]
FACTORS = ["simplicial", "supernodal"]
PHASES = [("time_assembly", "FreeFEM assembly"), ("time_plugin_setup", "plugin set-up"),
          ("time_factor", "factorization"), ("time_solve", "dual solve"), ("time_recovery", "recovery")]


def blas_library():
    """The BLAS the dynamic linker gives CHOLMOD (Debian's alternatives: reference or OpenBLAS)."""
    try:
        text = subprocess.run(["ldconfig", "-p"], capture_output=True, text=True, check=True).stdout
    except (OSError, subprocess.CalledProcessError):
        return "unknown"
    path = next((line.split("=>")[-1].strip() for line in text.splitlines() if "libblas.so.3 " in line), "")
    resolved = os.path.realpath(path) if path else ""
    return "OpenBLAS" if "openblas" in resolved else ("reference BLAS (netlib)" if resolved else "unknown")


def scene(n, *extra, **options):
    args = ["-n", n, *extra]
    for key, value in options.items():
        args += [f"-{key}", value]
    row = run("cubes-elasticity-3d.edp", *args)["RESULT"][0]
    return dict(row, **{key: str(value) for key, value in options.items()})


def scene_total(row):
    """The FETI scene's whole time: FreeFEM's assembly, fetiSetup, the solve and recovery."""
    return sum(f(row, key) for key, _ in PHASES)


def measure_peers():
    """Each size's FETI run beside the direct peers, each run alone, one after the other (so
    that they see the same load); FETI's energy and contact set are compared with UMFPACK's
    answer."""
    rows = []
    for n in PEER_SIZES:
        feti = scene(n, check=1)
        peers = [dict(scene(n, *flags, feti=0, reference=1), solver=f"primal-dual active set, {name}")
                 for name, flags in PEERS]
        reference = f(peers[0], "energy_reference")
        rows.append(dict(feti, solver="ffeti (FETI)", time_total=repr(scene_total(feti)),
                         memory_mb=feti["process_peak_mb"],
                         energy_error=repr(abs(f(feti, "energy") - reference) / abs(reference)),
                         same_contact_set=str(int(feti["active"]) == int(peers[0]["active_reference"]))))
        rows += [dict(p, time_total=p["time_reference"], memory_mb=p["process_peak_mb"]) for p in peers]
    return rows


def measure():
    begun = begin_run()
    weak = [dict(scene(n, check=1), case="default") for n in SIZES]
    coarse = [dict(scene(n, check=1, Hh=4), case="H/h = 4") for n in COARSE_SIZES]
    variants = [dict(scene(VARIANT_SIZE, preconditioner=p), case=f"preconditioner {p}") for p in PRECONDITIONERS]
    variants += [dict(scene(VARIANT_SIZE, factor=k), case=f"factor {k}") for k in FACTORS]
    peers = measure_peers()
    write_csv(PAGE, "weak", weak)
    write_csv(PAGE, "coarse", coarse)
    write_csv(PAGE, "variants", variants)
    write_csv(PAGE, "peers", peers)
    end_run(PAGE, begun)
    write_csv(PAGE, "blas", [{"blas": blas_library()}])


def plot_phases(weak, name):
    figure, (counts, phases) = plt.subplots(1, 2, figsize=(11, 4.2))
    unknowns = [f(r, "unknowns") for r in weak]
    counts.plot(unknowns, [f(r, "hessian") for r in weak], "o-", label="Hessian multiplications")
    counts.set_xscale("log")
    counts.set_xlabel("unknowns")
    counts.set_ylabel("Hessian multiplications")
    counts.set_ylim(0, 1.3 * max(f(r, "hessian") for r in weak))
    counts.set_title("Dual solve, H/h = 8 fixed")
    counts.grid(True, alpha=0.3)
    totals = [sum(f(r, key) for key, _ in PHASES) for r in weak]
    bottom = [0.0] * len(weak)
    labels = [f"n = {r['n']}\n{int(f(r, 'subdomains'))} subdomains\n{t:.1f} s" for r, t in zip(weak, totals)]
    for key, label in PHASES:
        shares = [100 * f(r, key) / t for r, t in zip(weak, totals)]
        phases.bar(labels, shares, bottom=bottom, label=label)
        bottom = [b + v for b, v in zip(bottom, shares)]
    phases.set_ylim(0, 100)
    phases.set_ylabel("share of the scene's wall-clock time [%]")
    phases.set_title("Where the scene's time goes (total below each bar)")
    phases.legend(fontsize=8, loc="upper left", bbox_to_anchor=(1.0, 1.0))
    figure.tight_layout()
    figure.savefig(os.path.join(OUT, name), dpi=90)
    plt.close(figure)


def meaning(growth, last, run_row):
    """What the headline means, said from the figures (the aim met or not; the next size's memory)."""
    if growth <= 1.5:
        said = ["**What it means.** The number of multiplications stays bounded as subdomains are added at",
                "fixed H/h, as FETI theory predicts for elasticity with six rigid modes per subdomain: a",
                "finer mesh costs more subdomain work, not more iterations."]
    else:
        said = [f"**What it means.** The number of multiplications grows {growth:.2f} times over these sizes,",
                "more than the aim allows: the dual solve's conditioning is not yet independent of the",
                "number of subdomains here."]
    memory_per_unknown = f(last, "peak_memory_mb") / f(last, "unknowns")  # MB
    next_unknowns = 8 * f(last, "unknowns")
    needed_gib = memory_per_unknown * next_unknowns / 1024
    if needed_gib > f(run_row, "memory_gib"):
        said.append(f"n = {2 * int(last['n'])} ({next_unknowns / 1e6:.1f} million unknowns) was not run: at the "
                    f"{memory_per_unknown * 1024:.1f} KiB per unknown measured at n = {last['n']} it would need about "
                    f"{needed_gib:.0f} GiB, more than this machine's {f(run_row, 'memory_gib'):.0f} GiB.")
    return said


def peer_ratios(peers):
    """Per size, the peers' time and memory over FETI's."""
    lines = []
    for n in sorted({r["n"] for r in peers}, key=int):
        feti = next(r for r in peers if r["n"] == n and r["solver"] == "ffeti (FETI)")
        for r in peers:
            if r["n"] == n and r is not feti:
                lines.append(f"- n = {n}: {r['solver']} takes {f(r, 'time_total') / f(feti, 'time_total'):.1f} times "
                             f"FETI's time and {f(r, 'memory_mb') / f(feti, 'memory_mb'):.1f} times its memory.")
    return lines


def render():
    weak, variants = read_csv(PAGE, "weak"), read_csv(PAGE, "variants")
    coarse, peers = read_csv(PAGE, "coarse"), read_csv(PAGE, "peers")
    run_row, blas = read_csv(PAGE, "run")[0], read_csv(PAGE, "blas")[0]["blas"]
    plot_phases(weak, f"{PAGE}.png")
    first, last = weak[0], weak[-1]
    growth = f(last, "hessian") / f(first, "hessian")
    total = {id(r): sum(f(r, key) for key, _ in PHASES) for r in weak}
    assembly_share = f(last, "time_assembly") / total[id(last)]
    setup_over_factor = f(last, "time_plugin_setup") / f(last, "time_factor")
    lines = [
        "# 3D elasticity at scale: two elastic cubes in contact",
        "",
        "Generated by `scripts/benchmark.sh elasticity-3d` (do not edit by hand) on:",
        machine_line(run_row),
        f"BLAS used by CHOLMOD: {blas}.",
        "",
        "**What was solved.** `edp/cubes-elasticity-3d.edp`: two elastic unit cubes stacked (a quarter",
        "model), the lower clamped at its bottom, the upper floating, pressed by a traction on a quarter",
        "of its top; node-to-node contact on the shared face with a crowned gap, so that the contact",
        "zone is partial. Each cube is cut into boxes of 8 cells per side (H/h = 8 fixed), P1",
        "elasticity, Total FETI: every box floats, six rigid modes each, tol = 1e-4, default options.",
        "",
        f"**Headline.** From n = {first['n']} to n = {last['n']} cells per cube side ({int(f(first, 'unknowns')):,} to "
        f"{int(f(last, 'unknowns')):,} unknowns, {first['subdomains']} to {last['subdomains']} subdomains, coarse "
        f"space {first['coarse']} to {last['coarse']}) the dual solve takes "
        f"{', '.join(r['hessian'] for r in weak)} Hessian multiplications: {growth:.2f} times the smallest's "
        "(aim: at most 1.5).",
        f"At the largest size FreeFEM's assembly is {assembly_share:.0%} of the scene's time and the plugin's "
        f"own set-up {setup_over_factor:.2f} times its factorizations (aim: at most 1).",
        "",
        *meaning(growth, last, run_row),
        "",
        "## Weak scaling, H/h = 8",
        "",
        *markdown_table(weak, [
            ("n", "n"), ("unknowns", "unknowns"), ("subdomains", "subdomains"), ("dual", "dual"),
            ("coarse", "coarse"), ("couples", "couples"), ("active", "active"), ("Hessian mult.", "hessian"),
            ("outer", "outer"), ("assembly [s]", ("time_assembly", ".2f")),
            ("plugin set-up [s]", ("time_plugin_setup", ".2f")), ("of which coarse [s]", ("time_coarse", ".3f")),
            ("factorization [s]", ("time_factor", ".2f")), ("solve [s]", ("time_solve", ".2f")),
            ("recovery [s]", ("time_recovery", ".3f")), ("peak memory [MB]", ("peak_memory_mb", ".0f")),
            ("force balance", ("balance", ".1e")), ("status", "status")]),
        "",
        f"![phases]({PAGE}.png)",
        "",
        "## The coarse problem with many subdomains, H/h = 4",
        "",
        "The same sizes cut into boxes of 4 cells per side: 8 times the subdomains and the coarse",
        "space (six rigid modes per box). `time_coarse` is the coarse problem's set-up (G G' assembled",
        "and factorized); its application is inside the solve's time.",
        "",
        *markdown_table(coarse, [
            ("n", "n"), ("unknowns", "unknowns"), ("subdomains", "subdomains"), ("coarse", "coarse"),
            ("Hessian mult.", "hessian"), ("assembly [s]", ("time_assembly", ".2f")),
            ("plugin set-up [s]", ("time_plugin_setup", ".2f")), ("of which coarse [s]", ("time_coarse", ".3f")),
            ("factorization [s]", ("time_factor", ".2f")), ("solve [s]", ("time_solve", ".2f")),
            ("peak memory [MB]", ("peak_memory_mb", ".0f")), ("status", "status")]),
        "",
        "## The direct peers",
        "",
        "The undivided cubes (one mesh each) by the primal-dual active set method, each Newton step",
        "a sparse direct solve of the KKT system (edp/active-set.idp), with UMFPACK and with MUMPS",
        "(both ship with FreeFEM), each run alone; the FETI row is the whole scene (assembly,",
        "set-up, solve, recovery), its energy compared with UMFPACK's answer (energy error) and its",
        "contact set's size with UMFPACK's. Memory: each process's peak resident set. FETI's unknowns",
        "count the copies of interface nodes in every subdomain, the peers' each node once.",
        "",
        *markdown_table(peers, [
            ("n", "n"), ("unknowns", "unknowns"), ("solver", "solver"), ("time [s]", ("time_total", ".2f")),
            ("of which last solve [s]", lambda r: f"{f(r, 'time_reference_last_solve'):.2f}" if r["solver"] != "ffeti (FETI)" else "-"),
            ("Newton steps", lambda r: r["pdas_iterations"] if r["solver"] != "ffeti (FETI)" else "-"),
            ("peak memory [MB]", ("memory_mb", ".0f")),
            ("energy error", lambda r: f"{f(r, 'energy_error'):.1e}" if r["solver"] == "ffeti (FETI)" else "-"),
            ("active", lambda r: r["active"] if r["solver"] == "ffeti (FETI)" else r["active_reference"])]),
        "",
        *peer_ratios(peers),
        "",
        f"## Preconditioners and factor kinds, n = {VARIANT_SIZE}",
        "",
        "The same scene with each preconditioner (lumped: a sparse product; Dirichlet: a factorized",
        "interior block per subdomain) and each CHOLMOD factor kind (simplicial, or supernodal with",
        f"dense blocks through the BLAS, here {blas}).",
        "",
        *markdown_table(variants, [
            ("case", "case"), ("Hessian mult.", "hessian"), ("factor nnz", ("factor_nnz", ".3g")),
            ("factorization [s]", ("time_factor", ".2f")), ("solve [s]", ("time_solve", ".2f")),
            ("solve per mult. [ms]", lambda r: f"{1000 * f(r, 'time_solve') / f(r, 'hessian'):.0f}"),
            ("peak memory [MB]", ("peak_memory_mb", ".0f")), ("status", "status")]),
        "",
    ]
    save_page(f"{PAGE}.md", lines)


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--render", action="store_true", help="re-render the page from its CSVs, no run")
    if not parser.parse_args().render:
        measure()
    render()


if __name__ == "__main__":
    main()
