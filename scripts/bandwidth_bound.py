#!/usr/bin/env python3
"""The dual operator against the memory-bandwidth bound: one part of the model-problem page
(scripts/model_problem_benchmark.py; alone: scripts/benchmark.sh model-problem --only
bandwidth). Each Hessian multiplication applies F = B K^+ B' once: per subdomain a forward and
a backward triangular solve with its CHOLMOD factor, which reads every factor at least once
(twice, L then L', where a factor does not stay in cache). So no multiplication can take less
than (bytes of all factors) / (memory bandwidth). This part measures the bandwidth with
build/tests/stream_triad (STREAM's triad, arrays far larger than the caches, best of several
runs) and runs the 2D model problem (edp/model-problem.edp) and the 3D elasticity cubes
(edp/cubes-elasticity-3d.edp), both on one thread (like the bandwidth), for their factor bytes
and their times per multiplication: the whole Hessian multiplication (F with the coarse
projections), F alone, and the triangular solves inside F.
  scripts/bandwidth_bound.py [--render]   measure (CSV into FFETI_RESULTS or docs/results) and
                                          print the page's section in Markdown
FFETI_BANDWIDTH_2D / FFETI_BANDWIDTH_3D: the sizes n (default "256 512 1024" and "16 32");
FFETI_BUILD: the build tree holding tests/stream_triad (default build/)."""
import argparse
import csv
import glob
import io
import os
import subprocess

from ffeti_bench import ROOT, begin_run, end_run, f, machine_line, markdown_table, read_csv, run, write_csv
from factor_kinds import blas_variants
from three_dimensions_elasticity import blas_library

PAGE = "model-problem"
SIZES_2D = [int(n) for n in os.environ.get("FFETI_BANDWIDTH_2D", "256 512 1024").split()]
SIZES_3D = [int(n) for n in os.environ.get("FFETI_BANDWIDTH_3D", "16 32").split()]
BUILD = os.environ.get("FFETI_BUILD", os.path.join(ROOT, "build"))
ARRAY_MB, STREAM_RUNS = 256, 10  # three arrays of 256 MB: 24 times the 32 MiB L3 here
# One subdomain of each scene as build/tests/factor_kinds_probe builds it (dimension,
# components, cells per side): the model problem's H/h = 64 squares, the cubes' 8^3 boxes.
SUBDOMAINS = {"2D model problem": (2, 1, 64), "3D elasticity cubes": (3, 3, 8)}


def cache_sizes():
    """{level: bytes} of cpu0's data and unified caches (/sys/devices/system/cpu)."""
    sizes = {}
    for folder in glob.glob("/sys/devices/system/cpu/cpu0/cache/index*"):
        with open(os.path.join(folder, "type")) as kind, open(os.path.join(folder, "level")) as level, \
                open(os.path.join(folder, "size")) as size:
            if kind.read().strip() in ("Data", "Unified"):
                text = size.read().strip()
                scale = {"K": 2**10, "M": 2**20}.get(text[-1], 1)
                sizes[int(level.read())] = int(text.rstrip("KM")) * scale
    return sizes


def bandwidth():
    """One row: stream_triad's best triad and read-only bandwidths on one thread, the caches."""
    binary = os.path.join(BUILD, "tests", "stream_triad")
    if not os.path.exists(binary):
        raise SystemExit(f"bandwidth_bound.py: {binary} is missing: build it (cmake --build build --target stream_triad)")
    out = subprocess.run([binary, str(ARRAY_MB), str(STREAM_RUNS), "1"], check=True, capture_output=True,
                         text=True).stdout.splitlines()
    row = dict(zip(out[0].split(","), out[1].split(",")))
    caches = cache_sizes()
    row.update(l2_bytes=caches.get(2, ""), l3_bytes=caches.get(3, ""), blas=blas_library())
    return row


def cache_hot_solves():
    """Per scene, one subdomain-like factor of each kind solved right after its factorization
    (its factor in cache; best of 10, one thread): the triangular solves' speed without memory,
    under the system's BLAS (system_blas 1: the scenes') and each OpenBLAS build installed."""
    binary = os.path.join(BUILD, "tests", "factor_kinds_probe")
    rows = []
    for _, library in blas_variants():
        env = dict(os.environ, **({"LD_LIBRARY_PATH": library} if library else {}))
        for problem, case in SUBDOMAINS.items():
            out = subprocess.run([binary, *map(str, case), "1", "10"], env=env, check=True, capture_output=True,
                                 text=True).stdout
            rows += [dict(problem=problem, system_blas=0 if library else 1, **r) for r in csv.DictReader(io.StringIO(out))]
    return rows


