#!/usr/bin/env python3
"""Real meshes at scale: docs/results/real-meshes.md from edp/crowned-punch-3d.edp (a crowned
punch on an elastic base, each body meshed by gmsh on its own, METIS parts, node to face on
non-matching meshes, Total FETI with default options).

Four runs, each a CSV under docs/results/ and a table of the page (the weak one also a table
of the kinds of MPRGP's steps):
- weak: mesh sizes -h from FFETI_REAL_SIZES (default 0.7 0.5 0.35 0.25 0.2 0.155, the page's run) at parts of
  FFETI_REAL_PART_NODES nodes (default 250: the part-size table's fewest multiplications, and at
  -h 0.155 a tenth less memory for the same mesh than parts of 1000 nodes), one after the other,
  each under FFETI_REAL_TIME_LIMIT_S (default 2400 s) and FFETI_REAL_MEMORY_LIMIT_GIB (default
  23 GiB of address space); the first size that reaches a limit ends the table with a row
  saying which limit and when (a larger size would not fit either);
- parts: the part size -partNodes 250 ... 2000 at -h 0.5 (counts, memory, times);
- peer: FETI against the direct peer (-peer 1: the primal-dual active set method on the
  undivided bodies, MUMPS) at the sizes FFETI_REAL_PEER_SIZES (default 0.7 0.5);
- undivided: each body one subdomain (no METIS cut) at FFETI_REAL_UNDIVIDED_SIZES (default
  0.7 0.5 0.35): the multiplications the contact alone takes, against the weak table's;
- scaling: the preconditioner's weights, multiplicity (the default) against stiffness
  (fetiSetup's scaling=), at FFETI_REAL_SCALING_SIZES (default 0.7 0.5 0.35 0.25 0.2 0.155), parts as weak;
- preconditioner: lumped (the default) against Dirichlet (fetiSetup's preconditioner=), at
  FFETI_REAL_PRECONDITIONER_SIZES (default 0.7 0.5 0.35 0.25 0.2), parts as weak.
Times are wall clock on the machine as it was (its load is in the run's row); counts
(Hessian multiplications, outer iterations) and bytes do not depend on the machine.
Usage: scripts/real_meshes_benchmark.py [--render | --only undivided | --only scaling |
--only preconditioner] (--render: the page from the CSVs alone; --only PART: that table alone,
with its own run row).
FFETI_RUN_DIR=build/edp-tests runs the build's plugin."""
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402  (after the backend)

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from ffeti_bench import (OUT, OverLimit, begin_run, csv_path, end_run, f, forget_run, machine_line,  # noqa: E402
                         markdown_table, measure_and_render, read_csv, run, save_page, write_csv)

PAGE = "real-meshes"
SIZES = [float(h) for h in os.environ.get("FFETI_REAL_SIZES", "0.7 0.5 0.35 0.25 0.2 0.155").split()]
PART_NODES = int(os.environ.get("FFETI_REAL_PART_NODES", "250"))
PART_SWEEP = [250, 500, 1000, 2000]
PART_SWEEP_H = 0.5
PEER_SIZES = [float(h) for h in os.environ.get("FFETI_REAL_PEER_SIZES", "0.7 0.5").split()]
UNDIVIDED_SIZES = [float(h) for h in os.environ.get("FFETI_REAL_UNDIVIDED_SIZES", "0.7 0.5 0.35").split()]
# Tables of one fetiSetup option, its default first, side by side at each size (parts as weak):
# name -> the scene's flag, the values, the sizes.
SIDE_BY_SIDE = {
    "scaling": ("-scaling", ["multiplicity", "stiffness"],
                [float(h) for h in os.environ.get("FFETI_REAL_SCALING_SIZES", "0.7 0.5 0.35 0.25 0.2 0.155").split()]),
    "preconditioner": ("-preconditioner", ["lumped", "dirichlet"],
                       [float(h) for h in os.environ.get("FFETI_REAL_PRECONDITIONER_SIZES",
                                                         "0.7 0.5 0.35 0.25 0.2").split()]),
}
ONE_PART_PER_BODY = 10 ** 9  # -partNodes above any body's node count: ffetiMetis3 makes one part
TIME_LIMIT_S = float(os.environ.get("FFETI_REAL_TIME_LIMIT_S", "2400"))
MEMORY_LIMIT_MB = 1024 * float(os.environ.get("FFETI_REAL_MEMORY_LIMIT_GIB", "23"))
SCENE = "crowned-punch-3d.edp"


def scene(h, part_nodes, *flags, limited=False):
    """One run of the scene: its RESULT line (with the process's peak memory)."""
    limits = dict(seconds=TIME_LIMIT_S, memory_mb=MEMORY_LIMIT_MB) if limited else {}
    row = run(SCENE, "-h", h, "-partNodes", part_nodes, *flags, **limits)["RESULT"][0]
    print(f"h={h} partNodes={part_nodes} {' '.join(map(str, flags))}: {row['unknowns']} unknowns, "
          f"{row['hessian']} multiplications, {float(row['time_scene']):.1f} s, {row['status']}", flush=True)
    return row


