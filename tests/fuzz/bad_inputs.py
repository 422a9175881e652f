#!/usr/bin/env python3
"""Bad inputs, generated, against both front ends: random mutations of a valid problem.

ffeti-solve: a valid GetDP problem file (getdp/hertz.json on GetDP's assembly, and in three
dimensions getdp/sphere-block.json, a quarter as many cases: its solves take seconds) with one
value replaced (by null, a wrong type, 0, -1, a huge or tiny number, an integer beyond
int, an empty list or object), a key deleted or an unknown key added. The plugin: a
valid two-membrane script with one argument of fetiSetup, fetiSolve, fetiSensitivity or
fetiContactPressure replaced by a bad value; "plugin 3D": two blocks in node-to-face contact
with a gap per row (contactGap) whose derivative (dGap) is the design, given friction,
planes, balls, reversed or broken faces, scaled or broken coordinates.

Every case must end as one of: a clear refusal (ffeti-solve: exit status 2 and a message
naming the problem file or a data file; FreeFEM: an "Exec error" naming the plugin
function and an argument), or a run that completes (exit 0 or 1, with a RESULT line).
Never a signal (crash), a hang (time limit), an uncaught exception or exit 3. A found
class of bad input gets its own test in tests/edp/bad-input.edp or tests/getdp/bad-input.sh.

Usage: bad_inputs.py SOURCE_DIR FFETI_SOLVE [--cases N] [--seed S] [--report FILE]
(run where freefem++.pref points at the build; N cases per front end, default 40, N/4 for the
3D problem file; "macros": the grid macros of ffeti.idp and ffetiLame with one bad argument each, as many;
--report writes the run's counts and failures as a Markdown page)."""
import argparse
import collections
import copy
import json
import os
import random
import re
import shutil
import subprocess
import sys
import tempfile

LIMIT = 120  # seconds per case: a hang is a failure

BAD_VALUES = [None, "text", True, [], {}, 0, -1, 1.5, 1e308, -1e308, 1e-320, 2 ** 31, 2 ** 63 - 1, -(2 ** 31) - 1,
              [1e308], [-1], ["x"], [2 ** 40]]


def paths(node, prefix=()):
    """Every (path, value) inside a JSON tree, objects by key and lists by index."""
    yield prefix, node
    if isinstance(node, dict):
        for key, value in node.items():
            yield from paths(value, prefix + (key,))
    elif isinstance(node, list):
        for index, value in enumerate(node):
            yield from paths(value, prefix + (index,))


def mutate(problem, rng):
    """One mutation of a copy of `problem`: (description, mutated problem)."""
    p = copy.deepcopy(problem)
    candidates = [path for path, _ in paths(p) if path]
    path = rng.choice(candidates)
    parent = p
    for step in path[:-1]:
        parent = parent[step]
    last = path[-1]
    kind = rng.random()
    if kind < 0.15 and isinstance(parent, dict):
        del parent[last]
        return f"delete {'.'.join(map(str, path))}", p
    if kind < 0.25 and isinstance(parent, dict):
        parent["no_such_key"] = 1
        return f"unknown key beside {'.'.join(map(str, path))}", p
    value = rng.choice(BAD_VALUES)
    parent[last] = value
    return f"{'.'.join(map(str, path))} = {json.dumps(value)}", p


# ffeti-solve's problems: (front end's name, problem, gmsh dimension, geometry): the plane
# Hertz pair, and in three dimensions the sphere on a block (node to face, a gap, volumes).
SOLVER_PROBLEMS = {"ffeti-solve": ("hertz", "-2", "hertz-pair.geo"), "ffeti-solve 3D": ("sphere-block", "-3", "sphere-block.geo")}


