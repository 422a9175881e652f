"""The direct peers part of docs/results/three-dimensions.md (scripts/three_dimensions_benchmark.py
runs it with the page's other parts, or alone with --only peers): the undivided problem by the
primal-dual active set method (edp/active-set.idp), each Newton step a sparse direct solve with
UMFPACK and with MUMPS, beside FETI, each run alone, one after the other, on
- the 3D elasticity cubes (edp/cubes-elasticity-3d.edp -feti 0 -reference 1) at n = 8, 16, 32
  (FFETI_PEER_CUBES_SIZES),
- the Hertz sphere on the rigid plane and on the elastic block (edp/hertz-sphere.edp -feti 0
  -peers 1) at h = 0.2, 0.1, 0.07 (FFETI_PEER_SPHERE_SIZES).
Sizes grow within each problem; a peer stops at the first size where it would pass
FFETI_PEER_TIME_LIMIT_S (1800 s) or FFETI_PEER_MEMORY_LIMIT_GIB (20 GiB): projected from its
two largest sizes run so far (a power of the unknowns, FETI's unknowns as the size: known
before the peer runs), it is not started; else it runs under these limits (killed at the time
limit; the memory one as an address-space limit) and a run that reaches one stops it too: a
row with status "stopped", the limit and the projection or the seconds it ran. A peer that ends
without an answer (not converged, or an energy of 0 or not finite) is a row with status
"failed": it is not the reference and runs no larger size. Table: three-dimensions-peers.csv, one row per
(problem, size, solver); plot three-dimensions-peers.png (time over unknowns, log-log).
Progress: each (problem, size) done is appended to three-dimensions-peers-progress.csv (in the
results folder, removed when the table is written) and a line printed; a run started again
after an interruption takes the sizes done from it and goes on with the next."""
import csv
import math
import os

import matplotlib.pyplot as plt  # the driver chooses the backend first

from ffeti_bench import OUT, ROOT, OverLimit, csv_path, end_run, f, markdown_table, read_csv, run, run_machine, write_csv

PAGE = "three-dimensions"
TABLE = "peers"
CUBES_SIZES = [int(n) for n in os.environ.get("FFETI_PEER_CUBES_SIZES", "8 16 32").split()]
SPHERE_SIZES = [float(h) for h in os.environ.get("FFETI_PEER_SPHERE_SIZES", "0.2 0.1 0.07").split()]
TIME_LIMIT_S = float(os.environ.get("FFETI_PEER_TIME_LIMIT_S", "1800"))
MEMORY_LIMIT_MB = 1024 * float(os.environ.get("FFETI_PEER_MEMORY_LIMIT_GIB", "20"))
PEERS = [("UMFPACK", []), ("MUMPS", ["-DwithMUMPS=1"])]
FETI = "FETI"
PROBLEMS = ["cubes", "sphere on plane", "sphere on block"]


def limits(options):
    """The limits of a run: a peer's (-feti 0) runs under them, FETI's runs free."""
    return dict(seconds=TIME_LIMIT_S, memory_mb=MEMORY_LIMIT_MB) if options.get("feti") == 0 else {}


def cubes(size, *flags, **options):
    """One run of the cubes, the size and options as the scene's arguments; the common keys
    (size, unknowns, time_total, energy, active) added to its RESULT row."""
    args = [*flags, "-n", size]
    for key, value in options.items():
        args += [f"-{key}", value]
    row = run("cubes-elasticity-3d.edp", *args, **limits(options))["RESULT"][0]
    if "time_scene" in row:
        return dict(row, problem="cubes", size=str(size), time_total=row["time_scene"])
    return dict(row, problem="cubes", size=str(size), time_total=row["time_reference"],
                energy=row["energy_reference"], active=row["active_reference"])


def sphere(block, size, *flags, **options):
    """One run of the Hertz sphere (on the plane, or on the block with block = 1), as cubes()."""
    args = [*flags, "-h", size, "-block", block, "-meshes", os.path.join(ROOT, "meshes")]
    for key, value in options.items():
        args += [f"-{key}", value]
    row = run("hertz-sphere.edp", *args, **limits(options))["RESULT"][0]
    problem = "sphere on block" if block else "sphere on plane"
    if "time_scene" in row:
        return dict(row, problem=problem, size=str(size), time_total=row["time_scene"])
    return dict(row, problem=problem, size=str(size), time_total=row["time_peer"], unknowns=row["unknowns_peer"],
                energy=row["energy_peer"], active=row["active_peer"])


