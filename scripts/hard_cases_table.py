#!/usr/bin/env python3
"""The hard-case table: runs the hard-case suite (tests/unit/hard_cases_test.cpp, the CTest
tests named hard/...), the large-contact scene with thousands of couples and Hertz as nu
tends to 1/2, writes the rows each case records to docs/results/hard-cases-cases.csv; runs
friction at the onset of sliding (edp/friction-onset.edp, 2D and 3D, three mesh sizes each)
into docs/results/hard-cases-friction-onset.csv; renders docs/results/hard-cases.md from both. One command: ./scripts/benchmark.sh hard-cases
(--render: the page again from the CSVs, no run)."""
import argparse
import os
import subprocess
import tempfile
import xml.etree.ElementTree as ElementTree

from ffeti_bench import (ROOT, begin_run, end_run, f, machine_line, markdown_table, read_csv, run, save_page,
                         write_csv)

BUILD = os.environ.get("FFETI_BUILD", os.path.join(ROOT, "build"))


def suite_rows():
    """(test, scene, fields) for every row the GoogleTest hard cases record."""
    with tempfile.TemporaryDirectory() as folder:
        report = os.path.join(folder, "hard.xml")
        subprocess.run([os.path.join(BUILD, "tests", "ffeti_unit_tests"),
                        "--gtest_filter=HardCases.*:Factors/ExtremeScaling.*", f"--gtest_output=xml:{report}"],
                       check=True, capture_output=True, text=True)
        tree = ElementTree.parse(report)
    rows = []
    for case in tree.iter("testcase"):
        failed = case.find("failure") is not None
        for prop in case.iter("property"):
            name = prop.get("name", "")
            if name.startswith("row "):
                fields = dict(kv.split("=", 1) for kv in prop.get("value").split(";"))
                fields["test"] = "FAILED" if failed else "passed"
                rows.append((f"{case.get('classname')}.{case.get('name')}", name[4:], fields))
    return rows


def large_contact_row():
    r = run("large-contact.edp", "-n", 80, "-check", 1)["RESULT"][0]
    kkt = max(f(r, k) for k in ("kkt_equilibrium", "kkt_equality", "kkt_inequality", "kkt_complementarity"))
    fields = {"status": "converged" if r["status_code"] == "0" else "status " + r["status_code"], "path": "mprgp",
              "outer": "0", "hessian": r["hessian"], "kkt": kkt, "error": abs(f(r, "energy_error")),
              "check": "energy against the active set reference", "active": r["active"],
              "seconds": r["time_solve"], "test": "passed", "couples": r["couples"]}
    return ("ffeti edp/large-contact.edp -n 80 -check 1", f"{r['couples']} couples, about half active", fields)


HERTZ_TOL = "1e-4"
HERTZ_NU = (0.3, 0.45, 0.49, 0.499)


def incompressible_rows():
    """Hertz (plane strain, h = 0.5 mm) as nu tends to 1/2, P1 against P2 displacements."""
    rows = []
    for order in (1, 2):
        for nu in HERTZ_NU:
            r = run("hertz.edp", "-h", 0.5, "-nu", nu, "-order", order, "-tol", HERTZ_TOL, "-meshes", os.path.join(ROOT, "meshes"))["RESULT"][0]
            fields = {"status": r["status"], "path": "smalbe", "outer": r["outer"], "hessian": r["hessian"],
                      "kkt": r["kkt_max"], "error": r["pressure_l2_relerr"],
                      "check": "contact pressure against Hertz (relative L2)", "active": r["active"],
                      "seconds": r["time_solve"], "test": "-", "nu": nu, "order": order}
            rows.append(("edp/hertz.edp", f"Hertz, nu = {nu}, P{order}, tol {HERTZ_TOL}", fields))
    return rows


ONSET_PULLS = "0.5 0.9 0.99 0.999 1.001 1.2"
ONSET_TOL = "1e-6"
ONSET_SIZES = [(3, "-m", m) for m in (2, 4, 6)] + [(2, "-n", n) for n in (12, 24, 48)]


ONSET_METHODS = ["fixed-point", "newton"]  # fetiSolve's coulomb=; "auto" is Newton in 2D, the fixed point in 3D


def friction_onset_rows():
    """The block pulled along the floor by q mu W, q from 0.5 to 1.2, per dimension and size,
    with each way of solving Coulomb's law."""
    rows = []
    for dim, option, size in ONSET_SIZES:
        for method in ONSET_METHODS:
            out = run("friction-onset.edp", "-dim", dim, option, size, "-tol", ONSET_TOL, "-pulls", ONSET_PULLS,
                      "-coulomb", method)
            checks = [line for line in out["output"].splitlines() if line.startswith("FAILED")]
            for r in out["RESULT"]:
                r["checks"] = "failed" if any(f"q = {r['q']}:" in line for line in checks) else "passed"
                rows.append(r)
    return rows