def solver_cases(source, ffeti_solve, count, rng, work, verdicts, front="ffeti-solve"):
    """ffeti-solve on `count` mutated problem files; returns the failures."""
    if not shutil.which("getdp"):
        print(f"{front}: skipped (getdp is not installed)")
        return []
    name, dimension, geometry = SOLVER_PROBLEMS[front]
    for suffix in (".pro", ".json"):
        shutil.copy(os.path.join(source, "getdp", name + suffix), work)
    subprocess.run(["gmsh", dimension, "-format", "msh22", "-v", "0", os.path.join(source, "meshes", geometry),
                    "-o", name + ".msh"], cwd=work, check=True)
    subprocess.run(["getdp", name + ".pro", "-msh", name + ".msh", "-solve", "Assemble", "-v", "0"], cwd=work,
                   check=True, capture_output=True)
    problem = json.load(open(os.path.join(work, name + ".json")))
    problem["output"] = {"table": "out.csv"}
    failures = []
    for case in range(count):
        what, mutated = mutate(problem, rng)
        with open(os.path.join(work, "case.json"), "w") as file:
            json.dump(mutated, file)
        try:
            run = subprocess.run([ffeti_solve, "case.json"], cwd=work, capture_output=True, text=True, timeout=LIMIT)
        except subprocess.TimeoutExpired:
            failures.append(f"{front} case {case} ({what}): no answer within {LIMIT} s")
            continue
        message = (run.stdout + run.stderr).strip().splitlines()
        last = message[-1] if message else ""
        if run.returncode == 2 and re.search(r"ffeti-solve: \S+: ", last):
            verdict = "refused"
        elif run.returncode in (0, 1) and "RESULT " in run.stdout:
            verdict = "ran" if run.returncode == 0 else "not converged"
        else:
            failures.append(f"{front} case {case} ({what}): exit status {run.returncode}: {last[:300]}")
            continue
        verdicts[front, verdict] += 1
        print(f"ok: {front} {what}: {verdict}: {last[:160]}")
    return failures


SCRIPT = r"""
include "ffeti.idp"
int N = 1, m = 8, S = 2;
mesh[int] Th(S);
ffetiGrid(Th, 0, 0., 0., 1., 1., N, N, m)
ffetiGrid(Th, 1, 1., 0., 1., 1., N, N, m)
matrix[int] K(S), dK(S);
real[int][int] F(S), X(S), Y(S), U(S), Z(S), dF(S), Share(S), Pr(S);
int[int] body(S);
int[int][int] fixed(S), slave(S), master(S);
for (int s = 0; s < S; ++s) {
  fespace Vh(Th[s], P1);
  varf vK(u, v) = int2d(Th[s])(dx(u) * dx(v) + dy(u) * dy(v));
  varf vF(u, v) = int2d(Th[s])(-1. * v);
  varf vS(u, v) = int1d(Th[s], 2, 4)(v);
  ffetiAssemble(Vh, s, vK, vF, K, F)
  ffetiCoordinates(Vh, X[s], Y[s])
  body[s] = s;
  Share[s].resize(Vh.ndof);
  Share[s] = vS(0, Vh);
  dF[s].resize(Vh.ndof);
  dF[s] = 0;
  ffetiDofsWhere(Vh, s == 0 && x < 1e-10, fixed[s])
  ffetiDofsWhere(Vh, s == 0 && abs(x - 1) < 1e-10, slave[s])
  ffetiDofsWhere(Vh, s == 1 && abs(x - 1) < 1e-10, master[s])
}
real[int] zeroNormal = [0., 0., 0., 0.];
@MUTATION@
int P = fetiSetup(K, F, X, Y, body, dirichlet = fixed, contactSlave = slave, contactMaster = master@SETUP@);
int status = fetiSolve(P, U@SOLVE@);
cout << "RESULT status=" << status << endl;
if (status == 0) {
  int rows = fetiContactPressure(P, Share, Pr);
  int st = fetiSensitivity(P, dK, dF, Z@SENS@);
  cout << "RESULT sensitivity=" << st << " rows=" << rows << endl;
}
"""

