"""The 3D elasticity part of docs/results/three-dimensions.md (scripts/three_dimensions_benchmark.py
runs it with the page's other parts, or alone with --only elasticity): edp/cubes-elasticity-3d.edp,
weak scaling at H/h = 8 (n = 16, 32, 64, 128 cells per cube side, 128 taking 16 GB and
about 8 minutes; FFETI_ELASTICITY_3D_SIZES overrides) with the whole scene's phases (FreeFEM's assembly, the plugin's set-up, factorization,
solve, recovery) and peak memory, the coarse problem at H/h = 4 (8 times the subdomains; n = 16,
32, 64, FFETI_ELASTICITY_3D_COARSE_SIZES), the preconditioners and CHOLMOD's factor kinds side by
side at n = 32 (the direct peers: scripts/three_dimensions_peers.py).
The coarse Gram matrices (--only gram, in the full run too): the free rows' and primal checks'
factors separate or from GG''s with the contact modes last (fetiSetup's coarseGram), side by side
at n = 64 with H/h = 8 and 4 (FFETI_ELASTICITY_3D_GRAM_CASES, "n:Hh ...").
Optional (--only mpi, not in the page's full run): one size (FFETI_ELASTICITY_3D_MPI_SIZE,
default 128) on one process and on two MPI ranks, the same answer
and each rank's memory. Each table is the CSV three-dimensions-elasticity-<table>.csv."""
import os
import subprocess

import matplotlib.pyplot as plt  # the driver chooses the backend first

from ffeti_bench import OUT, PHASES, end_run, f, markdown_table, phase_table, read_csv, run, run_machine, write_csv
import three_dimensions_peers as peers

PAGE = "three-dimensions"
SIZES = [int(n) for n in os.environ.get("FFETI_ELASTICITY_3D_SIZES", "16 32 64 128").split()]
VARIANT_SIZE = 32 if 32 in SIZES else SIZES[-1]
COARSE_SIZES = [int(n) for n in os.environ.get("FFETI_ELASTICITY_3D_COARSE_SIZES", "16 32 64").split()]
GRAM_CASES = [tuple(int(v) for v in case.split(":"))
              for case in os.environ.get("FFETI_ELASTICITY_3D_GRAM_CASES", "64:8 64:4").split()]
GRAM_LAYOUTS = ["separate", "contact-last"]
MPI_SIZE = int(os.environ.get("FFETI_ELASTICITY_3D_MPI_SIZE", 128))
PRECONDITIONERS = ["lumped", "dirichlet", "none"]
SOLVE_PARTS = ("time_hessian", "time_primal_checks", "time_free_rows", "time_norm_estimate", "time_preconditioner")
FACTORS = ["simplicial", "supernodal", "auto"]


def table(name):
    return f"elasticity-{name}"


def blas_library():
    """The BLAS the dynamic linker gives CHOLMOD (Debian's alternatives: reference or OpenBLAS)."""
    try:
        text = subprocess.run(["ldconfig", "-p"], capture_output=True, text=True, check=True).stdout
    except (OSError, subprocess.CalledProcessError):
        return "unknown"
    path = next((line.split("=>")[-1].strip() for line in text.splitlines() if "libblas.so.3 " in line), "")
    resolved = os.path.realpath(path) if path else ""
    return "OpenBLAS" if "openblas" in resolved else ("reference BLAS (netlib)" if resolved else "unknown")


def scene(n, *extra, ranks=0, **options):
    """One run of the scene: its RESULT row with the options given, and under MPI its ranks'
    peak memories (RANK lines) as 'rank_peak_mb' ('a / b' MB)."""
    args = ["-n", n, *extra]
    for key, value in options.items():
        args += [f"-{key}", value]
    lines = run("cubes-elasticity-3d.edp", *args, ranks=ranks)
    row = dict(lines["RESULT"][0], **{key: str(value) for key, value in options.items()})
    row["rank_peak_mb"] = " / ".join(f"{f(r, 'peak_memory_mb'):.0f}" for r in lines["RANK"])
    return row


