#!/usr/bin/env python3
"""Friction (edp/cattaneo-mindlin.edp, edp/block-on-slope.edp): Cattaneo-Mindlin partial slip
against the analytic tractions for three Q/(mu P), the stick/slip map, the Coulomb fixed
point's iterations and Hessian multiplications against the frictionless solve of the same
scene, their growth with h at fixed subdomain size, the block on a slope, the cost of
every friction scene before and after the change of how Coulomb's law is solved (scripts/friction_cost.py),
and the sphere in three dimensions (scripts/friction_3d.py). Writes docs/results/friction.md
and its plots from one run on this machine."""
import argparse
import os
import tempfile

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

import friction_3d  # noqa: E402
import friction_cost  # noqa: E402
from ffeti_bench import (OUT, ROOT, begin_run, end_run, f, forget_run, listing, machine_line,  # noqa: E402
                         markdown_table, read_csv, run, save_page, span, write_csv)

PAGE = "friction"
RATIOS = [0.3, 0.6, 0.9]
SIZES = [0.4, 0.2, 0.1, 0.05]
PART_SIZE = 1500  # triangles per subdomain in the refinement: H/h fixed
MESHES = os.path.join(ROOT, "meshes")
SLOPE_CASES = [("Coulomb, tan θ < μ", ["-theta", 15, "-mu", 0.5]), ("Coulomb, tan θ > μ", ["-theta", 30, "-mu", 0.5]),
               ("Tresca below the load, stop", ["-law", "tresca"]),
               ("Tresca below the load, no stop", ["-law", "tresca", "-stop", 0])]


def ratio(row, key, reference):
    return f(row, key) / f(row, reference)


MINDLIN = [("Q/(μP)", ("q_ratio", ".3f")), ("c/a", ("stick_ratio", ".4f")), ("analytic", ("stick_ratio_analytic", ".4f")),
           ("error", ("stick_ratio_error", ".1%")), ("stick zone centre [mm]", ("stick_centre", ".2f")),
           ("a [mm]", ("a", ".3f")), ("a Hertz", ("a_hertz", ".3f")),
           ("Σλ_t vs Q", ("balance_error", ".1e")), ("L2 error p, q", lambda r: f"{r['pressure_l2']:.1%}, {r['shear_l2']:.1%}"), ("stick / slip rows", lambda r: f"{r['sticking']} / {r['slipping']}"),
           ("Tresca solves: step 1, 2", lambda r: f"{r['fixed_point_iterations_step1']}, {r['fixed_point_iterations']}"),
           ("Hessian: step 1, 2", lambda r: f"{r['hessian_step1']}, {r['hessian']}"),
           ("frictionless", "hessian_frictionless"),
           ("step 2 / frictionless", lambda r: f"{ratio(r, 'hessian', 'hessian_frictionless'):.2f}"),
           ("solve step 2 [s]", ("time_solve", ".3f")), ("status", "status")]
REFINEMENT = [("h [mm]", "h"), ("unknowns", "unknowns"), ("subdomains", "subdomains"), ("couples", "couples"),
              ("c/a", ("stick_ratio", ".4f")), ("c/a error", ("stick_ratio_error", ".2%")),
              ("stick zone centre [mm]", ("stick_centre", ".2f")),
              ("Tresca solves: step 1, 2", lambda r: f"{r['fixed_point_iterations_step1']}, {r['fixed_point_iterations']}"),
              ("Hessian: step 1, 2", lambda r: f"{r['hessian_step1']}, {r['hessian']}"),
              ("frictionless", "hessian_frictionless"),
              ("(step 1 + 2) / frictionless",
               lambda r: f"{(f(r, 'hessian_step1') + f(r, 'hessian')) / f(r, 'hessian_frictionless'):.2f}"),
              ("solve step 2 [s]", ("time_solve", ".3f")), ("factor [s]", ("time_factor", ".3f")), ("status", "status")]
