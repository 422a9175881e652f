#!/usr/bin/env python3
"""Runs the model problem scripts under FreeFEM, parses their RESULT/DIRECT lines and writes
docs/results/model-problem.md with tables and plots. Every figure in that page comes from
this one run on this machine."""
import argparse
import os
import platform
import re
import subprocess
import time

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
EDP = os.path.join(ROOT, "edp")
OUT = os.path.join(ROOT, "docs", "results")
SIZES = [64, 128, 256, 512]


def run(script, *args):
    """Runs one .edp script and returns the key=value dictionaries of its result lines."""
    command = ["FreeFem++-nw", "-v", "0", script, *map(str, args)]
    text = subprocess.run(command, cwd=EDP, capture_output=True, text=True, check=True).stdout
    rows = []
    for line in text.splitlines():
        if line.startswith("RESULT ") or line.startswith("DIRECT "):
            rows.append(dict(kv.split("=", 1) for kv in line.split()[1:]))
    if not rows:
        raise RuntimeError(f"no result line from {' '.join(command)}:\n{text[-2000:]}")
    return rows


def solve(n, **options):
    args = ["-n", n]
    for key, value in options.items():
        args += [f"-{key}", value]
    return run("model-problem.edp", *args)[0]


def f(row, key):
    return float(row[key])


def machine():
    cpu = "unknown CPU"
    try:
        with open("/proc/cpuinfo") as info:
            cpu = re.search(r"model name\s*:\s*(.*)", info.read()).group(1)
    except (OSError, AttributeError):
        pass
    return f"{cpu}, {os.cpu_count()} cores, {platform.system()} {platform.release()}"


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--quick", action="store_true", help="sizes up to 256, fewer tolerances")
    options = parser.parse_args()
    sizes = SIZES[:3] if options.quick else SIZES
    largest = sizes[-1]
    started = time.time()

    default = [solve(n) for n in sizes]
    direct = [run("model-problem-direct.edp", "-n", n)[0] for n in sizes]
    reference_energy = {n: f(solve(n, tol="1e-10"), "energy") for n in sizes[-2:]}
    tolerances = ["1e-2", "1e-3", "1e-4", "1e-6", "1e-8"] if not options.quick else ["1e-2", "1e-4", "1e-6"]
    accuracy = {n: [solve(n, tol=t) for t in tolerances] for n in sizes[-2:]}
    variants = [
        ("FETI-1, SMALBE-M (default)", default[-1]),
        ("Total FETI, SMALBE-M", solve(largest, variant="tfeti")),
        ("FETI-1, seed Algorithm 3.1", solve(largest, algorithm="seed")),
        ("FETI-1, supernodal CHOLMOD (1 thread)", solve(largest, factor="supernodal")),
        ("FETI-1, 1 OpenMP thread", solve(largest, threads=1)),
    ]
    os.makedirs(OUT, exist_ok=True)
    write_plots(sizes, default, direct, accuracy, reference_energy)
    write_page(sizes, default, direct, accuracy, reference_energy, variants, time.time() - started)


def write_plots(sizes, default, direct, accuracy, reference_energy):
    fig, (left, right) = plt.subplots(1, 2, figsize=(11, 4.2))
    left.plot(sizes, [f(r, "hessian") for r in default], "o-", label="ffeti: Hessian multiplications")
    left.plot(sizes, [f(r, "cg") for r in default], "s--", label="ffeti: CG steps")
    left.plot([64, 512], [27, 54], "k^", label="seed: CG iterations (smallest, largest)")
    left.axhline(65, color="gray", lw=0.8, ls=":", label="seed: most CG iterations (65)")
    left.set_xscale("log", base=2)
    left.set_xlabel("n (h = 1/n), H/h = 64")
    left.set_ylabel("count")
    left.set_title("Numerical scalability")
    left.legend(fontsize=8)
    solve_time = [f(r, "time_factor") + f(r, "time_solve") + f(r, "time_recovery") for r in default]
    right.loglog(sizes, solve_time, "o-", label="ffeti: factorization + dual solve + recovery")
    right.loglog(sizes, [f(r, "time_assembly") for r in default], "s--", label="FreeFEM assembly of the subdomain data")
    right.loglog(sizes, [f(r, "time_last_solve") for r in direct], "d-.", label="UMFPACK, final contact set fixed")
    right.loglog(sizes, [f(r, "time_pdas") for r in direct], "x:", label="primal-dual active set + UMFPACK")
    right.set_xscale("log", base=2)
    right.set_xlabel("n (h = 1/n)")
    right.set_ylabel("seconds")
    right.set_title("Time on this machine")
    right.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(OUT, "model-problem-scaling.png"), dpi=110)
    plt.close(fig)

    fig, ax = plt.subplots(figsize=(6, 4.2))
    for n, rows in accuracy.items():
        errors = [max(abs(f(r, "energy") - reference_energy[n]) / abs(reference_energy[n]), 1e-16) for r in rows]
        times = [f(r, "time_solve") for r in rows]
        ax.loglog(times, errors, "o-", label=f"n = {n}")
        for r, t, e in zip(rows, times, errors):
            ax.annotate(f"{float(r['tol']):.0e}", (t, e), fontsize=7, xytext=(3, 3), textcoords="offset points")
    ax.set_xlabel("dual solve time [s]")
    ax.set_ylabel("relative energy error")
    ax.set_title("What accuracy costs (labels: tol)")
    ax.legend()
    fig.tight_layout()
    fig.savefig(os.path.join(OUT, "model-problem-accuracy.png"), dpi=110)
    plt.close(fig)