def projection(done, unknowns):
    """A peer's time and peak memory at `unknowns` (FETI's count), from its two largest sizes
    run so far as powers of FETI's unknowns; None before two sizes have run."""
    if len(done) < 2:
        return None
    (x1, t1, m1), (x2, t2, m2) = done[-2:]
    time_power, memory_power = math.log(t2 / t1) / math.log(x2 / x1), math.log(m2 / m1) / math.log(x2 / x1)
    return t2 * (unknowns / x2) ** time_power, m2 * (unknowns / x2) ** memory_power, time_power, memory_power


PROGRESS = f"{TABLE}-progress"


def record_progress(rows):
    """Appends one (problem, size)'s rows to the progress file, one row per line (each line
    its own columns: the file is a log read back row by row), and says so."""
    with open(csv_path(PAGE, PROGRESS), "a", newline="") as file:
        writer = csv.writer(file)
        for row in rows:
            writer.writerow([f"{key}={value!r}" if isinstance(value, float) else f"{key}={value}"
                             for key, value in row.items() if not isinstance(value, (list, dict))])
    for row in rows:
        print(f"peers: {row['problem']} {row['size']} {row['solver']}: {row.get('status', '')}"
              f" {row.get('time_total', '')}", flush=True)


def read_progress():
    """The progress file's rows as dicts of strings (empty without one)."""
    if not os.path.exists(csv_path(PAGE, PROGRESS)):
        return []
    with open(csv_path(PAGE, PROGRESS), newline="") as file:
        return [dict(cell.split("=", 1) for cell in line) for line in csv.reader(file) if line]


def answered(peer):
    """True when a peer's run gave an answer: converged (ffetiActiveSetStatus, which says
    solve_failed where a sparse solve gave nothing) and a nonzero finite energy (the 2026-12-07
    run's UMFPACK peer ended with energy 0 before that check existed)."""
    energy = float(peer.get("energy") or 0)
    return peer.get("status") == "converged" and energy != 0 and math.isfinite(energy)


def measure_problem(problem, sizes, solve, feti_options, peer_options, earlier):
    """One problem's rows: per size FETI, then each peer alone unless stopped; FETI's energy
    and contact set compared with the first peer's answer (UMFPACK's, else MUMPS's). The
    sizes in `earlier` (rows of an interrupted run) are taken from it, not run again."""
    rows, done, stopped = [], {name: [] for name, _ in PEERS}, set()
    for size in sizes:
        before = [row for row in earlier if row["problem"] == problem and row["size"] == str(size)]
        if before:
            rows += before
            for row in before:
                if row["solver"] in done and row.get("status") == "converged" and row.get("time_total"):
                    done[row["solver"]].append((f(row, "feti_unknowns"), f(row, "time_total"), f(row, "process_peak_mb")))
                elif row["solver"] in done:
                    stopped.add(row["solver"])
            continue
        feti = dict(solve(size, **feti_options), solver=FETI)
        unknowns = f(feti, "unknowns")
        peers, stops = [], []
        for name, flags in PEERS:
            projected = projection(done[name], unknowns)
            if name in stopped:
                continue
            stop = dict(problem=feti["problem"], size=str(size), solver=name, status="stopped",
                        feti_unknowns=repr(unknowns))
            if projected and (projected[0] > TIME_LIMIT_S or projected[1] > MEMORY_LIMIT_MB):
                stops.append(dict(stop, stop="projected", projected_time_s=repr(projected[0]),
                                 projected_memory_mb=repr(projected[1]), time_power=repr(projected[2]),
                                 memory_power=repr(projected[3])))
                stopped.add(name)
                continue
            try:
                peer = dict(solve(size, *flags, **peer_options), solver=name)
            except OverLimit as limit:
                stops.append(dict(stop, stop=f"{limit.what} limit", ran_s=repr(limit.seconds)))
                stopped.add(name)
                continue
            if not answered(peer):
                peers.append(dict(peer, status="failed", scene_status=peer.get("status", ""), feti_unknowns=repr(unknowns)))
                stopped.add(name)
                continue
            done[name].append((unknowns, f(peer, "time_total"), f(peer, "process_peak_mb")))
            peers.append(dict(peer, feti_unknowns=repr(unknowns)))
        reference = next((peer for peer in peers if peer.get("status") != "failed" and "energy" in peer), None)
        if reference:
            feti.update(energy_error=repr(abs(f(feti, "energy") - f(reference, "energy")) / abs(f(reference, "energy"))),
                        same_contact_set=str(int(feti["active"]) == int(reference["active"])),
                        energy_reference_solver=reference["solver"])
        size_rows = [dict(feti, feti_unknowns=repr(unknowns))] + peers + stops
        record_progress(size_rows)
        rows += size_rows
    return rows