# (where, text): a named argument added to a call, or a statement that spoils the data.
SCRIPT_MUTATIONS = [
    ("SOLVE", ", tol = 0"), ("SOLVE", ", tol = -1"), ("SOLVE", ", tol = 1e308"), ("SOLVE", ", tol = sqrt(-1.)"),
    ("SOLVE", ", maxit = 0"), ("SOLVE", ", maxit = -7"), ("SOLVE", ", maxit = 65536 * 65536"),
    ("SOLVE", ", rho = 1e308 * 10"), ("SOLVE", ", rho = -1"), ("SOLVE", ", M = 0"), ("SOLVE", ", eta = -1"),
    ("SOLVE", ", gamma = 0"), ("SOLVE", ", algorithm = \"fast\""), ("SOLVE", ", stop = \"\""),
    ("SOLVE", ", settle = -3"), ("SOLVE", ", coarse = \"none\""), ("SOLVE", ", expansion = \"x\""),
    ("SOLVE", ", history = \"/no/such/folder/h.csv\""), ("SETUP", ", threads = 100000"), ("SETUP", ", threads = -2"),
    ("SETUP", ", variant = \"feti3\""), ("SETUP", ", factor = \"lu\""), ("SETUP", ", preconditioner = \"\""),
    ("SETUP", ", gap = 1e308 * 10"), ("SETUP", ", gap = -1e300"), ("SETUP", ", contactRadius = -1"),
    ("SETUP", ", obstacle = zeroNormal"), ("SETUP", ", friction = -0.2"), ("SETUP", ", friction = sqrt(-1.)"),
    ("SETUP", ", friction = 0.3"), ("SETUP", ", slipBound = 1e308 * 10"), ("SENS", ", activeTol = 2"), ("SENS", ", activeTol = 0"),
    ("SENS", ", maxit = 0"), ("SENS", ", tol = -1"),
    ("MUTATION", "F[1][3] = sqrt(-1.);"), ("MUTATION", "F[0] = 1e308; F[0] *= 10;"), ("MUTATION", "X[1][2] = sqrt(-1.);"),
    ("MUTATION", "F[1].resize(3);"), ("MUTATION", "body[1] = -1;"), ("MUTATION", "body[1] = 0;"),
    ("MUTATION", "fixed[0].resize(1); fixed[0][0] = 100000;"), ("MUTATION", "slave[0].resize(1); slave[0][0] = -5;"),
    ("MUTATION", "Share[1].resize(2);"), ("MUTATION", "dF[1].resize(1);"), ("MUTATION", "dF[0][0] = 1e308 * 10;"),
    ("MUTATION", "Y[0] = X[0];"), ("MUTATION", "K[1] = 0 * K[1];"), ("MUTATION", "K[0] = -1 * K[0];"),
    ("MUTATION", "master[1].resize(0);"), ("MUTATION", "fixed[0].resize(0);"),
]


# Three dimensions: two blocks, the upper one's bottom nodes against the lower one's top
# faces (node to face), with a gap per row (contactGap) as a design (dGap), friction
# mutations and the 3D-only arguments (Z, component, faces, planes, balls).
SCRIPT3 = r"""
include "ffeti.idp"
include "elasticity.idp"
int S = 2;
mesh3[int] Th(S);
Th[0] = cube(2, 2, 2);
Th[1] = cube(2, 2, 2, [x, y, z - 1.001]);
matrix[int] K(S), dK(S);
real[int][int] F(S), X(S), Y(S), Z(S), U(S), dF(S), G(S), dG(S), Share(S), Pr(S), Zs(S);
int[int] body = [0, 1];
int[int][int] fixed(S), component(S), slave(S), faces(S), noFaces(S);
for (int s = 0; s < S; ++s) {
  fespace Vh(Th[s], [P13d, P13d, P13d]);
  varf vK([u1, u2, u3], [v1, v2, v3]) = ffetiElasticity3(Th[s], 100., 0.3);
  varf vF([u1, u2, u3], [v1, v2, v3]) = int3d(Th[s])(-1. * v3);
  varf vS([u1, u2, u3], [v1, v2, v3]) = int2d(Th[s], 5)(v1 + v2 + v3);
  ffetiAssemble(Vh, s, vK, vF, K, F)
  ffetiVectorCoordinates3(Vh, X[s], Y[s], Z[s], component[s])
  // The lower block's bottom fixed, the upper one's top held in x and y: the contact holds it in z.
  ffetiVectorDofsWhere3(Vh, (s == 1 && z < -1.001 + 1e-10) || (s == 0 && z > 1 - 1e-10),
                        (s == 1 && z < -1.001 + 1e-10) || (s == 0 && z > 1 - 1e-10), s == 1 && z < -1.001 + 1e-10, fixed[s])
  ffetiVectorDofsWhere3(Vh, s == 0 && z < 1e-10, s == 0 && z < 1e-10, s == 0 && z < 1e-10, slave[s])
  faces[s].resize(0);
  if (s == 1) ffetiBoundaryFaces(Th[s], Vh, X[s], Y[s], Z[s], component[s], 6, faces[s])
  noFaces[s].resize(0);
  G[s].resize(Vh.ndof); G[s] = 0;
  dG[s].resize(Vh.ndof); dG[s] = 1e-4;
  dF[s].resize(Vh.ndof); dF[s] = 0;
  Share[s].resize(Vh.ndof); Share[s] = vS(0, Vh);
  dK[s] = 0 * K[s];
}
real[int] plane = [0., 0., -0.001, 0., 0., 1.], line = [0., 0., 0., 1.], ball = [0.5, 0.5, -1., 0.9];
real[int] intoBody = [0., 0., -0.001, 0., 0., -1.];
@MUTATION@
int P = fetiSetup(K, F, X, Y, body, Z = Z, component = component, dirichlet = fixed, contactSlave = slave,
                  contactFaces = faces, contactGap = G@SETUP@);
int status = fetiSolve(P, U@SOLVE@);
cout << "RESULT status=" << status << endl;
if (status == 0) {
  int rows = fetiContactPressure(P, Share, Pr);
  int st = fetiSensitivity(P, dK, dF, Zs, dGap = dG@SENS@);
  cout << "RESULT sensitivity=" << st << " rows=" << rows << endl;
}
"""