def measure():
    begun = begin_run()
    weak = []
    for h in SIZES:
        try:
            weak.append(scene(h, PART_NODES, limited=True))
        except OverLimit as stop:
            weak.append({"h": h, "status": "stopped", "limit": stop.what, "seconds": repr(stop.seconds)})
            print(f"h={h}: {stop}", flush=True)
            break
    write_csv(PAGE, "weak", weak)
    write_csv(PAGE, "parts", [scene(PART_SWEEP_H, nodes) for nodes in PART_SWEEP])
    write_csv(PAGE, "peer", [scene(h, PART_NODES, "-peer", 1, "-DwithMUMPS=1") for h in PEER_SIZES])
    measure_undivided_table()
    for name in SIDE_BY_SIDE:
        measure_side_by_side_table(name)
    for table in ["undivided-run"] + [f"{name}-run" for name in SIDE_BY_SIDE]:
        forget_run(PAGE, table)  # the table is this run's now
    end_run(PAGE, begun)


def measure_undivided_table():
    write_csv(PAGE, "undivided", [scene(h, ONE_PART_PER_BODY) for h in UNDIVIDED_SIZES])


def measure_undivided():
    """The undivided table alone (--only undivided), with its own run row."""
    begun = begin_run()
    measure_undivided_table()
    end_run(PAGE, begun, table="undivided-run")


def measure_side_by_side_table(name):
    flag, values, sizes = SIDE_BY_SIDE[name]
    write_csv(PAGE, name, [scene(h, PART_NODES, flag, value) for h in sizes for value in values])


def measure_side_by_side(name):
    """One side-by-side table alone (--only NAME), with its own run row."""
    def measure_alone():
        begun = begin_run()
        measure_side_by_side_table(name)
        end_run(PAGE, begun, table=f"{name}-run")
    return measure_alone


MEMORY_PHASES = [("meshes read", "mb_meshes"), ("parts cut", "mb_parts"), ("assembled", "mb_assembly"),
                 ("set up", "mb_setup"), ("solved", "mb_solve")]


def mib_as_kib_per_unknown(row, key, per="unknowns"):
    """The MiB in `key` as KiB per unknown: per the parts' unknowns (interface nodes once per
    part) or, with per="body_unknowns", per the undivided bodies' unknowns."""
    return f(row, key) * 1024 / f(row, per)


def per_unknown_kib(key):
    """A table cell: the resident MiB in `key` as KiB per unknown."""
    return lambda r: f"{mib_as_kib_per_unknown(r, key):.2f}"


def reported_kib(key):
    """A table cell: the bytes per unknown the plugin reports in `key` as KiB, "-" where the run
    did not report it."""
    return lambda r: f"{kib(r, key):.2f}" if r.get(key) else "-"


def nearest(rows, unknowns):
    """The row whose size is closest to `unknowns` (by ratio)."""
    return min(rows, key=lambda r: abs(math.log(f(r, "unknowns") / unknowns)))


def nearest_boxes(unknowns):
    """The 3D boxes' weak-scaling row (three-dimensions.md) closest in size."""
    return nearest(read_csv("three-dimensions", "elasticity-weak"), unknowns)


def peak_kib(row, per="unknowns"):
    """The process's peak resident set in KiB per unknown (mib_as_kib_per_unknown's `per`)."""
    return mib_as_kib_per_unknown(row, "process_peak_mb", per)


def body_peak_kib(row):
    """A table cell: peak KiB per unknown of the undivided bodies, "-" where the run did not report them."""
    return f"{peak_kib(row, 'body_unknowns'):.2f}" if row.get("body_unknowns") else "-"


def per_unknown_us(row, key):
    return 1e6 * f(row, key) / f(row, "unknowns")


def gbytes_per_second(row):
    """The bytes one multiplication reads (the factors, once) over its measured time."""
    return f(row, "operator_bytes") * f(row, "hessian") / f(row, "time_hessian") / 1e9


PHASES = [("gmsh", "time_gmsh"), ("METIS + cut", "time_metis"), ("assembly", "time_assembly"),
          ("plugin set-up", "time_plugin_setup"), ("factorization", "time_factor"), ("dual solve", "time_solve")]


def whole(row):
    return sum(f(row, key) for _, key in PHASES) + f(row, "time_recovery")