def measure(begun):
    """The elasticity part's tables and its own run row (elasticity-run)."""
    weak = [dict(scene(n, check=1), case="default") for n in SIZES]
    coarse = [dict(scene(n, check=1, Hh=4), case="H/h = 4") for n in COARSE_SIZES]
    variants = [dict(scene(VARIANT_SIZE, preconditioner=p), case=f"preconditioner {p}") for p in PRECONDITIONERS]
    variants += [dict(scene(VARIANT_SIZE, factor=k), case=f"factor {k}") for k in FACTORS]
    write_csv(PAGE, table("weak"), weak)
    write_csv(PAGE, table("coarse"), coarse)
    write_csv(PAGE, table("variants"), variants)
    write_csv(PAGE, table("blas"), [{"blas": blas_library()}])
    end_run(PAGE, begun, table("run"))


def measure_gram(begun):
    """Each case with the coarse Gram matrices factorized separately and from GG''s factor,
    one run after the other (gram, gram-run)."""
    rows = [dict(scene(n, check=1, Hh=Hh, coarseGram=layout), case=layout)
            for n, Hh in GRAM_CASES for layout in GRAM_LAYOUTS]
    write_csv(PAGE, table("gram"), rows)
    end_run(PAGE, begun, table("gram-run"))


def measure_mpi(begun):
    """The largest size on one process and on two MPI ranks (each rank its own boxes, the
    plugin's threads as it chooses them), one after the other."""
    rows = [dict(scene(MPI_SIZE, check=1), case="1 process"),
            dict(scene(MPI_SIZE, check=1, ranks=2), case="2 MPI ranks")]
    write_csv(PAGE, table("mpi"), rows)
    end_run(PAGE, begun, table("mpi-run"))


def plot_phases(weak, name):
    figure, (counts, phases) = plt.subplots(1, 2, figsize=(12, 4.4))
    unknowns = [f(r, "unknowns") for r in weak]
    counts.plot(unknowns, [f(r, "hessian") for r in weak], "o-", label="Hessian multiplications")
    counts.set_xscale("log")
    counts.set_xlabel("unknowns")
    counts.set_ylabel("Hessian multiplications")
    counts.set_ylim(0, 1.3 * max(f(r, "hessian") for r in weak))
    counts.set_title("3D elasticity, dual solve, H/h = 8 fixed")
    counts.grid(True, alpha=0.3)
    bottom = [0.0] * len(weak)
    labels = [f"n = {r['n']}\n{int(f(r, 'subdomains'))} subdomains\n{f(r, 'time_scene'):.1f} s" for r in weak]
    for key_label, key in PHASES:
        shares = [100 * f(r, key) / f(r, "time_scene") for r in weak]
        phases.bar(labels, shares, bottom=bottom, label=key_label)
        bottom = [b + v for b, v in zip(bottom, shares)]
    phases.tick_params(axis="x", labelsize=8)
    phases.set_ylim(0, 100)
    phases.set_ylabel("share of the scene's wall-clock time [%]")
    phases.set_title("Where the scene's time goes (total below each bar)")
    phases.legend(fontsize=8, loc="upper left", bbox_to_anchor=(1.0, 1.0))
    figure.tight_layout()
    figure.savefig(os.path.join(OUT, name), dpi=90)
    plt.close(figure)