SCRIPT3_MUTATIONS = [
    ("SETUP", ", friction = 0.3"), ("SETUP", ", friction = -0.3"), ("SETUP", ", slipBound = 0.01"),
    ("SETUP", ", friction = 0.3, slipBound = 1"), ("SETUP", ", contactRadius = 1e-9"), ("SETUP", ", contactRadius = 0.0005"),
    ("SETUP", ", obstacle = line"), ("SETUP", ", obstacleBall = ball"), ("SETUP", ", obstacle = plane"),
    ("SETUP", ", contactSlaveFaces = faces"), ("SETUP", ", frictionField = G"), ("SETUP", ", threads = 1"),
    ("SOLVE", ", tol = 0"), ("SOLVE", ", maxit = 3"), ("SOLVE", ", algorithm = \"smalbe\""), ("SENS", ", tol = -1"),
    ("SENS", ", velocityZ = dG"), ("SENS", ", velocityX = dG, velocityY = dG"),
    ("MUTATION", "Z[1][0] = sqrt(-1.);"), ("MUTATION", "Z[0].resize(3);"), ("MUTATION", "component[0][0] = 5;"),
    ("MUTATION", "component[1][3] = 0;"), ("MUTATION", "Z[0] = 1000 * Z[0];"), ("MUTATION", "Z[1] = 0 * Z[1];"),
    ("MUTATION", "faces[1][4] = faces[1][7];"), ("MUTATION", "faces[1].resize(8);"), ("MUTATION", "faces[1][0] = -1;"),
    ("MUTATION", "{ int t = faces[1][3]; faces[1][3] = faces[1][6]; faces[1][6] = t; t = faces[1][4]; "
                 "faces[1][4] = faces[1][7]; faces[1][7] = t; t = faces[1][5]; faces[1][5] = faces[1][8]; faces[1][8] = t; }"),
    ("MUTATION", "faces[0].resize(faces[1].n); faces[0] = faces[1];"), ("MUTATION", "slave[0].resize(1);"),
    ("MUTATION", "G[0].resize(5);"), ("MUTATION", "G[0] = -1e300;"), ("MUTATION", "G[0][0] = sqrt(-1.);"),
    ("MUTATION", "dG[0].resize(2);"), ("MUTATION", "dG[1][0] = 1e308 * 10;"), ("MUTATION", "plane = intoBody;"),
    ("MUTATION", "fixed[1].resize(0);"), ("MUTATION", "body[1] = 0;"), ("MUTATION", "F[0] = -1 * F[0];"),
    ("MUTATION", "Share[0].resize(4);"), ("MUTATION", "X[0][1] = X[0][0];"),
]