def plot(weak):
    done = [r for r in weak if r["status"] != "stopped"]
    unknowns = [f(r, "unknowns") for r in done]
    fig, axes = plt.subplots(1, 3, figsize=(15, 4.6))
    for label, key in PHASES:
        axes[0].semilogx(unknowns, [per_unknown_us(r, key) for r in done], "o-", label=label)
    axes[0].semilogx(unknowns, [1e6 * whole(r) / f(r, "unknowns") for r in done], "k^-", label="whole run")
    axes[0].set_ylabel("seconds per unknown [µs]")
    axes[0].set_ylim(0, 1.45 * max(1e6 * whole(r) / f(r, "unknowns") for r in done))  # room for the legend
    axes[0].legend(fontsize=7, ncol=3, loc="upper center")
    axes[1].semilogx(unknowns, [f(r, "hessian") for r in done], "o-", label="Hessian multiplications")
    axes[1].semilogx(unknowns, [f(r, "outer") for r in done], "s--", label="outer iterations")
    axes[1].set_ylim(bottom=0)
    axes[1].set_ylabel("count")
    axes[1].legend(fontsize=8)
    axes[2].semilogx(unknowns, [f(r, "bytes_factor_per_unknown") / 1024 for r in done], "o-", label="factors")
    axes[2].semilogx(unknowns, [peak_kib(r) for r in done], "s--",
                     label="whole process (peak)")
    if all(r.get("body_unknowns") for r in done):
        axes[2].semilogx(unknowns, [peak_kib(r, "body_unknowns") for r in done], "d:",
                         label="whole process (peak), per unknown of the undivided bodies")
    axes[2].set_ylim(bottom=0)
    axes[2].set_ylabel("memory per unknown [KiB]")
    axes[2].legend(fontsize=8)
    for ax in axes:
        ax.set_xlabel("unknowns (of the parts: interface nodes once per part)")
        ax.grid(True, which="both", alpha=0.3)
    fig.suptitle(f"crowned punch on a base, METIS parts of {PART_NODES} nodes, Total FETI with defaults")
    fig.tight_layout()
    fig.savefig(os.path.join(OUT, f"{PAGE}.png"), dpi=110)
    plt.close(fig)


def kib(row, key):
    return f(row, key) / 1024


def counts_without_cuts(done):
    """The aims' reading of the undivided table: the contact problem's own growth."""
    undivided = read_csv(PAGE, "undivided")
    cut = {r["h"]: r for r in done}
    low, high = undivided[0], undivided[-1]
    text = (f"Without the cuts (each body one subdomain, 'Counts without the cuts' below) the contact problem alone "
            f"took {low['hessian']} at -h {low['h']} and {high['hessian']} at -h {high['h']} "
            f"({f(high, 'hessian') / f(low, 'hessian'):.2f} times)")
    if low["h"] in cut and high["h"] in cut:
        text += f"; the parts {cut[low['h']]['hessian']} and {cut[high['h']]['hessian']} at the same sizes"
    return text + "."


def expansions_without_cuts():
    """The aims' reading of the undivided table: the expansions grow with the contact zone's nodes
    with no cut at all, while the conjugate gradient steps stay."""
    undivided = read_csv(PAGE, "undivided")
    low, high = undivided[0], undivided[-1]
    return (f"without any cut the expansions went from {low['expansion']} to {high['expansion']} "
            f"(-h {low['h']} to {high['h']}, active rows {low['active']} to {high['active']}) and the conjugate "
            f"gradient steps from {low['cg']} to {high['cg']}: the count follows the contact nodes the active set "
            "is found among, which a fixed part size does not hold fixed;")


def first_and_last(rows, name, value):
    """The rows of a side-by-side table where option `name` has `value`, at its coarsest and its
    finest size (None where fewer than two sizes ran)."""
    mine = sorted((r for r in rows if r[name] == value), key=lambda r: -float(r["h"]))
    return (mine[0], mine[-1]) if len(mine) > 1 else None


def growth_by_option():
    """The aims' reading of the side-by-side tables: each option value's count at its table's
    first and last size."""
    parts = []
    for name, (_, values, __) in SIDE_BY_SIDE.items():
        if not os.path.exists(csv_path(PAGE, name)):
            continue
        rows = read_csv(PAGE, name)
        for value in values[1:]:
            ends = first_and_last(rows, name, value)
            if ends:
                low, high = ends
                parts.append(f"with `{name} = \"{value}\"` {low['hessian']} at -h {low['h']} and {high['hessian']} at "
                             f"-h {high['h']} ({f(high, 'hessian') / f(low, 'hessian'):.2f} times)")
    return ("Other options, side by side with the defaults below: " + "; ".join(parts) + ".") if parts else ""


def contact_against_boxes(done):
    """The aims' reading: the contact problem alone against the boxes' smallest count, and
    what the cuts add at the same sizes."""
    undivided = read_csv(PAGE, "undivided")
    low = undivided[0]
    box = read_csv("three-dimensions", "elasticity-weak")[0]
    cut = {r["h"]: r for r in done}
    ratios = [f(cut[r["h"]], "hessian") / f(r, "hessian") for r in undivided if r["h"] in cut]
    text = (f"The contact problem alone, with no cut, took {low['hessian']} at {f(low, 'unknowns'):,.0f} unknowns, "
            f"{f(low, 'hessian') / f(box, 'hessian'):.1f} times the boxes' whole count at {f(box, 'unknowns'):,.0f} "
            f"({box['hessian']})")
    if ratios:
        text += f"; the METIS cuts multiplied it by {min(ratios):.2f} to {max(ratios):.2f} at the same mesh sizes"
    if f(low, "hessian") > 1.5 * f(box, "hessian"):
        text += (". The aim is missed before any cut: the problem itself (a curved punch held by contact alone, "
                 "non-matching meshes) takes more than 1.5 times the boxes' count")
    return text + "."