def measure(begun):
    """The part's table and its own run row (peers-run)."""
    earlier = read_progress()
    rows = measure_problem("cubes", CUBES_SIZES, cubes, dict(check=1), dict(feti=0, reference=1), earlier)
    for block in (0, 1):
        rows += measure_problem("sphere on block" if block else "sphere on plane", SPHERE_SIZES,
                                lambda size, *flags, **options: sphere(block, size, *flags, **options),
                                {}, dict(feti=0, peers=1), earlier)
    write_csv(PAGE, TABLE, rows)
    os.remove(csv_path(PAGE, PROGRESS))
    run_row = end_run(PAGE, begun, f"{TABLE}-run")
    write_csv(PAGE, f"{TABLE}-run", [dict(run_row, time_limit_s=repr(TIME_LIMIT_S), memory_limit_mb=repr(MEMORY_LIMIT_MB))])


def run_limits(run_row):
    """The limits the part ran with (its run row; the environment's for a row without them)."""
    return (float(run_row.get("time_limit_s") or TIME_LIMIT_S), float(run_row.get("memory_limit_mb") or MEMORY_LIMIT_MB))


def ran(rows):
    return [r for r in rows if r.get("status") not in ("stopped", "failed")]


def plot(rows, name):
    """Time (top) and peak memory (bottom) over FETI's unknowns, log-log, one column per problem."""
    figure, axes = plt.subplots(2, len(PROBLEMS), figsize=(13, 7.5))
    for column, problem in enumerate(PROBLEMS):
        for solver, style in ((FETI, "o-"), ("UMFPACK", "s--"), ("MUMPS", "^--")):
            points = [r for r in ran(rows) if r["problem"] == problem and r["solver"] == solver]
            label = solver if solver == FETI else f"active set, {solver}"
            for row, key in ((0, "time_total"), (1, "process_peak_mb")):
                if points:
                    axes[row][column].loglog([f(r, "feti_unknowns") for r in points], [f(r, key) for r in points],
                                             style, label=label)
        axes[0][column].set_title(problem)
        axes[1][column].set_xlabel("unknowns (FETI's count)")
        for row in (0, 1):
            axes[row][column].grid(True, which="both", alpha=0.3)
    axes[0][0].set_ylabel("wall-clock time [s]")
    axes[1][0].set_ylabel("peak resident memory [MB]")
    axes[0][0].legend(fontsize=8)
    figure.tight_layout()
    figure.savefig(os.path.join(OUT, name), dpi=90)
    plt.close(figure)


def ratio_rows(rows):
    """Per problem and size, each peer's time and peak memory over FETI's ("stopped" where it
    did not run to the end, "failed" where it ended without an answer)."""
    table = []
    for problem in PROBLEMS:
        for size in dict.fromkeys(r["size"] for r in rows if r["problem"] == problem):
            here = {r["solver"]: r for r in rows if r["problem"] == problem and r["size"] == size}
            feti = here[FETI]
            line = dict(problem=problem, size=size, unknowns=feti["unknowns"], time=f"{f(feti, 'time_total'):.2f}",
                        memory=f"{f(feti, 'process_peak_mb'):.0f}")
            for name, _ in PEERS:
                peer = here.get(name)
                if peer is None or peer.get("status") in ("stopped", "failed"):
                    line[f"{name} time"] = line[f"{name} memory"] = peer["status"] if peer else "-"
                else:
                    line[f"{name} time"] = f"{f(peer, 'time_total') / f(feti, 'time_total'):.1f}"
                    line[f"{name} memory"] = f"{f(peer, 'process_peak_mb') / f(feti, 'process_peak_mb'):.1f}"
            table.append(line)
    return table