def next_size(last, memory_gib):
    """Whether the next size (8 times the unknowns) would fit this machine's memory, at the
    peak memory per unknown measured at the largest size."""
    per_unknown = f(last, "process_peak_mb") / f(last, "unknowns")  # MB
    unknowns = 8 * f(last, "unknowns")
    needed = per_unknown * unknowns / 1024
    if needed <= memory_gib:
        return []
    factors = f"{f(last, 'factor_bytes') / 2**30:.2f}" if last.get("factor_bytes") else "?"
    return [f"n = {2 * int(last['n'])} ({unknowns / 1e6:.1f} million unknowns) was not run: at the "
            f"{per_unknown * 1024:.1f} KiB per unknown measured at n = {last['n']} it would need about "
            f"{needed:.0f} GiB, more than this machine's {memory_gib:.0f} GiB. Of the "
            f"{f(last, 'process_peak_mb') / 1024:.1f} GiB at n = {last['n']} the factors hold {factors} GiB "
            f"({last.get('factorizations', '?')} distinct factors for {last['subdomains']} subdomains: "
            "identical boxes share one; the boxes share one stiffness matrix); the rest is the script's "
            "meshes and vectors and the plugin's constraints, kernels, coarse problem and work vectors."]


def headline():
    """The page's opening lines: the largest 3D elasticity contact solved, its Hessian count
    against the smallest size's, its time against the direct peers where both ran."""
    weak = read_csv(PAGE, table("weak"))
    first, last = weak[0], weak[-1]
    growth = f(last, "hessian") / f(first, "hessian")
    return [f"**Headline.** The largest 3D elasticity contact solved here: two elastic cubes, n = {last['n']} cells per "
            f"side, {int(f(last, 'unknowns')):,} unknowns in {last['subdomains']} subdomains (Total FETI, six rigid "
            f"modes each), the whole scene in {f(last, 'time_scene'):.0f} s and {f(last, 'process_peak_mb') / 1024:.1f} GB. "
            f"Its dual solve took {last['hessian']} Hessian multiplications against {first['hessian']} at n = "
            f"{first['n']} ({int(f(first, 'unknowns')):,} unknowns): {growth:.2f} times (aim: at most 1.5)."
            + peers.headline_words()]