# The installed macros that take numbers (the grid macros, ffetiLame): one argument of one
# call replaced by a bad value. The macro must stop with an "ffeti: <macro>: <argument> ..."
# line (an assert), or build boxes the set-up takes; an empty mesh array reaching the next
# macro crashed FreeFEM, nu = 0.5 gave lambda = inf. The 3D grid is built by one of
# ffetiGrid3Where, ffetiGrid3 and ffetiGrid3Owned (@GRID3@), chosen per case.
MACRO_SCRIPT = r"""
include "ffeti.idp"
include "elasticity.idp"
int S = 8;
mesh3[int] Th(S);
mesh[int] T2(4);
real lameLambda, lameMu;
ffetiLame(@E@, @nu@, false, lameLambda, lameMu)
@GRID3@
ffetiGrid(T2, 0, @x0@, 0., @Lx@, 1., @Nx@, 2, @m@)
matrix[int] K(S);
real[int][int] F(S), X(S), Y(S), Z(S), U(S);
int[int] body(S);
for (int s = 0; s < S; ++s) {
  fespace Vh(Th[s], P13d);
  varf vK(u, v) = int3d(Th[s])(dx(u) * dx(v) + dy(u) * dy(v) + dz(u) * dz(v)) + on(1, u = 0);
  varf vF(u, v) = int3d(Th[s])(v);
  ffetiAssemble(Vh, s, vK, vF, K, F)
  ffetiCoordinates3(Vh, X[s], Y[s], Z[s])
  body[s] = s;
}
int P = fetiSetup(K, F, X, Y, body, Z = Z);
cout << "RESULT status=" << fetiSolve(P, U) << endl;
"""
MACRO_ARGUMENTS = {"first": "0", "x0": "0.", "y0": "0.", "z0": "0.", "Lx": "1.", "Ly": "1.", "Lz": "1.", "Nx": "2",
                   "Ny": "2", "Nz": "2", "m": "2", "keep": "1", "E": "1.", "nu": "0.3"}
MACRO_BAD_VALUES = {"first": ["-1"], "x0": ["sqrt(-1.)", "1e308 * 10"], "y0": ["sqrt(-1.)"], "z0": ["1e308 * 10"],
                    "Lx": ["0.", "-1.", "sqrt(-1.)", "1e308 * 10"], "Ly": ["0.", "sqrt(-1.)"], "Lz": ["-1."],
                    "Nx": ["0", "-3"], "Ny": ["0"], "Nz": ["-1"], "m": ["0", "-1"], "keep": ["0", "ffS > 100"],
                    "E": ["0.", "-1.", "sqrt(-1.)", "1e308 * 10"], "nu": ["0.5", "-1.", "0.7", "sqrt(-1.)"]}
GRID3 = "(Th, @first@, @x0@, @y0@, @z0@, @Lx@, @Ly@, @Lz@, @Nx@, @Ny@, @Nz@, @m@"


def run_case(front, case, what, path, work, refused, verdicts, failures):
    """Runs one generated script and files its verdict: `refused(output)` is the text of a
    clear refusal, or None; otherwise it must run to a RESULT line."""
    try:
        run = subprocess.run(["FreeFem++-nw", "-v", "0", path], cwd=work, capture_output=True, text=True,
                             timeout=LIMIT)
    except subprocess.TimeoutExpired:
        failures.append(f"{front} case {case} ({what}): no answer within {LIMIT} s")
        return
    output = run.stdout + run.stderr
    refusal = refused(output)
    if refusal:
        verdicts[front, "refused"] += 1
        print(f"ok: {front} {what}: refused: {refusal[:160]}")
    elif run.returncode == 0 and "RESULT status=" in output:
        verdicts[front, "ran"] += 1
        print(f"ok: {front} {what}: ran: {' '.join(re.findall(r'RESULT (.*)', output))}")
    else:
        tail = " | ".join(output.strip().splitlines()[-3:])
        failures.append(f"{front} case {case} ({what}): exit status {run.returncode}: {tail[:300]}")


def macro_cases(count, rng, work, verdicts, front="macros"):
    """The macros with one bad argument; returns the failures."""
    failures = []
    for case in range(count):
        name = rng.choice(sorted(MACRO_BAD_VALUES))
        value = rng.choice(MACRO_BAD_VALUES[name])
        grid = "ffetiGrid3Where" if name == "keep" else rng.choice(["ffetiGrid3Where", "ffetiGrid3", "ffetiGrid3Owned"])
        text = MACRO_SCRIPT.replace("@GRID3@", grid + GRID3 + (", @keep@)" if grid == "ffetiGrid3Where" else ")"))
        for argument, good in MACRO_ARGUMENTS.items():
            text = text.replace(f"@{argument}@", value if argument == name else good)
        path = os.path.join(work, f"macro{case}.edp")
        with open(path, "w") as file:
            file.write(text)
        what = f"{name} = {value}" + ("" if name in ("E", "nu") else f" ({grid})")

        def refused(output):
            refusal = re.search(r"ffeti: (ffetiGrid3?|ffetiLame): (\w+)[ =(].*", output)
            return refusal.group(0) if refusal and refusal.group(2) == name and "exec assert" in output else None
        run_case(front, case, what, path, work, refused, verdicts, failures)
    return failures