def stops(rows, limits):
    """Why each peer stopped where it did (limits: seconds, MB)."""
    time_limit_s, memory_limit_mb = limits
    lines = []
    for r in rows:
        if r.get("status") not in ("stopped", "failed"):
            continue
        label = f"{r['problem']}, {'n' if r['problem'] == 'cubes' else 'h'} = {r['size']}"
        if r["status"] == "failed":
            lines.append(f"- {label}: {r['solver']} ended after {f(r, 'time_total') / 60:.0f} min without an answer "
                         f"(its status {r.get('scene_status') or '-'}, energy {r.get('energy') or '-'}); nor larger sizes.")
            continue
        if r["stop"] == "projected":
            lines.append(f"- {label}: {r['solver']} not run: over its two largest sizes run it grew as unknowns^"
                         f"{f(r, 'time_power'):.2f} in time and ^{f(r, 'memory_power'):.2f} in peak memory, which "
                         f"projects {f(r, 'projected_time_s') / 60:.0f} min and {f(r, 'projected_memory_mb') / 1024:.1f} "
                         f"GiB here (limits {time_limit_s / 60:.0f} min, {memory_limit_mb / 1024:.0f} GiB); nor larger sizes.")
        else:
            lines.append(f"- {label}: {r['solver']} stopped by the {r['stop']} after {f(r, 'ran_s') / 60:.0f} min (limits "
                         f"{time_limit_s / 60:.0f} min, {memory_limit_mb / 1024:.0f} GiB of address space); nor larger sizes.")
    return lines


def agreement(rows):
    """One sentence: FETI's answer against the peers' wherever both ran (an independent check)."""
    compared = [r for r in rows if r["solver"] == FETI and r.get("energy_error")]
    if not compared:
        return "No size ran a peer to compare FETI's answer with."
    same = all(r["same_contact_set"] == "True" for r in compared)
    return (f"Reading: at the {len(compared)} sizes where a peer ran, FETI's energy agrees with the peer's to "
            f"{min(f(r, 'energy_error') for r in compared):.1e} to {max(f(r, 'energy_error') for r in compared):.1e} "
            "(relative; FETI stops at tol = 1e-4 on the cubes, 1e-6 on the sphere) and its contact set has "
            + ("the same size at every one." if same else "a different size at "
               + ", ".join(f"{r['problem']} {r['size']}" for r in compared if r["same_contact_set"] != "True") + "."))


def growth(rows):
    """The time ratio's growth per problem and peer: its first and last size where both ran."""
    lines = []
    for problem in PROBLEMS:
        for name, _ in PEERS:
            pairs = []
            for r in ran(rows):
                if r["problem"] == problem and r["solver"] == name:
                    feti = next(x for x in rows if x["problem"] == problem and x["size"] == r["size"]
                                and x["solver"] == FETI)
                    pairs.append((f(feti, "feti_unknowns"), f(r, "time_total") / f(feti, "time_total")))
            if len(pairs) >= 2:
                (x1, q1), (x2, q2) = pairs[0], pairs[-1]
                lines.append(f"{problem}, {name}: the time ratio goes from {q1:.1f} to {q2:.1f} as the unknowns grow "
                             f"{x2 / x1:.1f} times (the ratio as unknowns^{math.log(q2 / q1) / math.log(x2 / x1):.2f}).")
    return lines or ["no problem ran two sizes with a peer."]


