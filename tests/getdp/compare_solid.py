#!/usr/bin/env python3
"""Compares a solid (3 components) solved by GetDP + ffeti-solve with the same problem solved
by FreeFEM + the plugin on the same gmsh mesh (tests/getdp/sphere-block-cross-check.sh).

usage: compare_solid.py NAME FFETI_TABLE FFETI_RESULT FREEFEM_TABLE FREEFEM_RESULT TOLERANCE
                        [STRESS_TABLE GETDP_VONMISES_GLOB]

FFETI_TABLE is ffeti-solve's output.table, FREEFEM_TABLE tests/edp/sphere-block.edp's, the
RESULT files hold each run's "RESULT key=value ..." line. Checks, each relative:
- displacements: max |u_ffeti-solve - u_FreeFEM| / max |u| (nodes matched by body and
  position; FreeFEM's copies of a node on several subdomains averaged);
- contact forces at the slave nodes (the same set of rows): max difference / max force;
- energies: |difference| / |energy|; all three <= TOLERANCE, and the same couples and active rows;
- the contact forces balance the load ffeti-solve reports (load_z) to 1e-8: a check of the
  physics that does not lean on the other front end;
- with STRESS_TABLE: von Mises per tetrahedron, ffeti-solve's own against GetDP's
  post-processing of the solution ffeti-solve handed back, matched by centroid, <= TOLERANCE.
Prints one line per check and "CROSS-CHECK name=NAME ..." with the figures; exit status 1 on failure.
"""
import csv
import glob
import math
import sys

BALANCE_TOLERANCE = 1e-8


def position(row):
    return tuple(round(float(row[c]), 9) for c in ("x", "y", "z"))


def result_value(path, key):
    line = next(l for l in open(path) if l.startswith("RESULT "))
    return line.split(f" {key}=")[1].split()[0]


def main():
    name, ffeti_table, ffeti_result, freefem_table, freefem_result, tolerance = sys.argv[1:7]
    tolerance = float(tolerance)
    stress_table, vonmises_glob = (sys.argv[7], sys.argv[8]) if len(sys.argv) > 8 else (None, None)

    ffeti, forces = {}, {}
    for row in csv.DictReader(open(ffeti_table)):
        ffeti[(int(row["body"]),) + position(row)] = tuple(float(row[c]) for c in ("u_x", "u_y", "u_z"))
        if row["contact_row"] == "1":
            forces[position(row)] = float(row["contact_force"])
    sums, ff_forces = {}, {}
    for row in csv.DictReader(open(freefem_table)):
        if row["kind"] == "u":
            entry = sums.setdefault((int(row["body"]),) + position(row), [[0.0, 0] for _ in range(3)])
            entry[int(row["component"])][0] += float(row["value"])
            entry[int(row["component"])][1] += 1
        else:
            ff_forces[position(row)] = float(row["value"])
    freefem = {k: tuple(s / n for s, n in v) for k, v in sums.items()}

    checks, failures = [], []
    if set(ffeti) != set(freefem):
        failures.append(f"node sets differ: {len(set(ffeti) ^ set(freefem))} nodes in one table only")
    if set(forces) != set(ff_forces):
        failures.append(f"contact rows differ: {len(set(forces) ^ set(ff_forces))} slave nodes in one run only")
    common = set(ffeti) & set(freefem)
    u_scale = max(max(abs(c) for c in u) for u in freefem.values())
    checks.append(("displacement", max(max(abs(a - b) for a, b in zip(ffeti[k], freefem[k])) for k in common) / u_scale,
                   tolerance))
    f_scale = max(abs(f) for f in ff_forces.values())
    checks.append(("contact_force", max(abs(forces.get(p, 0.0) - ff_forces.get(p, 0.0))
                                        for p in set(forces) | set(ff_forces)) / f_scale, tolerance))
    e_ffeti, e_freefem = float(result_value(ffeti_result, "energy")), float(result_value(freefem_result, "energy"))
    checks.append(("energy", abs(e_ffeti - e_freefem) / abs(e_freefem), tolerance))
    load = -float(result_value(ffeti_result, "load_z"))
    checks.append(("balance", abs(sum(forces.values()) - load) / load, BALANCE_TOLERANCE))
    for key in ("couples", "active"):
        a, b = result_value(ffeti_result, key), result_value(freefem_result, key)
        if a != b:
            failures.append(f"{key}: {a} from ffeti-solve, {b} from the plugin")

    if stress_table:
        # Centroids to 6 digits: GetDP computes them in its own order of operations.
        mine = {tuple(round(float(row[c]), 6) for c in ("x", "y", "z")): float(row["von_mises"])
                for row in csv.DictReader(open(stress_table))}
        getdp = {}
        for path in sorted(glob.glob(vonmises_glob)):
            for line in open(path):
                values = line.split()
                if len(values) >= 4:
                    getdp[tuple(round(float(v), 6) for v in values[:3])] = float(values[-1])
        if not getdp or set(mine) != set(getdp):
            failures.append(f"element sets differ: {len(mine)} from ffeti-solve, {len(getdp)} from GetDP")
        s_common = set(mine) & set(getdp)
        s_scale = max(getdp.values()) if getdp else 1.0
        checks.append(("von_mises", max((abs(mine[k] - getdp[k]) for k in s_common), default=math.inf) / s_scale,
                       tolerance))

    for check, error, bound in checks:
        ok = error <= bound
        print(f"{'ok' if ok else 'FAILED'}: {name}: {check}: relative difference {error:.3e} (bound {bound:g})")
        if not ok:
            failures.append(check)
    for failure in failures:
        print(f"FAILED: {name}: {failure}")
    print(f"CROSS-CHECK name={name} nodes={len(common)} contact_rows={len(forces)} active={result_value(ffeti_result, 'active')} "
          + " ".join(f"{check}={error:.3e}" for check, error, _ in checks)
          + f" energy_ffeti={e_ffeti:.12g} energy_plugin={e_freefem:.12g}")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