SLOPE = [("case", "case"), ("tan θ", ("tan_theta", ".3f")), ("μ or g per row", lambda r: r["mu"] if r["law"] == "coulomb"
                                                               else f"g = {f(r, 'bound_per_row'):.1f} N/m"),
         ("rows closed / stick / slip", lambda r: f"{r['closed']} / {r['sticking']} / {r['slipping']}"),
         ("friction force / W sin θ", lambda r: f"{ratio(r, 'friction_force', 'weight_tangential'):.4f}"),
         ("normal force / W cos θ", lambda r: f"{ratio(r, 'normal_force', 'weight_normal'):.10f}"),
         ("slipping rows at g (rel. error)", ("at_bound_error", ".0e")),
         ("Tresca solves", "fixed_point_iterations"), ("Hessian", "hessian"), ("status", "status")]


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--render", action="store_true", help="re-render the page from its CSVs, no run")
    if not parser.parse_args().render:
        begun = begin_run()
        mindlin, tractions, refinement, slope = [], [], [], []
        with tempfile.TemporaryDirectory() as scratch:
            for q in RATIOS:
                table = os.path.join(scratch, f"tractions-{q}.csv")
                mindlin.append(run("cattaneo-mindlin.edp", "-q", q, "-meshes", MESHES, "-table", table)["RESULT"][0])
                with open(table) as rows:
                    header = rows.readline().strip().split(",")
                    tractions += [dict(q=q, **dict(zip(header, line.strip().split(",")))) for line in rows]
        for h in SIZES:
            refinement.append(run("cattaneo-mindlin.edp", "-h", h, "-partsize", PART_SIZE, "-meshes", MESHES)["RESULT"][0])
        for name, args in SLOPE_CASES:
            slope.append(dict(case=name, **run("block-on-slope.edp", *args)["RESULT"][0]))
        friction_3d.measure(MESHES)
        write_csv(PAGE, "cattaneo-mindlin", mindlin)
        write_csv(PAGE, "tractions", tractions)
        write_csv(PAGE, "refinement", refinement)
        write_csv(PAGE, "slope", slope)
        write_csv(PAGE, "cost", friction_cost.measure())
        forget_run(PAGE, friction_cost.OWN_RUN)
        end_run(PAGE, begun)
    render()


def write_tractions(tractions):
    fig, axes = plt.subplots(1, len(RATIOS), figsize=(12, 3.8), sharey=True)
    for ax, q in zip(axes, RATIOS):
        rows = [r for r in tractions if float(r["q"]) == q]
        x = [f(r, "x") for r in rows]
        ax.plot(x, [f(r, "pressure_hertz") for r in rows], "k-", lw=1, label="Hertz p")
        ax.plot(x, [f(r, "shear_mindlin") for r in rows], "k--", lw=1, label="Mindlin q")
        ax.plot(x, [f(r, "pressure") for r in rows], "o", ms=2.5, color="tab:blue", label="ffeti p")
        ax.plot(x, [f(r, "shear") for r in rows], "s", ms=2.5, color="tab:red", label="ffeti |q|")
        ax.set_title(f"Q/(μP) = {q}")
        ax.set_xlabel("x [mm]")
    axes[0].set_ylabel("traction [MPa]")
    axes[0].legend(fontsize=8)
    fig.suptitle("Cattaneo–Mindlin: contact pressure and shear traction, h = 0.1 mm")
    fig.tight_layout()
    fig.savefig(os.path.join(OUT, "friction-tractions.png"), dpi=110)
    plt.close(fig)


def write_states(tractions):
    colours = {0: "lightgrey", 1: "tab:blue", 2: "tab:red"}
    fig, ax = plt.subplots(figsize=(8, 2.6))
    for k, q in enumerate(RATIOS):
        rows = [r for r in tractions if float(r["q"]) == q]
        for state, name in ((0, "open"), (1, "stick"), (2, "slip")):
            xs = [f(r, "x") for r in rows if int(r["state"]) == state]
            ax.scatter(xs, [k] * len(xs), s=9, marker="s", color=colours[state], label=name if k == 0 else None)
    ax.set_yticks(range(len(RATIOS)))
    ax.set_yticklabels([f"Q/(μP) = {q}" for q in RATIOS])
    ax.set_xlabel("x [mm]")
    ax.set_title("Stick / slip / open per contact row")
    ax.legend(loc="center left", bbox_to_anchor=(1.01, 0.5), fontsize=8, frameon=False)
    ax.set_ylim(-0.5, len(RATIOS) - 0.5)
    fig.tight_layout()
    fig.savefig(os.path.join(OUT, "friction-states.png"), dpi=110)
    plt.close(fig)