def section():
    """The page's lines of the peers part, rendered from its CSV (none before the part has run)."""
    if not os.path.exists(os.path.join(OUT, f"{PAGE}-{TABLE}.csv")):
        return ["## The direct peers side by side", "",
                "Not run yet: `scripts/three_dimensions_benchmark.py --only peers`.", ""]
    rows, run_row = read_csv(PAGE, TABLE), read_csv(PAGE, f"{TABLE}-run")[0]
    time_limit_s, memory_limit_mb = run_limits(run_row)
    plot(rows, f"{PAGE}-peers.png")
    return [
        "## The direct peers side by side",
        "",
        "The undivided problem (one mesh per body) by the primal-dual active set method, each Newton step",
        "a sparse direct solve of the KKT system (`edp/active-set.idp`), with UMFPACK and with MUMPS (both",
        "ship with FreeFEM), against FETI, each run alone, one after the other: the 3D elasticity cubes",
        "(`edp/cubes-elasticity-3d.edp -feti 0 -reference 1`) and the Hertz sphere on the rigid plane and on",
        "the elastic block (`edp/hertz-sphere.edp -feti 0 -peers 1`; on the block the peer takes the mortar",
        "rows the plugin built, its process first running `fetiSetup` for them, freed before the peer starts).",
        "Time: FETI's whole scene, the peer's mesh, assembly and every Newton step (the sphere's times",
        "both include gmsh's meshing). Memory: each process's peak resident set. FETI's unknowns count the",
        "copies of interface nodes in every subdomain, the peers' each node once; the plot and the",
        "projections take FETI's count. Energy error: FETI's energy against the peer's answer (UMFPACK's, or",
        "MUMPS's where UMFPACK stopped); active: the",
        "contact rows in the final contact set (mortar rows on the block). Newton steps: the method starts",
        "from every contact row active and factors the KKT system anew at each step; `of which last solve`",
        "is one factorization and solve, the floor of an active set method with that solver. A peer stops",
        f"at the first size where its growth over its two largest sizes run projects more than {time_limit_s / 60:.0f} min",
        f"or {memory_limit_mb / 1024:.0f} GiB, or where it reaches a limit while it runs (killed at {time_limit_s / 60:.0f} min;",
        f"{memory_limit_mb / 1024:.0f} GiB of address space). This part ran on its own on {run_machine(run_row)}: {run_row['date']}, "
        f"{float(run_row['elapsed_s']):.0f} s, load average {float(run_row['load_at_start']):.1f} as it started, "
        f"{float(run_row['load_at_end']):.1f} as it ended. Raw data: [{PAGE}-{TABLE}.csv]({PAGE}-{TABLE}.csv).",
        "",
        *markdown_table(ran(rows), [
            ("problem", "problem"), ("n or h", "size"), ("unknowns", "unknowns"), ("solver", "solver"),
            ("time [s]", ("time_total", ".2f")),
            ("of which last solve [s]", lambda r: "-" if r["solver"] == FETI else
             f"{f(r, 'time_reference_last_solve' if r['problem'] == 'cubes' else 'time_peer_last_solve'):.2f}"),
            ("Newton steps", lambda r: "-" if r["solver"] == FETI else r["pdas_iterations"]),
            ("peak MB", ("process_peak_mb", ".0f")),
            ("energy error", lambda r: f"{f(r, 'energy_error'):.1e}" if r.get("energy_error") else "-"),
            ("active", "active")]),
        "",
        agreement(rows),
        "",
        "The peers' time and peak memory over FETI's (times FETI's), per size:",
        "",
        *markdown_table(ratio_rows(rows), [
            ("problem", "problem"), ("n or h", "size"), ("FETI unknowns", "unknowns"), ("FETI time [s]", "time"),
            ("FETI peak MB", "memory"), ("UMFPACK: time", "UMFPACK time"), ("UMFPACK: memory", "UMFPACK memory"),
            ("MUMPS: time", "MUMPS time"), ("MUMPS: memory", "MUMPS memory")]),
        "",
        *stops(rows, (time_limit_s, memory_limit_mb)),
        "",
        f"![time and memory over unknowns]({PAGE}-peers.png)",
        "",
        "How the gap grows: " + " ".join(growth(rows)),
        "",
    ]


def headline_words():
    """The headline's sentence on the peers (the cubes' largest size where both ran), or none."""
    if not os.path.exists(os.path.join(OUT, f"{PAGE}-{TABLE}.csv")):
        return ""
    rows = [r for r in ran(read_csv(PAGE, TABLE)) if r["problem"] == "cubes"]
    shared = max((r["size"] for r in rows if r["solver"] != FETI), key=int, default=None)
    if shared is None:
        return ""
    feti = next(r for r in rows if r["size"] == shared and r["solver"] == FETI)
    against = [f"{r['solver']} {f(r, 'time_total') / f(feti, 'time_total'):.0f} times"
               for r in rows if r["size"] == shared and r["solver"] != FETI]
    return (f" The direct peers (the undivided cubes by the primal-dual active set method) ran up to n = {shared}, "
            f"where they took {' and '.join(against)} FETI's whole-scene time ({f(feti, 'time_total'):.1f} s); "
            "[below](#the-direct-peers-side-by-side) how the gap grows.")