def per_multiplication(row, triad_gb_s):
    """The scene's result row with its times per multiplication and its bound (seconds)."""
    applications = f(row, "dual_operator_applications")
    row["t_hessian"] = f(row, "time_hessian") / f(row, "hessian")
    row["t_operator"] = f(row, "time_dual_operator") / applications
    row["t_solves"] = f(row, "time_factor_solves") / applications
    row["t_bound"] = f(row, "operator_bytes") / (triad_gb_s * 1e9)
    return row


def measure():
    begun = begin_run()
    stream = write_csv(PAGE, "bandwidth", [bandwidth()])[0]
    write_csv(PAGE, "bandwidth-in-cache", cache_hot_solves())
    triad = f(stream, "triad_gb_s")
    rows = []
    for n in SIZES_2D:
        result = run("model-problem.edp", "-n", n, "-threads", 1, "-shareFactors", "off")["RESULT"][0]
        rows.append(per_multiplication(dict(problem="2D model problem", **result), triad))
    for n in SIZES_3D:
        result = run("cubes-elasticity-3d.edp", "-n", n, "-threads", 1, "-shareFactors", "off")["RESULT"][0]
        result["primal"] = result["unknowns"]
        rows.append(per_multiplication(dict(problem="3D elasticity cubes", **result), triad))
    write_csv(PAGE, "bandwidth-bound", rows)
    end_run(PAGE, begun, table="bandwidth-run")


def cache_note(row, stream):
    """Where the factors stand against the caches: all of them within L3 beat the DRAM bound."""
    total, each = f(row, "operator_bytes"), f(row, "operator_bytes") / f(row, "factorizations")
    if stream["l3_bytes"] and total <= float(stream["l3_bytes"]):
        return "all in L3"
    if stream["l2_bytes"] and each <= float(stream["l2_bytes"]):
        return "each in L2"
    return "each in L3" if stream["l3_bytes"] and each <= float(stream["l3_bytes"]) else "none"


def cache_hot(row, hot):
    """The probe's cache-hot solve of the kind the scene's factors have (all of one kind)."""
    kind = "supernodal" if row["supernodal_factors"] == row["subdomains"] else "simplicial"
    return next((r for r in hot if r["problem"] == row["problem"] and r["kind"] == kind and r["system_blas"] == "1"), None)


def ms(key):
    """A table cell: the row's seconds under `key` in milliseconds."""
    return lambda r: f"{1e3 * f(r, key):.2f}"


def over_bound(key):
    """A table cell: the row's seconds under `key` over its bandwidth bound."""
    return lambda r: f"{f(r, key) / f(r, 't_bound'):.2f}"