def section(memory_gib):
    """The page's lines of the elasticity part, rendered from its CSVs."""
    weak, variants = read_csv(PAGE, table("weak")), read_csv(PAGE, table("variants"))
    coarse = read_csv(PAGE, table("coarse"))
    run_row, blas = read_csv(PAGE, table("run"))[0], read_csv(PAGE, table("blas"))[0]["blas"]
    plot_phases(weak, f"{PAGE}-elasticity.png")
    last = weak[-1]
    lines = [
        "## 3D elasticity: weak scaling, H/h = 8",
        "",
        "`edp/cubes-elasticity-3d.edp`: two elastic unit cubes stacked (a quarter model), the lower",
        "clamped at its bottom, the upper floating, pressed by a traction on a quarter of its top;",
        "node-to-node contact on the shared face with a crowned gap, so that the contact zone is",
        "partial. Each cube is cut into boxes of 8 cells per side (H/h = 8 fixed), P1 elasticity, Total",
        f"FETI: every box floats, six rigid modes each, tol = 1e-4, default options. BLAS on the machine: {blas}, "
        "which the factors do not call (CHOLMOD's simplicial factors need none; supernodal ones are computed and "
        "solved on CHOLMOD's analysis through Eigen's dense kernels, [algorithms](../algorithms.md)).",
        f"This part ran on its own on {run_machine(run_row)}: {run_row['date']}, {float(run_row['elapsed_s']):.0f} s, load average "
        f"{float(run_row['load_at_start']):.1f} as it started, {float(run_row['load_at_end']):.1f} as it ended. Raw data:",
        f"[{PAGE}-elasticity-weak.csv]({PAGE}-elasticity-weak.csv), [{PAGE}-elasticity-coarse.csv]({PAGE}-elasticity-coarse.csv),",
        f"[{PAGE}-elasticity-variants.csv]({PAGE}-elasticity-variants.csv).",
        "",
        *markdown_table(weak, [
            ("n", "n"), ("unknowns", "unknowns"), ("subdomains", "subdomains"), ("dual", "dual"),
            ("coarse", "coarse"), ("couples", "couples"), ("active", "active"), ("Hessian mult.", "hessian"),
            ("outer", "outer"), ("whole scene [s]", ("time_scene", ".2f")), ("peak MB", ("process_peak_mb", ".0f")),
            ("force balance", ("balance", ".1e")), ("status", "status")]),
        "",
        *next_size(last, memory_gib),
        "",
        "## 3D elasticity: the whole scene, phase by phase",
        "",
        "Each phase as `edp/ffeti-phases.idp` names it: `assembly` FreeFEM builds the boxes' meshes,",
        "assembles the one stiffness matrix every box shares (`stiffnessOf=`), each f_s and the",
        "condition lists; `plugin set-up` `fetiSetup` without its",
        "factorizations (the input's conversion and checks, constraints, coarse problem, dual data),",
        "of which `coarse` the coarse problem (G G' assembled and factorized); `factorization` the",
        "boxes' kernels and CHOLMOD factorizations (identical boxes share one) and the",
        "preconditioner's set-up; `dual solve` the norm estimate and SMALBE-M with MPRGP; `recovery`",
        "the primal solution (0 where the stopping test's last check recovered it, inside the dual",
        "solve).",
        "",
        *phase_table(weak, (("n", "n"), ("unknowns", "unknowns"), ("subdomains", "subdomains"))),
        "",
        f"![phases]({PAGE}-elasticity.png)",
        "",
        f"Reading: at n = {last['n']} FreeFEM's assembly is {f(last, 'time_assembly') / f(last, 'time_scene'):.0%} of the "
        f"scene's time and the plugin's own set-up {f(last, 'time_plugin_setup') / f(last, 'time_factor'):.2f} times its "
        f"factorizations (aim: at most 1), of which the coarse problem {f(last, 'time_coarse'):.1f} s.",
        "",
        "The dual solve, part by part: `Hessian` the multiplications by P F P (F's applications and",
        "the projections), `primal checks` the stopping test's recoveries of the primal solution",
        "(each solves with G_S G_S', the Gram matrix of the coarse space's rows on the multipliers",
        "that are not at a bound), `free rows` the projector of the gluing multipliers (the null",
        "space of G_F G_F' and its factor, once), `norm estimate` ||PFP|| by Lanczos,",
        "`preconditioner` its applications. From 3000 rigid modes on, G_S G_S' and G_F G_F' come",
        "from GG''s factor with the contact boxes' modes eliminated last and a dense factor of",
        "their Schur complement ([algorithms](../algorithms.md), the coarse problem's Gram matrices).",
        "",
        *markdown_table(weak, [
            ("n", "n"), ("subdomains", "subdomains"), ("coarse", "coarse"), ("dual solve [s]", ("time_solve", ".2f")),
            ("Hessian [s]", ("time_hessian", ".2f")), ("primal checks [s]", ("time_primal_checks", ".2f")),
            ("free rows [s]", ("time_free_rows", ".2f")), ("norm estimate [s]", ("time_norm_estimate", ".2f")),
            ("preconditioner [s]", ("time_preconditioner", ".2f")),
            ("rest [s]", lambda r: f"{f(r, 'time_solve') - sum(f(r, k) for k in SOLVE_PARTS):.2f}")]),
        "",
        f"Reading: at n = {last['n']} the coarse problem (its set-up, the primal checks and the free rows) takes "
        f"{(f(last, 'time_coarse') + f(last, 'time_primal_checks') + f(last, 'time_free_rows')) / f(last, 'time_scene'):.0%} "
        f"of the scene's time, the Hessian multiplications {f(last, 'time_hessian') / f(last, 'time_scene'):.0%}: "
        "GG''s sparse Cholesky factor (of order six times the subdomains) fills like that of a 3D "
        "problem; it is now the only sparse factor of the "
        "coarse problem (G_S G_S' and G_F G_F' each took one of their own before; [log](../log.md), 2026-11-28). "
        "Not done: hybrid FETI (subdomains glued into clusters, a coarse problem of the clusters) or a coarse "
        "problem shared over ranks, which would shrink GG''s factor itself.",
        "",
        "## 3D elasticity: the coarse problem with many subdomains, H/h = 4",
        "",
        "The same sizes cut into boxes of 4 cells per side: 8 times the subdomains and the coarse",
        "space (six rigid modes per box). `coarse`: the coarse problem's set-up (G G' assembled and",
        "factorized); its application is inside the solve's time, and so are the primal checks and",
        "the free rows (their parts of it in their own columns).",
        "",
        *markdown_table(coarse, [
            ("n", "n"), ("unknowns", "unknowns"), ("subdomains", "subdomains"), ("coarse", "coarse"),
            ("Hessian mult.", "hessian"), ("assembly [s]", ("time_assembly", ".2f")),
            ("plugin set-up [s]", ("time_plugin_setup", ".2f")), ("of which coarse [s]", ("time_coarse", ".3f")),
            ("factorization [s]", ("time_factor", ".2f")), ("solve [s]", ("time_solve", ".2f")),
            ("of which primal checks [s]", ("time_primal_checks", ".2f")), ("free rows [s]", ("time_free_rows", ".2f")),
            ("peak MB", ("process_peak_mb", ".0f")), ("status", "status")]),
        "",
        f"## 3D elasticity: preconditioners and factor kinds, n = {VARIANT_SIZE}",
        "",
        "The same scene with each preconditioner (lumped: a sparse product; Dirichlet: a factorized",
        "interior block per subdomain, one factor per set of identical boxes) and each CHOLMOD factor",
        "kind (simplicial, CHOLMOD's; supernodal on CHOLMOD's analysis with its dense blocks through Eigen's",
        "kernels; auto, the default, chooses by CHOLMOD's flops per factor nonzero).",
        "",
        *markdown_table(variants, [
            ("case", "case"), ("Hessian mult.", "hessian"), ("factor nnz", ("factor_nnz", ".3g")),
            ("factorization [s]", ("time_factor", ".2f")), ("solve [s]", ("time_solve", ".2f")),
            ("solve per mult. [ms]", lambda r: f"{1000 * f(r, 'time_solve') / f(r, 'hessian'):.0f}"),
            ("peak MB", ("process_peak_mb", ".0f")), ("status", "status")]),
        "",
        *peers.section(),
    ]
    return lines + gram_section() + mpi_section()