def memory_reading(largest, parts):
    """The aims' reading of the memory: the peak per unknown (of the parts and of the undivided
    bodies), what the plugin holds of it, what other part sizes give, what 24 GiB would hold."""
    peak = peak_kib(largest)
    met = lambda kib_per_unknown: "met" if kib_per_unknown <= 2 else "not met"
    text = f"{peak:.2f} KiB per unknown of the divided problem at the peak (aim: at most 2; {met(peak)})"
    if largest.get("body_unknowns"):
        body = peak_kib(largest, "body_unknowns")
        text += (f", {body:.2f} per unknown of the undivided bodies ({met(body)} on that count: the parts hold "
                 f"{f(largest, 'unknowns') / f(largest, 'body_unknowns'):.2f} times the bodies' unknowns, each "
                 "interface node once per part)")
    text += f". The factors alone hold {kib(largest, 'bytes_factor_per_unknown'):.2f} KiB per unknown"
    if largest.get("bytes_input_per_unknown"):
        text += (f", the plugin's copies of K_s, f_s and coordinates {kib(largest, 'bytes_input_per_unknown'):.2f} "
                 f"(K_s as its lower triangle), its constraint rows {kib(largest, 'bytes_constraint_per_unknown'):.2f} "
                 f"and kernels {kib(largest, 'bytes_kernel_per_unknown'):.2f}")
    dual = ["bytes_dual_rows_per_unknown", "bytes_coarse_per_unknown", "bytes_preconditioner_per_unknown"]
    if all(largest.get(key) for key in dual):
        counted = sum(kib(largest, key) for key in ["bytes_factor_per_unknown", "bytes_input_per_unknown",
                                                    "bytes_constraint_per_unknown", "bytes_kernel_per_unknown", *dual])
        text += (f", the dual system's rows, coarse problem and preconditioner "
                 f"{', '.join(f'{kib(largest, key):.2f}' for key in dual)}: the plugin counts {counted:.2f} KiB per "
                 f"unknown of the peak's {peak:.2f}; the rest is the script's part meshes and vectors and the "
                 "solve's work vectors (heaptrack: docs/log.md, 2026-12-07)")
    by_size = sorted(parts, key=lambda r: int(r["part_nodes"]))
    text += (f". At -h {PART_SWEEP_H} ('Part size') parts of {by_size[0]['part_nodes']} to {by_size[-1]['part_nodes']} "
             f"nodes peak at {peak_kib(by_size[0]):.2f} to {peak_kib(by_size[-1]):.2f} KiB per unknown")
    if all(r.get("body_unknowns") for r in by_size):
        text += (f" ({peak_kib(by_size[0], 'body_unknowns'):.2f} to {peak_kib(by_size[-1], 'body_unknowns'):.2f} per "
                 "unknown of the undivided bodies)")
    reach = 24 * 1024 ** 2 / peak  # KiB in 24 GiB over KiB per unknown
    text += f". At the largest run's peak per unknown, 24 GiB would hold about {reach / 1e6:.1f} million unknowns"
    if largest.get("body_unknowns"):
        text += f" of the divided problem, {24 * 1024 ** 2 / peak_kib(largest, 'body_unknowns') / 1e6:.1f} million of the bodies"
    return text + " (extrapolated, not run)."


def undivided_section(weak):
    """Each body one subdomain against the weak table's METIS parts at the same mesh sizes."""
    undivided = read_csv(PAGE, "undivided")
    cut = {r["h"]: r for r in weak if r["status"] != "stopped"}
    lines = ["", "## Counts without the cuts", "",
             "The same scene with each body one subdomain (no METIS cut: the multiplications the contact "
             "problem alone takes) against the weak table's parts of about "
             f"{PART_NODES} nodes at the same mesh size."]
    if os.path.exists(csv_path(PAGE, "undivided-run")):
        lines += ["This table was measured on its own (`--only undivided`): " +
                  machine_line(read_csv(PAGE, "undivided-run")[0])]
    lines += [""]
    lines += markdown_table(undivided, [
        ("h", "h"), ("unknowns", ("unknowns", ",.0f")), ("active", "active"), ("Hessian", "hessian"),
        ("outer", "outer"), ("CG / expansion", lambda r: f"{r['cg']} / {r['expansion']}" if r.get("cg") else "-"),
        ("METIS parts: Hessian", lambda r: cut[r["h"]]["hessian"] if r["h"] in cut else "-"),
        ("parts / undivided",
         lambda r: f"{f(cut[r['h']], 'hessian') / f(r, 'hessian'):.2f}" if r["h"] in cut else "-"),
        ("dual solve [s]", ("time_solve", ".1f"))])
    return lines