def plugin_refusal(output):
    """The plugin's refusal naming its function and an argument, or None."""
    error = re.search(r"Exec error : (feti\w+: \w+[\[\]0-9, \w]*: .*)", output)
    return error.group(1) if error else None


def script_cases(count, rng, work, verdicts, script=SCRIPT, mutations=SCRIPT_MUTATIONS, front="plugin"):
    """FreeFEM scripts with one or two bad arguments; returns the failures."""
    failures = []
    for case in range(count):
        chosen = rng.sample(mutations, rng.choice([1, 1, 2]))
        names = [set(re.findall(r"(\w+) =", insert)) for where, insert in chosen if where != "MUTATION"]
        if len(names) == 2 and names[0] & names[1]:
            chosen = chosen[:1]  # one named argument given twice does not compile
        text = script
        for where, insert in chosen:
            text = text.replace(f"@{where}@", insert + f"@{where}@")
        text = re.sub(r"@[A-Z]+@", "", text)
        what = " + ".join(insert for _, insert in chosen)
        path = os.path.join(work, f"case{case}.edp")
        with open(path, "w") as file:
            file.write(text)
        run_case(front, case, what, path, work, plugin_refusal, verdicts, failures)
    return failures


def write_report(args, verdicts, failures):
    lines = ["# Generated bad inputs", "",
             f"Generated by `tests/fuzz/bad_inputs.py --cases {args.cases} --seed {args.seed} --report ...` (do not",
             "edit by hand): random mutations of a valid problem against both front ends (the",
             "generator's docstring says which). Every case must be refused with a message naming",
             "the argument (or file and key), or run to a RESULT line; a crash, a hang, an",
             "uncaught exception or an unclear refusal is a failure. The default test command runs",
             "40 cases per front end, 10 for the 3D problem file and 10 for the macros (the grids, ffetiLame; `ctest -R fuzz`).", "",
             "| front end | refused clearly | ran to a RESULT line (exit 0) | ran, not converged (exit 1) | failures |",
             "|---|---|---|---|---|"]
    for front in ("plugin", "plugin 3D", "ffeti-solve", "ffeti-solve 3D", "macros"):
        failed = sum(1 for f in failures if f.startswith(front + " case"))
        lines.append(f"| {front} | {verdicts[front, 'refused']} | {verdicts[front, 'ran']} | "
                     f"{verdicts[front, 'not converged']} | {failed} |")
    lines += ["", "Failures:" if failures else "No failures.", ""] + [f"- {f}" for f in failures] + [""]
    with open(args.report, "w") as page:
        page.write("\n".join(lines))


def solid_cases(cases):
    """The 3D problem file takes seconds per solve: a quarter as many cases."""
    return max(cases // 4, 5)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("source")
    parser.add_argument("ffeti_solve")
    parser.add_argument("--cases", type=int, default=40)
    parser.add_argument("--seed", type=int, default=20261125)
    parser.add_argument("--report", default="")
    args = parser.parse_args()
    rng = random.Random(args.seed)
    verdicts = collections.Counter()
    with tempfile.TemporaryDirectory() as work:
        if os.path.exists("freefem++.pref"):
            shutil.copy("freefem++.pref", work)
        failures = (script_cases(args.cases, rng, work, verdicts) +
                    script_cases(args.cases, rng, work, verdicts, SCRIPT3, SCRIPT3_MUTATIONS, "plugin 3D") +
                    solver_cases(args.source, args.ffeti_solve, args.cases, rng, work, verdicts) +
                    solver_cases(args.source, args.ffeti_solve, solid_cases(args.cases), rng, work, verdicts,
                                 "ffeti-solve 3D") +
                    macro_cases(solid_cases(args.cases), rng, work, verdicts))
    for failure in failures:
        print("FAILED: " + failure)
    if args.report:
        write_report(args, verdicts, failures)
    total = 3 * args.cases + 2 * solid_cases(args.cases)
    print(f"{len(failures)} failure(s) in {total} generated cases" if failures else
          f"all {total} generated cases refused clearly or ran")
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()