def gram_section():
    """The coarse Gram matrices' lines, when that part has been run (--only gram or the full run)."""
    if not os.path.exists(os.path.join(OUT, f"{PAGE}-{table('gram')}.csv")):
        return []
    rows, run_row = read_csv(PAGE, table("gram")), read_csv(PAGE, table("gram-run"))[0]
    lines = [
        "## 3D elasticity: the coarse Gram matrices, separate or from one factor",
        "",
        "The free rows' G_F G_F' and each primal check's G_S G_S' differ from GG' in contact columns",
        "only (`fetiSetup`'s `coarseGram`, [algorithms](../algorithms.md)): `separate` factorizes",
        "each on its own (CHOLMOD; the free rows twice, a shifted factor for the null space and one",
        "of the kept rows); `contact-last` factorizes GG' once with the contact boxes' modes last and",
        "solves each with a dense Cholesky factor of its Schur complement on them (`auto` picks it",
        "from 3000 rigid modes on). `contact modes`: the rigid modes of the boxes on the contact face.",
        f"One run after the other on {run_machine(run_row)} ({run_row['date']}, {float(run_row['elapsed_s']):.0f} s, load average "
        f"{float(run_row['load_at_start']):.1f} as it started, {float(run_row['load_at_end']):.1f} as it ended). "
        f"Raw data: [{PAGE}-{table('gram')}.csv]({PAGE}-{table('gram')}.csv).",
        "",
        *markdown_table(rows, [
            ("n", "n"), ("H/h", "Hh"), ("subdomains", "subdomains"), ("coarse", "coarse"),
            ("contact modes", lambda r: f"{12 * (int(r['n']) // int(r['Hh'])) ** 2}"), ("coarseGram", "case"),
            ("Hessian mult.", "hessian"), ("coarse set-up [s]", ("time_coarse", ".2f")),
            ("primal checks [s]", ("time_primal_checks", ".2f")), ("free rows [s]", ("time_free_rows", ".2f")),
            ("dual solve [s]", ("time_solve", ".2f")), ("whole scene [s]", ("time_scene", ".2f")),
            ("peak MB", ("process_peak_mb", ".0f")), ("energy", "energy"), ("status", "status")]),
        "",
    ]
    pairs = [rows[k:k + 2] for k in range(0, len(rows) - 1, 2)]
    readings = []
    for separate, last in pairs:
        coarse_separate = sum(f(separate, k) for k in ("time_coarse", "time_primal_checks", "time_free_rows"))
        coarse_last = sum(f(last, k) for k in ("time_coarse", "time_primal_checks", "time_free_rows"))
        same = separate["hessian"] == last["hessian"]
        energy = abs(f(last, "energy") - f(separate, "energy")) / abs(f(separate, "energy"))
        readings.append(
            f"n = {separate['n']}, H/h = {separate['Hh']}: the coarse problem's three parts take {coarse_separate:.1f} s "
            f"separate and {coarse_last:.1f} s contact-last, the whole scene {f(last, 'time_scene') / f(separate, 'time_scene'):.2f} "
            f"times as long; {'the same' if same else 'NOT the same'} Hessian count, energies {energy:.0e} apart (relative).")
    return lines + ["Reading: " + " ".join(readings), ""]