def default_method(dim):
    """What coulomb = "auto" runs (docs/algorithms.md, "Coulomb by semismooth Newton")."""
    return "newton" if str(dim) == "2" else "fixed-point"


PAGE = "hard-cases"
COLUMNS = [("case", "scene"), ("path", "path"), ("status", "status"), ("outer", "outer"), ("Hessian mult.", "hessian"),
           ("KKT", ("kkt", ".3g")), ("error", ("error", ".3g")), ("check", "check"), ("contact", "active"),
           ("time [s]", ("seconds", ".3g")), ("test", "test")]


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--render", action="store_true", help="re-render the page from its CSVs, no run")
    if not parser.parse_args().render:
        begun = begin_run()
        rows = suite_rows() + [large_contact_row()] + incompressible_rows()
        write_csv(PAGE, "cases", [dict(source=source, scene=scene, **fields) for source, scene, fields in rows])
        write_csv(PAGE, "friction-onset", friction_onset_rows())
        end_run(PAGE, begun)
    render()


def onset_ratio(r):
    return f"{float(r['ratio']):.1f}" if r["status"] == "converged" else "-"


def onset_pairs(rows):
    """One row per pull: the fixed point's and Newton's runs side by side."""
    by_key = {(r["dim"], r["size"], r["q"], r["coulomb"]): r for r in rows}
    pulls = sorted({(r["dim"], r["size"], r["q"]) for r in rows},
                   key=lambda k: (-int(k[0]), int(k[1]), float(k[2])))
    return [(by_key[(*k, "fixed-point")], by_key[(*k, "newton")]) for k in pulls]


def onset_pull(fixed, newton):
    """One pull's table row: the fixed point's and Newton's runs, and the default's answer."""
    chosen = newton if default_method(fixed["dim"]) == "newton" else fixed
    return {"fixed": fixed, "newton": newton, "chosen": chosen, "converged": chosen["status"] == "converged"}


def chosen_number(key):
    """A cell of the default's answer, '-' where it did not converge."""
    return lambda p: f"{float(p['chosen'][key]):.1e}" if p["converged"] else "-"


ONSET_COLUMNS = [
    ("dim", lambda p: p["fixed"]["dim"]), ("mesh", lambda p: p["fixed"]["size"]), ("q = Q / (μW)", lambda p: p["fixed"]["q"]),
    ("status", lambda p: p["chosen"]["status"]), ("frictionless", lambda p: p["fixed"]["frictionless"]),
    ("fixed point: Hessian (ratio; Tresca solves)",
     lambda p: f"{p['fixed']['hessian']} ({onset_ratio(p['fixed'])}; {p['fixed']['fixed_point_iterations']})"),
    ("Newton: Hessian (ratio; steps, Tresca solves)",
     lambda p: f"{p['newton']['hessian']} ({onset_ratio(p['newton'])}; {p['newton']['newton_steps']}, "
               f"{p['newton']['fixed_point_iterations']})"),
    ("default", lambda p: default_method(p["fixed"]["dim"])),
    ("excess / W", chosen_number("excess")), ("balance", chosen_number("balance")),
    ("checks", lambda p: "passed" if p["fixed"]["checks"] == p["newton"]["checks"] == "passed" else "failed")]


def onset_table(rows):
    return markdown_table([onset_pull(*pair) for pair in onset_pairs(rows)], ONSET_COLUMNS)