def side_by_side_section(name, title, intro, reading):
    """The option `name`'s values side by side at each size, from one run; `reading(ratio_range,
    growth_text, growth, largest)` the text after the table: the range of the other value's
    multiplications over the default's, the growth from the first size to the last (as a
    sentence, and as the default's and the other's ratios), and the two rows of the last size."""
    if not os.path.exists(csv_path(PAGE, name)):
        return []
    _, (default, other), _ = SIDE_BY_SIDE[name]
    rows = read_csv(PAGE, name)
    by = {(r["h"], r[name]): r for r in rows}
    sizes = sorted({r["h"] for r in rows}, key=lambda h: -float(h))
    lines = ["", f"## {title}", "", intro]
    if os.path.exists(csv_path(PAGE, f"{name}-run")):
        lines += [f"This table was measured on its own (`--only {name}`): " + machine_line(read_csv(PAGE, f"{name}-run")[0])]
    lines += [""]
    table = []
    for h in sizes:
        d, o = by.get((h, default)), by.get((h, other))
        if not (d and o):
            continue
        table.append(dict(h=h, unknowns=d["unknowns"], parts=d["subdomains"],
                          hd=f"{d['hessian']} ({d['outer']}; {d['cg']})", ho=f"{o['hessian']} ({o['outer']}; {o['cg']})",
                          ratio=f"{f(o, 'hessian') / f(d, 'hessian'):.2f}",
                          fd=f"{f(d, 'time_factor'):.1f}", fo=f"{f(o, 'time_factor'):.1f}",
                          td=f"{f(d, 'time_solve'):.1f}", to=f"{f(o, 'time_solve'):.1f}",
                          pd=f"{peak_kib(d):.2f}", po=f"{peak_kib(o):.2f}",
                          energy=f"{abs(f(o, 'energy') - f(d, 'energy')) / abs(f(d, 'energy')):.1e}",
                          status=f"{d['status']} / {o['status']}"))
    lines += markdown_table(table, [
        ("h", "h"), ("unknowns", ("unknowns", ",.0f")), ("parts", "parts"),
        (f"{default}: Hessian (outer; CG)", "hd"), (f"{other}: Hessian (outer; CG)", "ho"),
        (f"{other} / {default}", "ratio"),
        (f"factorization [s]: {default}", "fd"), (other, "fo"), (f"dual solve [s]: {default}", "td"), (other, "to"),
        (f"peak [KiB/unknown]: {default}", "pd"), (other, "po"),
        ("energies' relative difference", "energy"), ("status", "status")])
    ratios = [float(r["ratio"]) for r in table]
    ends = [first_and_last(rows, name, v) for v in (default, other)]
    if ratios and all(ends):
        growth = [f(high, "hessian") / f(low, "hessian") for low, high in ends]
        lines += ["", reading(f"{min(ratios):.2f} to {max(ratios):.2f}",
                              f"from -h {ends[0][0]['h']} to -h {ends[0][1]['h']} the count grew {growth[0]:.2f} "
                              f"times with {default} and {growth[1]:.2f} times with {other}",
                              growth, (ends[0][1], ends[1][1]))]
    return lines


def scaling_section():
    """Multiplicity against stiffness scaling at each mesh size."""
    return side_by_side_section(
        "scaling", "The preconditioner's weights",
        "`fetiSetup`'s `scaling`: the lumped preconditioner weighs the two sides of each row by multiplicity "
        "(the default, A = (BB')⁻¹) or by stiffness (A = (B D⁻¹ B')⁻¹, D the diagonal of each K_s: Rixen and "
        "Farhat's k-scaling; [algorithms](../algorithms.md)), at parts of about "
        f"{PART_NODES} nodes, everything else the defaults; both in one run, one after the other at each size.",
        lambda ratios, growth, _, __: (
            f"Reading: stiffness scaling took {ratios} times the multiplications of multiplicity scaling here; "
            f"{growth}. The default stays multiplicity: over the whole test suite stiffness scaling passed every "
            "check but moved the counts the tests pin both ways (the 2D Hertz and several-bodies lessons "
            "fewer, the friction, 3D and impact lessons more; [log](../log.md), 2026-12-07, twenty-first "
            "session); on regular grids, whose sides are equally stiff, the two are the same."))


def preconditioner_section():
    """The lumped against the Dirichlet preconditioner at each mesh size."""
    return side_by_side_section(
        "preconditioner", "Lumped or Dirichlet preconditioner",
        "`fetiSetup`'s `preconditioner`: lumped (the default: B_s K_s B_s' per subdomain, no factorization) "
        "or Dirichlet (K_s's Schur complement on the constrained dofs: one more factorization per part; "
        "[algorithms](../algorithms.md)), at parts of about "
        f"{PART_NODES} nodes, everything else the defaults; both in one run, one after the other at each size. "
        "In brackets SMALBE's outer iterations and MPRGP's conjugate gradient steps.",
        preconditioner_reading)