def l2_error(tractions, q, value, analytic):
    """Relative L2 error of a traction against its analytic curve over the contact rows."""
    rows = [r for r in tractions if float(r["q"]) == q]
    error = sum((f(r, value) - f(r, analytic)) ** 2 for r in rows)
    return (error / sum(f(r, analytic) ** 2 for r in rows)) ** 0.5


def render():
    mindlin, tractions, refinement, slope = (read_csv(PAGE, t) for t in ("cattaneo-mindlin", "tractions", "refinement", "slope"))
    run_row = read_csv(PAGE, "run")[0]
    write_tractions(tractions)
    write_states(tractions)
    for r in mindlin:
        q = float(r["q_ratio"])
        q = min(RATIOS, key=lambda target: abs(target - q))
        r["pressure_l2"] = l2_error(tractions, q, "pressure", "pressure_hertz")
        r["shear_l2"] = l2_error(tractions, q, "shear", "shear_mindlin")
    step2 = [ratio(r, "hessian", "hessian_frictionless") for r in mindlin]
    step1 = [ratio(r, "hessian_step1", "hessian_frictionless") for r in mindlin]
    growth = [f(r, "hessian") for r in refinement]
    free = [f(r, "hessian_frictionless") for r in refinement]
    lines = [
        "# Friction: Cattaneo–Mindlin and a block on a slope",
        "",
        "Generated by `scripts/benchmark.sh friction` (do not edit by hand) on:",
        machine_line(run_row),
        "",
        "`edp/cattaneo-mindlin.edp`: plane strain, a half cylinder R = 50 mm on a block 200 x 100 mm,",
        "both E = 210 GPa, ν = 0.3 (elastically similar: the normal and the tangential problems",
        "decouple), Coulomb friction μ = 0.3, node-to-segment contact (slaves on the cylinder), Total",
        "FETI, gmsh meshes (`meshes/mindlin-*.geo`) of size h within 8 mm of the contact, 4 METIS",
        "subdomains per body, tol = 1e-6 (the default set-up and solve options otherwise). Step 1",
        "presses: the cylinder's top cut moves down by 0.8 mm and stays level; P is the sum of the",
        "contact forces. Step 2 (`fetiSetLoads`, a new load step) adds Q = (Q/(μP)) μ P spread over",
        "the top cut. The stick zone's half-width c lies halfway between the outermost sticking and",
        "the next slipping row, a the same between closed and open rows; both are read off the",
        "mesh. Analytic (Cattaneo 1938, Mindlin 1949): c/a = √(1 − Q/(μP)), a = √(4PR/(πE*)). The",
        "frictionless solve is step 1 of the same scene with the top cut also held in x (without",
        "friction nothing else holds the cylinder in x). Raw data:",
        f"[{PAGE}-cattaneo-mindlin.csv]({PAGE}-cattaneo-mindlin.csv), [{PAGE}-tractions.csv]({PAGE}-tractions.csv)",
        f"(per contact row), [{PAGE}-refinement.csv]({PAGE}-refinement.csv), [{PAGE}-slope.csv]({PAGE}-slope.csv).",
        "",
        "## Cattaneo–Mindlin on the default mesh (h = 0.1 mm)",
        "",
        *markdown_table(mindlin, MINDLIN),
        "",
        "![tractions](friction-tractions.png)",
        "",
        "![states](friction-states.png)",
        "",
        f"Reading: c/a is within {span([f(r, 'stick_ratio_error') for r in mindlin], '.1%')} of the analytic",
        "ratio, about the mesh's resolution of c (half a node spacing, 0.05 mm, over c). The",
        f"friction forces balance Q to {span([f(r, 'balance_error') for r in mindlin], '.0e')} (tol = 1e-6). The",
        f"pressure is Hertz's to {span([r['pressure_l2'] for r in mindlin], '.1%')} (relative L2 over the rows of",
        f"the picture), the shear Mindlin's to {span([r['shear_l2'] for r in mindlin], '.1%')}: its largest",
        "deviations are the rows next to the stick/slip boundary, where the analytic shear has a kink,",
        "and the narrow slip zone at Q/(μP) = 0.3, a few rows wide. The stick zone's centre lies",
        f"{span([-f(r, 'stick_centre') for r in mindlin], '.2f')} mm behind the axis (against the direction of Q), where",
        "Mindlin's half-spaces have it on the axis: under refinement it moves little (next table), so it is",
        "not the mesh; the bodies here are finite (a half cylinder loaded on its cut, a block 100 mm",
        "deep), which is the likely cause, not proven here. The tangential step costs",
        f"{span(step2, '.2f')} times the frictionless solve's Hessian multiplications over all its",
        f"Tresca solves and Newton steps (aim: at most 3), the pressing step {span(step1, '.2f')} times (its first",
        "Tresca solve sticks everywhere, as a solve without a previous step must; in this plane problem",
        "Coulomb's law is then solved by Newton steps, checked by one more Tresca solve:",
        "[algorithms](../algorithms.md#friction)).",
        "",
        f"## The same under refinement, subdomains of about {PART_SIZE} triangles (Q/(μP) = 0.6)",
        "",
        *markdown_table(refinement, REFINEMENT),
        "",
        f"Reading: the tangential step takes {listing([r['fixed_point_iterations'] for r in refinement])} Tresca solves"
        " (Newton steps between the first and the last)",
        f"at h = {listing([r['h'] for r in refinement])} mm"
        + (": it does not grow with h." if len({r['fixed_point_iterations'] for r in refinement}) == 1 else ".")
        + " Its Hessian",
        f"count grows from {growth[0]:.0f} to {growth[-1]:.0f}, as the frictionless solve's does ({free[0]:.0f} to",
        f"{free[-1]:.0f}): on these graded meshes the contact zone gains rows as h falls and subdomains of a",
        "fixed size do not make the count bounded (the frictionless count is not bounded either);",
        "the ratio of the two stays",
        f"{span([a / b for a, b in zip(growth, free)], '.2f')}. c/a stays within",
        f"{span([f(r, 'stick_ratio_error') for r in refinement], '.1%')} of the analytic ratio on every mesh.",
        "",
        "## A block on a slope (`edp/block-on-slope.edp`)",
        "",
        "A 2 x 1 m block (E = 10 MPa, ν = 0.3, ρg = 10 kN/m³, plane strain, 4 subdomains, 16 cells",
        "along the bottom: 17 contact rows) on a rigid slope; gravity tilted by θ. Coulomb: the block",
        "floats on the slope (Total FETI), held by friction alone. Tresca: a bound per row whose total",
        "is 5 % of W sin θ, the block's downhill face against a stop (u_x = 0) or free. tol = 1e-8.",
        "",
        *markdown_table(slope, SLOPE),
        "",
        "Reading: below tan θ = μ no row slips and the friction forces carry W sin θ exactly (to the",
        "tolerance); above it no forces within the bounds balance the weight, and the solve reports",
        "`infeasible` instead of an answer (the forces in that row are the least-norm multipliers,",
        "not a solution). With a Tresca bound below the load every row that can slip does, at its",
        "bound exactly (the row at the stop's corner cannot slip: its x displacement is fixed); without",
        "the stop there is no equilibrium.",
        "",
        *friction_cost.section(),
    ]
    save_page(f"{PAGE}.md", lines + friction_3d.section())


if __name__ == "__main__":
    main()