def mpi_section():
    """The optional MPI part's lines, when it has been run (--only mpi)."""
    if not os.path.exists(os.path.join(OUT, f"{PAGE}-{table('mpi')}.csv")):
        return []
    rows, run_row = read_csv(PAGE, table("mpi")), read_csv(PAGE, table("mpi-run"))[0]
    serial, ranks = rows
    same = serial["hessian"] == ranks["hessian"] and serial["active"] == ranks["active"]
    energy = abs(f(ranks, "energy") - f(serial, "energy")) / abs(f(serial, "energy"))
    return [
        f"## 3D elasticity on two MPI ranks, n = {serial['n']}",
        "",
        "`mpirun -np 2 FreeFem++-mpi edp/cubes-elasticity-3d.edp`: each rank meshes (`ffetiGrid3Owned`),",
        "assembles and factorizes its own boxes and holds the whole coarse problem; beside one process, one run after the other"
        f" ({run_machine(run_row)}, {run_row['date']}, load average {float(run_row['load_at_start']):.1f} as it started). Peak MB per",
        "rank: each rank's own resident set (the RANK lines).",
        "",
        *markdown_table(rows, [
            ("run", "case"), ("Hessian mult.", "hessian"), ("active", "active"), ("energy", "energy"),
            ("assembly [s]", ("time_assembly", ".2f")), ("plugin set-up [s]", ("time_plugin_setup", ".2f")),
            ("factorization [s]", ("time_factor", ".2f")), ("dual solve [s]", ("time_solve", ".2f")),
            ("whole scene [s]", ("time_scene", ".2f")), ("peak MB per rank", "rank_peak_mb"), ("status", "status")]),
        "",
        f"Reading: the two runs {'give the same' if same else 'do NOT give the same'} Hessian count and contact set; "
        f"their energies differ by {energy:.0e} (relative). The whole scene takes "
        f"{f(ranks, 'time_scene') / f(serial, 'time_scene'):.2f} times one process's time on two ranks.",
        "",
    ]