def preconditioner_reading(ratios, growth_text, growth, largest):
    lumped, dirichlet = largest
    flatter = growth[1] < 0.9 * growth[0]
    return (f"Reading: the Dirichlet preconditioner took {ratios} times the lumped one's multiplications here; "
            f"{growth_text}. "
            + ("It flattens the growth: part of what grows on these parts is the lumped preconditioner's. "
               if flatter else
               "It does not flatten the growth: what grows on these parts is not the lumped preconditioner's "
               "(the undivided bodies and the expansions above say where it is). ")
            + f"At -h {lumped['h']} it took {f(dirichlet, 'time_factor') / f(lumped, 'time_factor'):.2f} times the "
            f"factorization time, {f(dirichlet, 'time_solve') / f(lumped, 'time_solve'):.2f} times the dual solve's and "
            f"{peak_kib(dirichlet) / peak_kib(lumped):.2f} times the peak memory. The default stays lumped"
            + (" until every page is re-run with the Dirichlet one." if flatter else "."))


def step_kinds_section(weak):
    """Where the weak table's multiplications go: MPRGP's steps by kind, per outer iteration."""
    done = [r for r in weak if r["status"] != "stopped" and r.get("cg")]
    if not done:
        return []
    lines = ["", "## Where the multiplications go", "",
             "The weak table's solves by the kind of step that spent each Hessian multiplication: MPRGP's "
             "conjugate gradient steps, its expansion steps (a projected step that grows the active set; one "
             "whose projected CG step falls back to the fixed step takes a second multiplication, counted in "
             "the rest) and proportioning steps (one that frees rows), and the rest (those fallbacks, gradients "
             "recomputed after sliding steps, at SMALBE's updates and by the stop tests); SMALBE's outer "
             "iterations and its penalty increases beside them.", ""]
    lines += markdown_table(done, [
        ("h", "h"), ("unknowns", ("unknowns", ",.0f")), ("active", "active"), ("Hessian", "hessian"),
        ("CG", "cg"), ("expansion", "expansion"),
        *([("of which fell back", "expansion_fallback")] if all(r.get("expansion_fallback") for r in done) else []),
        ("proportioning", "proportioning"),
        ("rest", lambda r: f"{f(r, 'hessian') - f(r, 'cg') - f(r, 'expansion') - f(r, 'proportioning'):.0f}"),
        ("outer", "outer"), ("Hessian per outer", lambda r: f"{f(r, 'hessian') / f(r, 'outer'):.1f}"),
        ("penalty increases", "penalty_increases")])
    first, last = done[0], done[-1]
    rest = lambda r: f(r, "hessian") - f(r, "cg") - f(r, "expansion") - f(r, "proportioning")
    lines += ["", f"From {f(first, 'unknowns'):,.0f} to {f(last, 'unknowns'):,.0f} unknowns the multiplications grew by "
              f"{f(last, 'hessian') - f(first, 'hessian'):.0f}: conjugate gradient steps "
              f"{f(last, 'cg') - f(first, 'cg'):+.0f}, expansions {f(last, 'expansion') - f(first, 'expansion'):+.0f}, the rest "
              f"{rest(last) - rest(first):+.0f}. The expansions follow the contact zone: its active rows grew "
              f"{f(last, 'active') / f(first, 'active'):.0f} times ({first['active']} to {last['active']}) and the expansions "
              f"{f(last, 'expansion') / f(first, 'expansion'):.1f} times, while the conjugate gradient steps per expansion "
              f"did not grow ({f(first, 'cg') / f(first, 'expansion'):.1f} at the smallest size, "
              f"{f(last, 'cg') / f(last, 'expansion'):.1f} at the largest, between "
              f"{min(f(r, 'cg') / f(r, 'expansion') for r in done):.1f} and "
              f"{max(f(r, 'cg') / f(r, 'expansion') for r in done):.1f}; each expansion changes the face, and CG "
              "goes on in the new one): the count grows with the number of contact nodes the active set has to be "
              "found among, which a fixed part size does not hold fixed (in 3D it grows as h⁻²)."]
    return lines