def friction_onset_section():
    rows = read_csv(PAGE, "friction-onset")
    feasible = [r for r in rows if float(r["q"]) < 1]
    chosen = [r for r in feasible if r["coulomb"] == default_method(r["dim"])]
    worst = max(chosen, key=lambda r: float(r["ratio"]))

    def share(method, dim, q_low, q_high):
        mine = [float(r["ratio"]) for r in feasible
                if r["coulomb"] == method and r["dim"] == dim and q_low <= float(r["q"]) <= q_high]
        return f"{min(mine):.1f}-{max(mine):.1f}"

    def total(method):
        return sum(int(r["hessian"]) for r in feasible if r["coulomb"] == method)

    return [
        "## Friction at the onset of sliding",
        "",
        "Does it slip? An elastic block on a rigid floor with Coulomb friction μ = 0.4, step 1 its",
        "weight W, step 2 the weight and a pull Q = q μW (`edp/friction-onset.edp`; 3D: the 2 x 1 x 1",
        "block of lesson 12 in two boxes of m³ cells, pulled on its top at 30° from x; 2D: the",
        "2 x 1 block of lesson 9 in 2 x 2 subdomains, n cells along the bottom, pulled on its right",
        f"face), tol {ONSET_TOL}, default options otherwise, each pull solved twice: by the fixed point over",
        "Tresca solves (`coulomb = \"fixed-point\"`) and by semismooth Newton steps after its first solve",
        "(`coulomb = \"newton\"`); \"default\": what `coulomb = \"auto\"` runs (Newton in 2D, the fixed point",
        "in 3D), whose status, excess and balance are shown. \"frictionless\": the same loads with the",
        "bottom held tangentially (the Hessian multiplications of one frictionless contact solve);",
        "ratio: step 2's multiplications over it. Excess: the largest ‖λ_t‖ − μλ_n, per W (≤ 0:",
        "no friction force beyond its cone); balance: |Σλ_t − Q| / Q. Checks (`-check 1`, run by",
        "`ctest -R friction_onset`): q < 1 converges and meets both to 10 tol; q > 1 is reported",
        "infeasible at once, naming body 0; \"passed\" where both methods' runs passed. Raw data:",
        f"[{PAGE}-friction-onset.csv]({PAGE}-friction-onset.csv).",
        "",
        *onset_table(rows),
        "",
        "Reading: every pull up to 0.999 μW converged and met Coulomb's law by both methods; every pull",
        "above μW was reported infeasible without a multiplication, by the law's own statics check",
        "(forces within the friction cones balancing the loads, [algorithms](../algorithms.md#friction)).",
        f"With the default, {sum(float(r['ratio']) > 5 for r in chosen)} of the {len(chosen)} pulls cost more than "
        f"5 times the frictionless solve (the aim), up to {float(worst['ratio']):.1f} times ({worst['dim']}D, mesh "
        f"{worst['size']}, q = {worst['q']}). Newton took {share('newton', '2', 0, 1)} times the frictionless solve "
        f"in 2D against the fixed point's {share('fixed-point', '2', 0, 1)}; in 3D "
        f"{share('newton', '3', 0, 0.9)} against {share('fixed-point', '3', 0, 0.9)} at q ≤ 0.9 but "
        f"{share('newton', '3', 0.99, 1)} against {share('fixed-point', '3', 0.99, 1)} at q ≥ 0.99, where nearly every "
        "pair slips and Newton's slip directions turn over for several steps before they settle: hence the fixed "
        f"point in 3D. All pulls: {total('fixed-point')} multiplications by the fixed point, {total('newton')} by "
        "Newton. The fixed point's cost is its Tresca solves (the column above), each beginning with the body's",
        "balance broken by its new bounds; the first solve of a pull, from the weight's bounds, stops at 0.3 and",
        "settles its start in one face solve ([algorithms](../algorithms.md#friction); earlier figures: the",
        "[log](../log.md)).",
        "",
    ]


def render():
    rows, run_row = read_csv(PAGE, "cases"), read_csv(PAGE, "run")[0]
    hertz = {(r["order"], float(r["nu"])): r for r in rows if r["source"] == "edp/hertz.edp"}
    contrast = next(r for r in rows if r["scene"].startswith("stiffness contrast"))
    lines = [
        "# Hard cases",
        "",
        "Generated by `scripts/benchmark.sh hard-cases` (do not edit by hand) on:",
        machine_line(run_row),
        "",
        "Each row is one solve of the hard-case suite (`ctest -R hard` runs it as regression",
        "tests, `tests/unit/hard_cases_test.cpp`; the last rows are `edp/large-contact.edp` and",
        "`edp/hertz.edp`), with default options except the tolerance each test sets (1e-8 or 1e-10;",
        f"1e-4 for the large contact zone, its default, and {HERTZ_TOL} for Hertz). The Hertz rows show P1 locking as the",
        "material becomes nearly incompressible (plane strain) and P2 displacements (`-order 2`) as",
        "the remedy; their error includes the discretization's (the pressure is recovered from",
        f"nodal forces, which is cruder with P2: {f(hertz[('2', HERTZ_NU[0])], 'error'):.1%} at nu = {HERTZ_NU[0]} "
        f"against P1's {f(hertz[('1', HERTZ_NU[0])], 'error'):.1%});",
        f"`ctest -R hard` checks P2 at nu = {HERTZ_NU[-1]} against Hertz. KKT: the largest relative KKT",
        "residual recomputed in primal form; error: the distance to the independent answer named in",
        "\"check\" (relative unless it is u = 0 or an energy shift); time: norm estimate and dual",
        "solve, seconds. \"test\": whether the test's assertions held in this run. Raw data:",
        f"[{PAGE}-cases.csv]({PAGE}-cases.csv).",
        "",
        "Where a test asks for a tolerance below the scene's round-off floor, its count is decided",
        "by round-off: the stiffness contrast (K scaled by 1e6) returns a KKT residual of",
        f"{f(contrast, 'kkt'):.3g} in this run, after {contrast['hessian']} multiplications.",
        "",
        *markdown_table(rows, COLUMNS),
        "",
        "Hertz's curved contact boundary is the curved node-to-segment case.",
        "",
        *friction_onset_section(),
    ]
    save_page(f"{PAGE}.md", lines)


if __name__ == "__main__":
    main()
