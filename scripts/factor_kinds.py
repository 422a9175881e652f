#!/usr/bin/env python3
"""CHOLMOD's simplicial against supernodal factors of subdomain-like matrices (P1 patterns on
2D and 3D grids, scalar and elasticity; build/tests/factor_kinds_probe) under each BLAS this
machine has (the reference BLAS of the alternatives system, and Debian's OpenBLAS builds
loaded for the probe alone through LD_LIBRARY_PATH: the system is not changed), on one and
two threads, and optionally beside a busy process. Prints the CSV and, per BLAS, the flops
per factor nonzero at which supernodal starts to win: the measurements behind
CholmodFactor's supernodal_switch (plugin/core/factor/cholmod_factor.cpp).
  scripts/factor_kinds.py [--build build] [--threads 1 2] [--busy] [--csv out.csv] [--quick]"""
import argparse
import csv
import io
import os
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
LIBDIR = "/usr/lib/x86_64-linux-gnu"
# (dimension, components per node, cells per side): subdomains of a few hundred to ~15,000
# dofs, the sizes FETI scenes use (H/h = 8 to 64 in 2D, 4 to 16 in 3D).
CASES = [(2, 1, c) for c in (32, 64, 128)] + [(2, 2, c) for c in (32, 64, 128)] + \
        [(3, 1, c) for c in (8, 12, 16, 24)] + [(3, 3, c) for c in (4, 6, 8, 12, 16)]
QUICK = [(2, 1, 64), (2, 2, 64), (3, 1, 16), (3, 3, 8), (3, 3, 16)]


def blas_variants():
    """The reference (system) BLAS, then each OpenBLAS build installed beside it."""
    variants = [("reference", None)]
    for name in ("openblas-openmp", "openblas-pthread", "openblas-serial"):
        folder = os.path.join(LIBDIR, name)
        if os.path.exists(os.path.join(folder, "libblas.so.3")):
            variants.append((name, folder))
    return variants


def probe(binary, case, threads, library, repeat):
    env = dict(os.environ)
    if library:
        env["LD_LIBRARY_PATH"] = library
    out = subprocess.run([binary, *map(str, case), str(threads), str(repeat)], env=env, check=True,
                         capture_output=True, text=True).stdout
    return list(csv.DictReader(io.StringIO(out)))


def crossover(rows):
    """Per BLAS and thread count: the largest flops/nnz(L) where simplicial factored faster
    and the smallest where supernodal did (numeric factorization on one thread)."""
    lines = []
    keys = sorted({(r["blas"], r["threads"], r["busy"]) for r in rows})
    for blas, threads, busy in keys:
        kinds = {}
        for r in rows:
            if (r["blas"], r["threads"], r["busy"]) == (blas, threads, busy):
                kinds.setdefault((r["dim"], r["components"], r["cells"]), {})[r["kind"]] = r
        simplicial_wins, supernodal_wins = [], []
        for case, k in sorted(kinds.items(), key=lambda kv: float(next(iter(kv[1].values()))["flops_per_nnz_L"])):
            ratio = float(k["simplicial"]["factor_s"]) / float(k["supernodal"]["factor_s"])
            both = float(k["simplicial"]["concurrent_round_s"]) / float(k["supernodal"]["concurrent_round_s"])
            density = float(k["simplicial"]["flops_per_nnz_L"])
            (supernodal_wins if ratio > 1 else simplicial_wins).append(density)
            lines.append(f"{blas:16s} threads={threads} busy={busy} dim={case[0]} comp={case[1]} cells={case[2]:>3s} "
                         f"dofs={k['simplicial']['dofs']:>6s} flops/nnzL={density:7.1f} "
                         f"simplicial/supernodal factor {ratio:5.2f} (concurrent {both:5.2f}) "
                         f"solve {float(k['simplicial']['solve_s']) / float(k['supernodal']['solve_s']):5.2f} "
                         f"auto={'supernodal' if k['automatic']['supernodal'] == '1' else 'simplicial'}")
        lines.append(f"{blas:16s} threads={threads} busy={busy}: simplicial faster up to flops/nnzL "
                     f"{max(simplicial_wins, default=0):.1f}, supernodal faster from "
                     f"{min(supernodal_wins, default=float('inf')):.1f}")
    return lines


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--build", default=os.path.join(ROOT, "build"))
    parser.add_argument("--threads", type=int, nargs="+", default=[1, 2])
    parser.add_argument("--busy", action="store_true", help="also beside one busy process (a spinning python loop)")
    parser.add_argument("--quick", action="store_true", help="five cases instead of sixteen")
    parser.add_argument("--repeat", type=int, default=3)
    parser.add_argument("--csv", help="write the rows here too")
    args = parser.parse_args()
    binary = os.path.join(args.build, "tests", "factor_kinds_probe")
    rows = []
    for busy in ([False, True] if args.busy else [False]):
        spinner = subprocess.Popen([sys.executable, "-c", "while True: pass"]) if busy else None
        try:
            for case in (QUICK if args.quick else CASES):
                for blas, library in blas_variants():  # interleaved: the machine's load hits all alike
                    for threads in args.threads:
                        for r in probe(binary, case, threads, library, args.repeat):
                            r["busy"] = int(busy)
                            rows.append(r)
                            print(",".join(map(str, r.values())), flush=True)
        finally:
            if spinner:
                spinner.kill()
    if args.csv:
        with open(args.csv, "w", newline="") as out:
            writer = csv.DictWriter(out, fieldnames=list(rows[0]))
            writer.writeheader()
            writer.writerows(rows)
    print("\n".join(crossover(rows)))


if __name__ == "__main__":
    main()
