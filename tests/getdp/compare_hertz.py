#!/usr/bin/env python3
"""Compares the Hertz scene solved by GetDP + ffeti-solve with the same scene solved by
FreeFEM + the plugin on the same gmsh mesh, and with Hertz's analytic solution.

usage: compare_hertz.py FFETI_TABLE FREEFEM_TABLE STRESS_TABLE GETDP_VONMISES_GLOB TOLERANCE HERTZ_TOLERANCE

- displacements: max |u_ffeti-solve - u_FreeFEM| / max |u| <= TOLERANCE (nodes matched by body
  and position; FreeFEM's copies of a node on several subdomains averaged);
- contact forces (the multipliers) at the slave nodes: max difference / max force <= TOLERANCE;
- von Mises per element: ffeti-solve's against GetDP's post-processing of the solution
  ffeti-solve handed back (.res), matched by centroid: max difference / max <= TOLERANCE;
- a and p0 of ffeti-solve's contact forces against Hertz (as edp/hertz.edp measures them)
  within HERTZ_TOLERANCE (relative).
Prints one line per check and "CROSS-CHECK ..." with the figures; exit status 1 on failure.
"""
import csv
import glob
import math
import sys


def key(body, x, y):
    return (int(body), round(float(x), 9), round(float(y), 9))


def main():
    ffeti_table, freefem_table, stress_table, vonmises_glob, tolerance, hertz_tolerance = sys.argv[1:7]
    tolerance, hertz_tolerance = float(tolerance), float(hertz_tolerance)

    ffeti = {}
    forces = {}
    for row in csv.DictReader(open(ffeti_table)):
        k = key(row["body"], row["x"], row["y"])
        ffeti[k] = (float(row["u_x"]), float(row["u_y"]))
        if row["contact_row"] == "1":
            forces[k[1:]] = float(row["contact_force"])
    sums, ff_forces = {}, {}
    for row in csv.DictReader(open(freefem_table)):
        if row["kind"] == "u":
            k = key(row["body"], row["x"], row["y"])
            entry = sums.setdefault(k, [[0.0, 0], [0.0, 0]])[int(row["component"])]
            entry[0] += float(row["value"])
            entry[1] += 1
        else:
            ff_forces[key(0, row["x"], row["y"])[1:]] = float(row["value"])
    freefem = {k: (v[0][0] / v[0][1], v[1][0] / v[1][1]) for k, v in sums.items()}

    failures = []
    if set(ffeti) != set(freefem):
        failures.append(f"node sets differ: {len(set(ffeti) ^ set(freefem))} nodes in one table only")
    common = set(ffeti) & set(freefem)
    u_scale = max(max(abs(c) for c in u) for u in freefem.values())
    u_error = max(max(abs(a - b) for a, b in zip(ffeti[k], freefem[k])) for k in common) / u_scale
    f_scale = max(abs(f) for f in ff_forces.values())
    f_error = max(abs(forces.get(p, 0.0) - ff_forces.get(p, 0.0)) for p in set(forces) | set(ff_forces)) / f_scale

    mine = {}
    for row in csv.DictReader(open(stress_table)):
        mine[(round(float(row["x"]), 6), round(float(row["y"]), 6))] = float(row["von_mises"])
    getdp = {}
    for path in sorted(glob.glob(vonmises_glob)):
        for line in open(path):
            values = line.split()
            if len(values) >= 4:
                getdp[(round(float(values[0]), 6), round(float(values[1]), 6))] = float(values[-1])
    if not getdp or set(mine) != set(getdp):
        failures.append(f"element sets differ: {len(mine)} from ffeti-solve, {len(getdp)} from GetDP")
    s_common = set(mine) & set(getdp)
    s_scale = max(getdp.values()) if getdp else 1.0
    s_error = max((abs(mine[k] - getdp[k]) for k in s_common), default=math.inf) / s_scale

    # Hertz: p over each slave node's share of the x axis, as edp/hertz.edp measures it.
    R, F, E1, E2, nu = 50.0, 35000.0, 70e3, 210e3, 0.3
    e_star = 1 / ((1 - nu**2) / E1 + (1 - nu**2) / E2)
    a_exact = math.sqrt(4 * F * R / (math.pi * e_star))
    p0_exact = 2 * F / (math.pi * a_exact)
    xs = sorted(forces, key=lambda p: p[0])
    x = [p[0] for p in xs]
    share = [((x[i + 1] if i + 1 < len(x) else x[i]) - (x[i - 1] if i > 0 else x[i])) / 2 for i in range(len(x))]
    p0 = forces[xs[0]] / share[0]
    last = max(i for i, p in enumerate(xs) if forces[p] > 0)
    a = (x[last] + x[last + 1]) / 2 if last + 1 < len(x) else x[last]
    a_error, p0_error = abs(a - a_exact) / a_exact, abs(p0 - p0_exact) / p0_exact

    for name, error, bound in [("displacement", u_error, tolerance), ("contact force", f_error, tolerance),
                               ("von Mises (GetDP)", s_error, tolerance), ("Hertz a", a_error, hertz_tolerance),
                               ("Hertz p0", p0_error, hertz_tolerance)]:
        ok = error <= bound
        print(f"{'ok' if ok else 'FAILED'}: {name}: relative difference {error:.3e} (bound {bound:g})")
        if not ok:
            failures.append(name)
    print(f"CROSS-CHECK nodes={len(common)} couples={len(forces)} elements={len(s_common)} u_relerr={u_error:.3e} "
          f"force_relerr={f_error:.3e} von_mises_relerr={s_error:.3e} a={a:.6g} p0={p0:.6g} "
          f"a_relerr={a_error:.4f} p0_relerr={p0_error:.4f}")
    for failure in failures:
        print("FAILED:", failure)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