def render():
    weak, parts, peer = (read_csv(PAGE, table) for table in ("weak", "parts", "peer"))
    run_row = read_csv(PAGE, "run")[0]
    plot(weak)
    done = [r for r in weak if r["status"] != "stopped"]
    stopped = [r for r in weak if r["status"] == "stopped"]
    largest = done[-1]
    first = done[0]
    lines = ["# Real meshes at scale", "",
             f"A crowned punch pressed on an elastic base, each body meshed by gmsh on its own (unstructured "
             f"tetrahedra, non-matching at the contact), METIS parts of about {PART_NODES} nodes, node-to-face "
             f"contact, Total FETI with default options (`edp/crowned-punch-3d.edp`): from "
             f"{f(first, 'unknowns'):,.0f} to {f(largest, 'unknowns'):,.0f} unknowns the Hessian multiplications "
             f"went from {first['hessian']} to {largest['hessian']} (SMALBE's outer iterations "
             f"{first['outer']} to {largest['outer']}), the whole run took "
             f"{1e6 * whole(first) / f(first, 'unknowns'):.0f} to {1e6 * whole(largest) / f(largest, 'unknowns'):.0f} µs "
             f"per unknown (gmsh's meshing {per_unknown_us(largest, 'time_gmsh'):.0f} of it at the largest size, "
             f"the plugin's set-up, factorizations and dual solve "
             f"{per_unknown_us(largest, 'time_plugin_setup') + per_unknown_us(largest, 'time_factor') + per_unknown_us(largest, 'time_solve'):.0f}), "
             f"and the process held {peak_kib(largest):.1f} "
             f"KiB per unknown at its peak, of which the factors "
             f"{f(largest, 'bytes_factor_per_unknown') / 1024:.1f} KiB"
             + (f" ({peak_kib(largest, 'body_unknowns'):.1f} KiB per unknown of the undivided bodies, "
                f"{f(largest, 'body_unknowns'):,.0f} of them)" if largest.get("body_unknowns") else "") + ".",
             ""]
    boxes = nearest_boxes(f(largest, "unknowns"))
    lines += ["What the aims of the real-mesh issue came to in this run:", "",
              f"- Multiplications at the largest size against the smallest: {largest['hessian']} / {first['hessian']} = "
              f"{f(largest, 'hessian') / f(first, 'hessian'):.2f} (aim: at most 1.5"
              f"{'; not met' if f(largest, 'hessian') > 1.5 * f(first, 'hessian') else ''}). {counts_without_cuts(done)} "
              f"{growth_by_option()} "
              "What grows is in 'Where the multiplications go' below: the expansions that find the active set, "
              "and the conjugate gradient steps after each. Why no default meets the aim: "
              f"{expansions_without_cuts()} neither option side by side flattens the growth, and the solver's "
              "options swept on this scene (Γ, M, ρ, η, a start nested from a coarser mesh, a secant step of "
              "SMALBE's multiplier: [log](../log.md), 2026-12-06) did not either.",
              f"- Against the 3D boxes at a similar size (three-dimensions.md, {f(boxes, 'unknowns'):,.0f} unknowns: "
              f"{boxes['hessian']} multiplications): the real mesh at {f(nearest(done, f(boxes, 'unknowns')), 'unknowns'):,.0f} "
              f"took {nearest(done, f(boxes, 'unknowns'))['hessian']}, "
              f"{f(nearest(done, f(boxes, 'unknowns')), 'hessian') / f(boxes, 'hessian'):.1f} times (aim: at most 1.5; "
              f"not met). {contact_against_boxes(done)}",
              f"- Memory: {memory_reading(largest, parts)}",
              f"- Size: {f(largest, 'unknowns'):,.0f} unknowns on this 24 GiB machine (aim: 5 million or more).", ""]
    if stopped:
        s = stopped[0]
        lines += [f"The next size, -h {s['h']}, stopped at the {s['limit']} limit after {float(s['seconds']):.0f} s "
                  f"(limits: {TIME_LIMIT_S:.0f} s, {MEMORY_LIMIT_MB / 1024:.0f} GiB of address space).", ""]
    lines += [machine_line(run_row), "", f"![weak scaling]({PAGE}.png)", "",
              "## Weak scaling", "",
              f"Parts of about {PART_NODES} nodes; `time_*` the phases of the whole run (gmsh's meshing, METIS with "
              "`fetiConnectParts` and the cut into part meshes, FreeFEM's assembly, the plugin's set-up, the "
              "factorizations, the dual solve); memory: the factors' bytes and the process's peak resident set, per "
              "unknown; GB/s: the bytes one multiplication reads (every factor once) over its measured time." +
              (" Other work shared the machine during this run, so the time columns scatter with its load from "
               "row to row; the counts and bytes do not depend on it."
               if max(f(run_row, "load_at_start"), f(run_row, "load_at_end")) >= 0.5 else ""), ""]
    lines += markdown_table(weak, [
        ("h", "h"), ("unknowns", ("unknowns", ",.0f")), ("parts", "subdomains"), ("dual", ("dual", ",.0f")),
        ("active", "active"), ("Hessian", "hessian"), ("outer", "outer"),
        ("gmsh [s]", ("time_gmsh", ".1f")), ("METIS + cut [s]", ("time_metis", ".1f")),
        ("assembly [s]", ("time_assembly", ".1f")), ("set-up [s]", ("time_plugin_setup", ".1f")),
        ("factorization [s]", ("time_factor", ".1f")), ("dual solve [s]", ("time_solve", ".1f")),
        ("factors [KiB/unknown]", lambda r: f"{f(r, 'bytes_factor_per_unknown') / 1024:.2f}" if r.get("unknowns") else "-"),
        ("peak [KiB/unknown]", lambda r: f"{peak_kib(r):.2f}" if r.get("unknowns") else "-"),
        ("peak [KiB per body unknown]", lambda r: body_peak_kib(r) if r.get("unknowns") else "-"),
        ("GB/s", lambda r: f"{gbytes_per_second(r):.1f}" if r.get("unknowns") else "-"),
        ("status", lambda r: r["status"] if r["status"] != "stopped" else f"stopped ({r['limit']})")])
    lines += ["", "## Memory by phase", "",
              "The process's resident memory as each phase of the scene ended, KiB per unknown: the two bodies' "
              "meshes read, the part meshes cut, the parts assembled (FreeFEM's matrices K_s, loads, coordinates and "
              "condition lists), `fetiSetup` done (the plugin's copies of K_s and f_s, constraint rows, coarse "
              "problem and factors; the scene passes `releaseK = true`, so the script's K_s are emptied as the "
              "plugin copies them), the solve done; then what the plugin reports it holds (`fetiInfo`: factors, "
              "its copies of K_s, f_s and coordinates, constraint rows, kernels, and the dual system: its rows, "
              "coarse problem and preconditioner; [reference](../reference.md), `fetiInfo`).", ""]
    lines += markdown_table(done, [
        ("unknowns", ("unknowns", ",.0f")),
        *[(label, per_unknown_kib(key)) for label, key in MEMORY_PHASES],
        ("of which factors", reported_kib("bytes_factor_per_unknown")),
        ("plugin's K_s, f_s, coordinates", reported_kib("bytes_input_per_unknown")),
        ("constraint rows", reported_kib("bytes_constraint_per_unknown")),
        ("kernels", reported_kib("bytes_kernel_per_unknown")),
        ("dual rows", reported_kib("bytes_dual_rows_per_unknown")),
        ("coarse problem", reported_kib("bytes_coarse_per_unknown")),
        ("preconditioner", reported_kib("bytes_preconditioner_per_unknown")),
        ("peak", lambda r: f"{peak_kib(r):.2f}"), ("peak per body unknown", body_peak_kib)])
    lines += ["", "## Part size", "",
              f"The same scene at -h {PART_SWEEP_H} cut into parts of {PART_SWEEP[0]} to {PART_SWEEP[-1]} nodes: smaller parts hold "
              "sparser factors (less memory per unknown, cheaper solves) against a larger dual and coarse problem.", ""]
    lines += markdown_table(parts, [
        ("nodes per part: asked / mean (interface nodes in each part)", lambda r: f"{r['part_nodes']} / {r['nodes_per_part']}"), ("parts", "subdomains"),
        ("dual", ("dual", ",.0f")), ("coarse", "coarse"), ("Hessian", "hessian"), ("outer", "outer"),
        ("factorization [s]", ("time_factor", ".1f")), ("dual solve [s]", ("time_solve", ".1f")),
        ("whole run [s]", lambda r: f"{whole(r):.1f}"),
        ("factors [KiB/unknown]", lambda r: f"{f(r, 'bytes_factor_per_unknown') / 1024:.2f}"),
        ("peak [KiB/unknown]", lambda r: f"{peak_kib(r):.2f}"), ("peak [KiB per body unknown]", body_peak_kib)])
    lines += ["", "## The direct peer", "",
              "The undivided bodies by the primal-dual active set method with MUMPS on the contact rows the plugin "
              "builds for one subdomain per body: the same discrete problem, a second method.", ""]
    lines += markdown_table(peer, [
        ("h", "h"), ("unknowns", ("unknowns", ",.0f")), ("FETI energy", ("energy", ".8g")),
        ("peer energy", ("energy_peer", ".8g")), ("relative difference", ("energy_error", ".1e")),
        ("active FETI / peer", lambda r: f"{r['active']} / {r['active_peer']}"),
        ("PDAS iterations", "pdas_iterations"), ("FETI whole run [s]", lambda r: f"{whole(r):.1f}"),
        ("peer [s]", ("time_peer", ".1f"))])
    lines += step_kinds_section(weak)
    lines += undivided_section(weak)
    lines += scaling_section()
    lines += preconditioner_section()
    lines += ["", "Tables: `real-meshes-weak.csv`, `real-meshes-parts.csv`, `real-meshes-peer.csv`, "
              "`real-meshes-undivided.csv`, `real-meshes-scaling.csv`, `real-meshes-preconditioner.csv`, `real-meshes-run.csv`; "
              "`scripts/real_meshes_benchmark.py --render` redraws the page from them.", ""]
    save_page(f"{PAGE}.md", lines)


if __name__ == "__main__":
    measure_and_render(__doc__, measure, render, parts={"undivided": measure_undivided,
                                                               **{name: measure_side_by_side(name) for name in SIDE_BY_SIDE}})