def write_page(sizes, default, direct, accuracy, reference_energy, variants, elapsed):
    seed_primal = {64: 8450, 512: 540800}
    lines = [
        "# The seed's model problem: reproduced",
        "",
        "Generated by `scripts/benchmark-model-problem.sh` (do not edit by hand) on:",
        f"{machine()}. Whole run: {elapsed:.0f} s. Every number below comes from that one run.",
        "",
        "Problem: the two membranes of the seed paper (`edp/model-problem.edp`), P1 on regular",
        "grids, h = 1/n, H/h = 64, FETI-1 (Dirichlet eliminated inside K_s, as the seed),",
        "SMALBE-M with MPRGP inside, the seed's relative stopping test with tol = 1e-4, no options",
        "passed. Times are wall-clock seconds; `hessian` counts every application of the dual",
        "operator inside the solve (the 15 of the norm estimate are reported apart).",
        "",
        "## Numerical scalability, beside the seed's figures",
        "",
        "| n | subdomains | primal (seed) | dual (seed) | couples (seed) | active (seed) | outer | Hessian mult. | CG steps | seed CG iterations |",
        "|---|---|---|---|---|---|---|---|---|---|",
    ]
    for r in default:
        n = int(r["n"])
        seed_cg = {64: "27", 512: "54"}.get(n, "27..65")
        lines.append(
            f"| {n} | {r['subdomains']} | {r['primal']} ({seed_primal.get(n, '-')}) | {r['dual']} "
            f"({'14975' if n == 512 else '-'}) | {r['couples']} ({'520' if n == 512 else '-'}) | "
            f"{r['active']} ({'~350' if n == 512 else '-'}) | {r['outer']} | {r['hessian']} | {r['cg']} | {seed_cg} |")
    lines += [
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
        "| n | unknowns (unsplit) | assembly | setup | solve | recovery | ffeti total (setup+solve+recovery) | UMFPACK floor | ratio to floor | PDAS (iterations) | energy ffeti | energy PDAS |",
        "|---|---|---|---|---|---|---|---|---|---|---|---|",
    ]
    for r, d in zip(default, direct):
        total = f(r, "time_factor") + f(r, "time_solve") + f(r, "time_recovery")
        lines.append(
            f"| {r['n']} | {d['unknowns']} | {f(r, 'time_assembly'):.3f} | {f(r, 'time_factor'):.3f} | "
            f"{f(r, 'time_solve'):.3f} | {f(r, 'time_recovery'):.3f} | {total:.3f} | {f(d, 'time_last_solve'):.3f} | "
            f"{total / f(d, 'time_last_solve'):.2f} | {f(d, 'time_pdas'):.2f} ({d['pdas_iterations']}) | "
            f"{f(r, 'energy'):.8f} | {f(d, 'energy'):.8f} |")
    lines += [
        "",
        "## What accuracy costs",
        "",
        "Relative energy error against a solve at tol = 1e-10 of the same discrete problem.",
        "",
        "| n | tol | outer | Hessian mult. | solve [s] | relative energy error | KKT equilibrium | KKT non-penetration |",
        "|---|---|---|---|---|---|---|---|",
    ]
    for n, rows in accuracy.items():
        for r in rows:
            error = abs(f(r, "energy") - reference_energy[n]) / abs(reference_energy[n])
            lines.append(
                f"| {n} | {r['tol']} | {r['outer']} | {r['hessian']} | {f(r, 'time_solve'):.3f} | {error:.1e} | "
                f"{f(r, 'kkt_equilibrium'):.1e} | {f(r, 'kkt_inequality'):.1e} |")
    lines += [
        "",
        "![accuracy](model-problem-accuracy.png)",
        "",
        f"## Variants at n = {sizes[-1]}",
        "",
        "| variant | dual | outer | Hessian mult. | setup [s] | solve [s] | energy | status |",
        "|---|---|---|---|---|---|---|---|",
    ]
    for name, r in variants:
        lines.append(
            f"| {name} | {r['dual']} | {r['outer']} | {r['hessian']} | {f(r, 'time_factor'):.3f} | "
            f"{f(r, 'time_solve'):.3f} | {f(r, 'energy'):.8f} | {r['status']} |")
    lines.append("")
    lines.append(open(os.path.join(ROOT, "docs", "results", "model-problem-reading.md")).read())
    with open(os.path.join(OUT, "model-problem.md"), "w") as page:
        page.write("\n".join(lines))


if __name__ == "__main__":
    main()
