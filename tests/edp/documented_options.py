#!/usr/bin/env python3
"""Every documented option of every function is accepted with a valid value.

Reads the option tables of docs/reference.md (fetiSetup's, fetiSolve's and the sensitivity
functions', which the plugin's registry prints: tests/docs_option_tables keeps them equal),
picks valid values from each row's "accepted values" column (every word of a word option; the
lowest and a middle value of a range), and writes one FreeFEM script that calls the function
with each in turn on the seed's two membranes (scenes/model-problem.idp: a contact problem with a floating body) (fetiSensitivity and fetiAdjoint
both take the sensitivity options); a value that applies only where nothing floats
(projector = "conjugate") on the same membranes with a lumped mass added, a time step's K + M. A refusal of a documented value is a failure: activeTol=
was refused by both sensitivity functions while the reference listed it, and the only test
passing it used invalid values, which passed for the wrong reason.

Usage: documented_options.py REFERENCE_MD (run where freefem++.pref points at the build)."""
import os
import re
import subprocess
import sys
import tempfile

FUNCTIONS = ("fetiSetup", "fetiSolve", "sensitivity")  # the tables' order in the reference
# Values that apply only where nothing floats (a time step's K + M), set up there.
WHERE_NOTHING_FLOATS = {("projector", '"conjugate"')}

PROBLEM = r"""
include "ffeti.idp"
include "scenes/model-problem.idp"
seedModelData(12, 6)
int failures = 0;
matrix[int] dK(S);
real[int][int] dF(S), Z(S), dJdu(S);
for (int s = 0; s < S; ++s) {
  dK[s] = 0 * K[s];
  dF[s].resize(F[s].n); dF[s] = 1;
  dJdu[s].resize(F[s].n); dJdu[s] = 1;
}
macro setUp(options) fetiSetup(K, F, X, Y, body, dirichlet = dirichlet, contactSlave = slave, contactMaster = master options) // EOM
// The same membranes with a lumped mass added (a time step's K + M: nothing floats), for
// the values that apply only there.
matrix[int] Kstep(S);
for (int s = 0; s < S; ++s) {
  fespace Vh(Th[s], P1);
  varf vm(u, v) = int2d(Th[s], qft = qf1pTlump)(u * v);
  matrix Ms = vm(Vh, Vh);
  Kstep[s] = K[s] + Ms;
}
macro setUpStep(options) fetiSetup(Kstep, F, X, Y, body, dirichlet = dirichlet, contactSlave = slave, contactMaster = master options) // EOM
macro accepted(statement, what)
try { statement; cout << "ok: " << what << endl; }
catch (...) { cout << "FAILED: " << what << " was refused" << endl; failures++; }
// EOM
int P = setUp();
int solved = fetiSolve(P, U, tol = 1e-8);
assert(solved == 0);
@CALLS@
fetiFree(P);
if (failures > 0) { cout << failures << " documented option value(s) refused" << endl; exit(1); }
cout << "all documented options accepted" << endl;
"""


def option_tables(reference):
    """The rows (name, type, accepted) of the reference's option tables, in order."""
    tables, rows = [], None
    for line in reference.splitlines():
        if line.startswith("| option | type | default | accepted values |"):
            rows = []
            tables.append(rows)
        elif rows is not None and line.startswith("| `"):
            cells = [c.strip() for c in line.strip().strip("|").split("|")]
            rows.append((cells[0].strip("`"), cells[1].strip("`"), cells[3]))
        elif rows is not None and not line.startswith("|"):
            rows = None
    return tables


def valid_values(kind, accepted):
    """Valid values of one option as FreeFEM literals, from its "accepted values" cell."""
    if kind == "string":
        return ['"%s"' % w for w in re.findall(r'`"([^"`]*)"`', accepted)]
    number = r"(-?[0-9.e+-]+|2\^31 − 1)"
    span = re.fullmatch(rf"{number} \.\. {number}", accepted)
    if span:  # integers
        low = int(span.group(1))
        return [str(low), str(low + 1)]
    bound = re.fullmatch(rf"(>|>=) {number}", accepted)
    if bound:
        low = float(bound.group(2))
        return [repr(max(low, 0) + 1.0), repr(max(low, 0) + 0.5) if low >= 0 else repr(low + 0.5)]
    interval = re.fullmatch(rf"([(\[]){number}, {number}([)\]])", accepted)
    if interval:
        low, high = float(interval.group(2)), float(interval.group(3))
        return [repr(low + (high - low) * f) for f in (1e-3, 0.5)]
    raise ValueError(f"cannot read the accepted values {accepted!r}")


def calls(tables):
    lines = []
    for function, rows in zip(FUNCTIONS, tables):
        if function == "sensitivity":  # a converged state again (fetiSolve's maxit = 1 left none)
            lines.append("assert(fetiSolve(P, U, tol = 1e-8) == 0);")
        for name, kind, accepted in rows:
            for value in valid_values(kind, accepted):
                option = f"{name} = {value}"
                label = "fetiSensitivity" if function == "sensitivity" else function
                what = f"{label}({option})".replace('"', "'")
                if function == "fetiSetup":
                    setup = "setUpStep" if (name, value) in WHERE_NOTHING_FLOATS else "setUp"
                    lines.append(f'accepted({{ int Q = {setup}({{, {option}}}); fetiSolve(Q, U); fetiFree(Q); }}, "{what}")')
                elif function == "fetiSolve":
                    lines.append(f'accepted(fetiSolve(P, U, {option}), "{what}")')
                else:
                    lines.append(f'accepted(fetiSensitivity(P, dK, dF, Z, {option}), "{what}")')
                    what = what.replace("fetiSensitivity(", "fetiAdjoint(")
                    lines.append(f'accepted(fetiAdjoint(P, dJdu, {option}), "{what}")')
    return lines


def main():
    with open(sys.argv[1]) as file:
        tables = option_tables(file.read())
    if len(tables) != len(FUNCTIONS) or not all(tables):
        sys.exit(f"expected {len(FUNCTIONS)} option tables in {sys.argv[1]}, found {len(tables)}")
    script = PROBLEM.replace("@CALLS@", "\n".join(calls(tables)))
    with tempfile.NamedTemporaryFile("w", suffix=".edp", dir=".", delete=False) as file:
        file.write(script)
    run = subprocess.run(["FreeFem++-nw", "-v", "0", file.name], capture_output=True, text=True, timeout=600)
    os.remove(file.name)
    print(run.stdout[-20000:] + run.stderr[-2000:])
    sys.exit(run.returncode)


if __name__ == "__main__":
    main()