def section():
    """The page's section, rendered from the part's CSVs."""
    stream = read_csv(PAGE, "bandwidth")[0]
    rows = read_csv(PAGE, "bandwidth-bound")
    hot = [r for r in read_csv(PAGE, "bandwidth-in-cache") if r["kind"] != "automatic"]
    run_row = read_csv(PAGE, "bandwidth-run")[0]
    mib = 2**20
    caches = (f"L2 {float(stream['l2_bytes']) / mib:.0f} MiB per core, L3 {float(stream['l3_bytes']) / mib:.0f} MiB shared"
              if stream["l2_bytes"] and stream["l3_bytes"] else "cache sizes unknown")

    def hot_ms(r):  # the scene's subdomains times one cache-hot solve of its kind
        if r.get("interface_factors", "0") not in ("", "0"):
            return "-"  # the probe solves on the whole factor, these solves on the interface
        h = cache_hot(r, hot)
        return f"{1e3 * f(r, 'subdomains') * f(h, 'solve_s'):.2f}" if h else "-"

    return [
        "## The dual operator against the memory bandwidth",
        "",
        f"Measured apart from the tables above: {machine_line(run_row)}",
        "",
        "A Hessian multiplication applies F = B K^+ B' once: per subdomain a forward and a backward",
        "triangular solve with its CHOLMOD factor. Each reads the part of the factor it needs: the whole",
        "factor, or where the factor ordered the subdomain's interface last (`ordering`, the 2D subdomains",
        "by default) the interface block alone; where the subdomain holds an explicit block instead",
        "(`dualOperator`, whose default `auto` takes one where it reads no more than the interface",
        "block's solves: the 2D subdomains; [dual operator](dual-operator.md)), the solves are one",
        "product with that dense block of K_s^+, and its bytes are what a pass reads",
        "(`operator_bytes` counts the block). No multiplication takes less than the bound = (bytes the",
        "solves read) / (memory bandwidth) once those bytes together outgrow the caches (L' after L may",
        "come from cache where one subdomain's part fits: one pass is the bound; two passes from memory",
        "would double it). Bytes: values (8 bytes) and the integer indices locating them (4 bytes per",
        "entry of a simplicial factor and per row of a supernode): `fetiInfo(P, \"operator_bytes\")`, of",
        "the whole factors' `factor_bytes`. Bandwidth: `tests/stream_triad.cpp`, STREAM's triad",
        f"a = b + s c on three arrays of {float(stream['array_mb']):.0f} MB, best of {stream['runs']} runs, one thread:",
        f"**{f(stream, 'triad_gb_s'):.2f} GB/s** (24 bytes per element; a read-only sum reached",
        f"{f(stream, 'read_gb_s'):.2f} GB/s). Caches: {caches}. BLAS (supernodal solves): {stream['blas']}.",
        "Both scenes run on one thread (`-threads 1`) and with `-shareFactors off` (every subdomain its own factor,",
        "as in a scene of distinct subdomains: identical boxes sharing one factor would keep it in cache), their",
        "other options the defaults. Per multiplication:",
        "`Hessian` the solver's whole multiplication (`time_hessian / hessian`: F and the coarse",
        "projections around it), `F` the dual operator (`time_dual_operator / dual_operator_applications`:",
        "gathers, B_s', the solves, B_s and the sum), `solves` the triangular solves inside F",
        "(`time_factor_solves / dual_operator_applications`, with the copies between a subdomain's dofs",
        "and its factor's). `in cache`: where the factors fit (all of them in L3: the DRAM bound does not",
        "hold; each in L2 or L3: L' after L from cache). `cache-hot solves`: the subdomains times one",
        "solve with a factor of the same kind and shape right after its factorization, the factor still in",
        "cache (`tests/factor_kinds_probe`, table below): what the solves cost without waiting for memory",
        "(whole-factor solves: `-` where the scene's subdomains solve on their interface).",
        f"Raw data: [{PAGE}-bandwidth-bound.csv]({PAGE}-bandwidth-bound.csv),",
        f"[{PAGE}-bandwidth.csv]({PAGE}-bandwidth.csv), [{PAGE}-bandwidth-in-cache.csv]({PAGE}-bandwidth-in-cache.csv).",
        "",
        *markdown_table(rows, [
            ("problem", "problem"), ("n", "n"), ("subdomains", "subdomains"), ("unknowns", "primal"),
            ("supernodal", lambda r: f"{r['supernodal_factors']} of {r['subdomains']}"),
            ("interface solves", lambda r: f"{r['interface_factors']} of {r['subdomains']}"),
            ("factor MB", lambda r: f"{f(r, 'factor_bytes') / 1e6:.1f}"),
            ("read per pass MB", lambda r: f"{f(r, 'operator_bytes') / 1e6:.1f}"),
            ("per factor MB", lambda r: f"{f(r, 'operator_bytes') / f(r, 'factorizations') / 1e6:.2f}"),
            ("in cache", lambda r: cache_note(r, stream)),
            ("Hessian mult.", "hessian"), ("F applied", "dual_operator_applications"),
            ("Hessian [ms]", ms("t_hessian")), ("F [ms]", ms("t_operator")), ("solves [ms]", ms("t_solves")),
            ("cache-hot solves [ms]", hot_ms), ("bound [ms]", ms("t_bound")),
            ("solves / bound", over_bound("t_solves")), ("F / bound", over_bound("t_operator")),
            ("Hessian / bound", over_bound("t_hessian")),
            ("factor read by the solves [GB/s]", lambda r: f"{f(r, 'operator_bytes') / f(r, 't_solves') / 1e9:.2f}")]),
        "",
        "One subdomain's factor solved in cache, by kind and BLAS (`tests/factor_kinds_probe DIM COMPONENTS",
        "CELLS`, the scenes' subdomain shapes: the model problem's 64 x 64 squares, the cubes' 8^3 boxes of",
        "elasticity; one pass over the factor per solve counted; the scenes ran under the system's BLAS,",
        "the OpenBLAS builds installed beside it loaded for the probe alone, as `scripts/factor_kinds.py` does):",
        "",
        *markdown_table(hot, [
            ("problem", "problem"), ("dofs", "dofs"), ("kind", "kind"),
            ("BLAS", lambda r: r["blas"] + (" (the scenes')" if r["system_blas"] == "1" else "")),
            ("factor MB", lambda r: f"{f(r, 'factor_bytes') / 1e6:.2f}"),
            ("solve [ms]", lambda r: f"{1e3 * f(r, 'solve_s'):.3f}"),
            ("factor read [GB/s]", lambda r: f"{f(r, 'factor_bytes') / f(r, 'solve_s') / 1e9:.2f}"),
            ("factorization [ms]", lambda r: f"{1e3 * f(r, 'factor_s'):.2f}")]),
        "",
    ]


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--render", action="store_true", help="print the section from the CSVs, no run")
    if not parser.parse_args().render:
        measure()
    print("\n".join(section()))


if __name__ == "__main__":
    main()
