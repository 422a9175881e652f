#!/usr/bin/env python3
"""Transient contact against exact solutions: the elastic bar striking a wall
(edp/bar-impact.edp, 2D and 3D, mesh refinement, both schemes, the time step) and the block
sliding to rest under Coulomb friction (edp/sliding-block.edp). Writes the raw data into
docs/results/dynamics-*.csv and renders docs/results/dynamics.md with its plots.
One command: ./scripts/benchmark.sh dynamics (--render: the page again from the CSVs)."""
import argparse
import csv
import os
import tempfile

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from ffeti_bench import (ROOT, begin_run, end_run, machine_line, markdown_table, read_csv, run, save_page,  # noqa: E402
                         write_csv)

PAGE = "dynamics"
RESULTS = os.path.join(ROOT, "docs", "results")
BAR_SIZES = (20, 40, 80, 160)
COURANTS = (0.5, 1, 2, 4, 8, 16)
HISTORY_N = 80
WAVE_EVERY = 40
BOUNCE_G, BOUNCE_STEPS = 2e4, 1000
# Columns several tables share (the bar and two bars against the exact impact).
CONTACT_TIME_ERROR = ("contact time error", lambda r: f"{relative(r, 'contact_time', 'contact_time_exact'):.1%}")
FORCE_ERROR = ("mean force error", lambda r: f"{relative(r, 'mean_contact_force_per_area', 'force_per_area_exact'):.1%}")
REBOUND = ("rebound / v0", lambda r: f"{float(r['rebound_velocity']) / float(r['v0']):.3f}")
ENERGY_CHANGE = ("energy change", lambda r: f"{float(r['energy_change']):+.2%}")
ENERGY_GAIN = ("largest energy gain", lambda r: f"{float(r['energy_gain_max']):.1e}")
MASS_COLUMNS = [("elements", lambda r: f"P{r['order']}"), ("mass", "mass"), ("n", "n"), ("unknowns", "unknowns"),
                CONTACT_TIME_ERROR, FORCE_ERROR, REBOUND, ENERGY_CHANGE, ENERGY_GAIN,
                ("Hessian per step (max)", "hessian_per_step_max"), ("status", "status")]
PAIR_COLUMNS = [("dim", "dim"), ("contact", "contact"), ("n", "n"), ("unknowns", "unknowns"),
                CONTACT_TIME_ERROR, FORCE_ERROR, REBOUND,
                ("largest total momentum / (m v0)", lambda r: f"{float(r['momentum_max']):.1e}"), ENERGY_CHANGE,
                ("status", "status")]
STEP_COLUMNS = [("n", "n"), ("c dt / h", "courant"), ("projector", "projector"), ("static solve", "hessian_static"),
                ("a step, mean", "hessian_step_mean"), ("a step, max", "hessian_step_max"),
                ("s per step", lambda r: f"{float(r['time_per_step']):.4f}"), ("status", "status")]
MEMBRANE_COLUMNS = [("n", "n"), ("subdomains", "subdomains"), ("unknowns", "unknowns"), ("c dt / h", "courant"),
                    ("time steps", "steps"), ("static solve", "hessian_static"), ("a step, mean", "hessian_step_mean"),
                    ("a step, max", "hessian_step_max"), ("of it the projection, max", "projection_max"),
                    ("status", "status")]
PEER_COLUMNS = [("n", "n"), ("unknowns", "unknowns"), ("FETI: s per step", lambda r: f"{float(r['time_per_step']):.4f}"),
                ("peer: s per step", lambda r: f"{float(r['peer_time_per_step']):.4f}"),
                ("peer / FETI", lambda r: f"{float(r['peer_time_per_step']) / float(r['time_per_step']):.0f}"),
                ("peer's active set iterations (max)", "peer_pdas_max"),
                ("largest energy difference", lambda r: f"{float(r['energy_difference']):.1e}")]
SPHERE_COLUMNS = [("onto", "support"), ("h at the contact [mm]", "h"), ("speed [m/s]", lambda r: f"{float(r['v0']) / 1000:g}"),
                  ("scheme", "scheme"), ("steps over Hertz's contact time", lambda r: str(round(float(r["contact_time_hertz"]) / float(r["dt"])))),
                  ("unknowns", "unknowns"),
                  ("contact time / Hertz", lambda r: f"{float(r['contact_time']) / float(r['contact_time_hertz']):.3f}"),
                  ("peak force / Hertz", lambda r: f"{float(r['peak_force']) / float(r['peak_force_hertz']):.3f}"),
                  ("rebound / v", lambda r: f"{float(r['rebound_velocity']) / float(r['v0']):.4f}"),
                  ("energy change", lambda r: f"{float(r['energy_change']):+.2%}"),
                  ("Hessian per step (max)", "hessian_per_step_max"), ("Hessian total", "hessian_total"), ("status", "status")]
BOUNCE_COLUMNS = [("scheme", "scheme"), ("steps", "steps"), ("impacts", "impacts"),
                  ("energy at the end / initial", lambda r: f"{1 + float(r['energy_change']):.3f}"),
                  ("largest energy gain", lambda r: f"{float(r['energy_gain_max']):.1e}"),
                  ("Hessian per step (max)", "hessian_per_step_max"), ("status", "status")]


def history(script, *args):
    """The RESULT line and the per-step history (list of dicts) of one run."""
    with tempfile.TemporaryDirectory() as folder:
        path = os.path.join(folder, "history.csv")
        result = run(script, *args, "-history", path)["RESULT"][0]
        with open(path) as text:
            steps = list(csv.DictReader(text))
    return result, steps


def bar_rows():
    rows = []
    for dim in (2, 3):
        for scheme in ("stabilized", "newmark"):
            for n in BAR_SIZES if dim == 2 else BAR_SIZES[:2]:
                r = run("bar-impact.edp", "-dim", dim, "-n", n, "-scheme", scheme)["RESULT"][0]
                rows.append(dict(r, courant=1, series="refinement"))
    for courant in COURANTS:
        r = run("bar-impact.edp", "-n", 40, "-courant", courant)["RESULT"][0]
        rows.append(dict(r, courant=courant, series="time step"))
    for dim, n, kind in ((2, 40, "node"), (2, 80, "node"), (2, 40, "segment"), (2, 80, "segment"), (3, 20, "node"),
                         (3, 20, "face"), (3, 20, "mortar")):
        r = run("bar-impact.edp", "-dim", dim, "-bars", 2, "-n", n, "-contact", kind)["RESULT"][0]
        rows.append(dict(r, courant=1, series="two bars", contact=kind))
    r = run("bar-impact.edp", "-n", 80, "-wall", "ball")["RESULT"][0]
    rows.append(dict(r, courant=1, series="ball"))
    for order, mass, n in ((1, "lumped", 20), (1, "consistent", 20), (1, "lumped", 80), (1, "consistent", 80),
                           (2, "consistent", 20), (2, "consistent", 40)):
        r = run("bar-impact.edp", "-n", n, "-order", order, "-mass", mass)["RESULT"][0]
        rows.append(dict(r, courant=1, series="mass", order=order, mass=mass))
    return rows


def bounce_rows():
    """A bar bouncing under gravity for BOUNCE_STEPS steps, both schemes: RESULT lines and histories."""
    rows, histories = [], []
    for scheme in ("stabilized", "newmark"):
        r, steps = history("bar-impact.edp", "-g", BOUNCE_G, "-n", 20, "-steps", BOUNCE_STEPS, "-scheme", scheme)
        rows.append(r)
        histories += [dict(step, scheme=scheme) for step in steps]
    return rows, histories


def bar_histories():
    rows = []
    for scheme in ("stabilized", "newmark"):
        _, steps = history("bar-impact.edp", "-n", HISTORY_N, "-scheme", scheme)
        rows += [dict(step, scheme=scheme) for step in steps]
    return rows


def sphere_rows():
    """The hemisphere on a plane against Hertz's impact: time steps, mesh, speed, both schemes."""
    rows = []
    for args in (("-steps", 40), ("-steps", 100), ("-h", 0.1, "-steps", 100), ("-steps", 100, "-speed", 100),
                 ("-steps", 100, "-scheme", "newmark"), ("-block", 1, "-steps", 40), ("-block", 1, "-steps", 100)):
        rows.append(run("sphere-impact-3d.edp", *args, "-meshes", os.path.join(ROOT, "meshes"))["RESULT"][0])
    return rows


def sphere_history():
    _, steps = history("sphere-impact-3d.edp", "-steps", 100, "-meshes", os.path.join(ROOT, "meshes"))
    return steps


def membrane_rows():
    """The seed's membranes in time: weak scaling at c dt / h = 1, then longer steps."""
    rows = [dict(r, series="weak scaling") for r in
            run("model-problem-dynamic.edp", "-sizes", "32,64,128,256", "-peer", 1)["RESULT"]]
    for courant in (1, 4, 16, 64):
        for projector in ("none", "conjugate"):
            rows += [dict(r, series="time step", projector=projector) for r in
                     run("model-problem-dynamic.edp", "-sizes", "64,128", "-courant", courant,
                         "-projector", projector)["RESULT"]]
    return rows


def vtu_arrays(path):
    """The binary (base64, UInt32 header) arrays of a FreeFEM VTU file: {name: numpy array}."""
    import base64
    import re
    import struct
    import numpy as np
    text, out = open(path).read(), {}
    pattern = r'<DataArray type="(\w+)"(?: Name="(\w+)")?(?: NumberOfComponents="(\d+)")? format="binary"\s*>\s*(\S+)\s*</DataArray>'
    for kind, name, components, data in re.findall(pattern, text):
        raw = base64.b64decode(data)
        size = struct.unpack("<I", raw[:4])[0]
        values = np.frombuffer(raw[4:4 + size], dtype={"Float32": "<f4", "Float64": "<f8", "Int32": "<i4", "UInt8": "u1"}[kind])
        out[name or "Points"] = values.reshape(-1, int(components)) if components else values
    return out


def wave_rows():
    """The bar's velocity along x at chosen steps (-vtk): the compression wave running to the free end and back."""
    rows = []
    with tempfile.TemporaryDirectory() as folder:
        r = run("bar-impact.edp", "-n", HISTORY_N, "-vtk", os.path.join(folder, "bar"), "-every", WAVE_EVERY)["RESULT"][0]
        for k in range(0, int(r["steps"]) + 1, WAVE_EVERY):
            for s in range(10):
                a = vtu_arrays(os.path.join(folder, f"bar-s{s}-k{k}.vtu"))
                for point, velocity in zip(a["Points"], a["velocity"]):
                    if abs(point[1]) < 1e-12:   # the bar's lower edge: one node per x
                        rows.append({"step": k, "t": k * float(r["dt"]), "x": float(point[0]), "vx": float(velocity[0])})
    return rows


def plot_wave(rows):
    figure, axis = plt.subplots(figsize=(7, 4))
    for k in sorted({int(r["step"]) for r in rows}):
        points = sorted((float(r["x"]), float(r["vx"])) for r in rows if int(r["step"]) == k)
        t = 1e6 * float(next(r["t"] for r in rows if int(r["step"]) == k))
        axis.plot([1e3 * x for x, _ in points], [v for _, v in points], label=f"t = {t:.0f} µs")
    axis.set(xlabel="x along the bar [mm] (the wall at 0)", ylabel="velocity along x [m/s]",
             title=f"the bar's velocity (n = {HISTORY_N}, stabilized): the wave runs out and back")
    save_figure(figure, axis, "wave", legend_columns=2, legend_size=8)


def slide_rows():
    rows = []
    for dim, m in ((2, 4), (3, 3)):
        for steps in (15, 30, 60, 120):
            rows.append(dict(run("sliding-block.edp", "-dim", dim, "-m", m, "-steps", steps)["RESULT"][0], material="rubber"))
        rows.append(dict(run("sliding-block.edp", "-dim", dim, "-m", m, "-law", "tresca")["RESULT"][0], material="rubber"))
    steel = run("sliding-block.edp", "-E", 210e9, "-rho", 7800, "-steps", 15)["RESULT"][0]
    rows.append(dict(steel, material="steel"))
    return rows


def slide_history():
    _, steps = history("sliding-block.edp", "-steps", 60)
    return steps


def save_figure(figure, axis, name, legend_columns=1, legend_size=None):
    """Legend, grid and layout of a one-panel figure, saved as docs/results/dynamics-NAME.png."""
    axis.legend(fontsize=legend_size, ncol=legend_columns)
    axis.grid(True, alpha=0.3)
    figure.tight_layout()
    figure.savefig(os.path.join(RESULTS, f"{PAGE}-{name}.png"), dpi=110)
    plt.close(figure)


def relative(r, key, exact):
    return abs(float(r[key]) - float(r[exact])) / float(r[exact])


BAR_COLUMNS = [("dim", "dim"), ("wall", lambda r: "ball" if r.get("series") == "ball" else "plane"), ("scheme", "scheme"), ("n", "n"), ("unknowns", "unknowns"), ("steps", "steps"),
               CONTACT_TIME_ERROR, FORCE_ERROR, REBOUND, ENERGY_CHANGE, ENERGY_GAIN,
               ("Hessian per step (max)", "hessian_per_step_max"), ("Hessian total", "hessian_total"), ("status", "status")]
COURANT_COLUMNS = [("c dt / h", "courant"), ("projector", "projector"), ("steps", "steps"),
                   CONTACT_TIME_ERROR, FORCE_ERROR, REBOUND, ENERGY_CHANGE,
                   ("Hessian per step (max)", "hessian_per_step_max"),
                   ("Hessian per step (mean)", lambda r: f"{int(r['hessian_total']) / int(r['steps']):.1f}"), ("status", "status")]
SLIDE_COLUMNS = [("dim", "dim"), ("law", "law"), ("block", "material"), ("steps to stop", lambda r: str(round(float(r["stop_time_exact"]) / float(r["dt"])))),
                 ("stop time error", lambda r: f"{relative(r, 'stop_time', 'stop_time_exact'):.1e}" if float(r["stop_time"]) > 0 else "-"),
                 ("deceleration error", lambda r: f"{relative(r, 'deceleration', 'deceleration_exact'):.1e}" if float(r["stop_time"]) > 0 else "-"),
                 ("distance error", lambda r: f"{relative(r, 'final_distance', 'stop_distance_exact'):.1e}" if r["status"] == "converged" else "-"),
                 ("Hessian per step (max)", "hessian_per_step_max"), ("Hessian total", "hessian_total"),
                 ("stagnated solves", "stagnated_solves"), ("status", "status")]


def plot_bar(histories, bar):
    exact = next(r for r in bar if r["dim"] == "2" and r["n"] == str(HISTORY_N) and r["scheme"] == "stabilized")
    t_contact, force = float(exact["contact_time_exact"]), float(exact["force_per_area_exact"])
    figure, (left, right) = plt.subplots(1, 2, figsize=(11, 4))
    for scheme, style in (("stabilized", "-"), ("newmark", ":")):
        steps = [h for h in histories if h["scheme"] == scheme]
        t = [1e6 * float(h["t"]) for h in steps]
        left.plot(t, [float(h["contact_force_per_area"]) / 1e6 for h in steps], style, label=scheme)
        right.plot(t, [float(h["total"]) / float(steps[0]["total"]) for h in steps], style, label=scheme)
    end = 1e6 * max(float(h["t"]) for h in histories)
    left.plot([0, 0, 1e6 * t_contact, 1e6 * t_contact, end], [0, force / 1e6, force / 1e6, 0, 0], "k--", lw=1, label="exact")
    left.set(xlabel="t [µs]", ylabel="wall force per area [MPa]", title=f"bar on a wall, n = {HISTORY_N}")
    right.set(xlabel="t [µs]", ylabel="total energy / initial", title="energy", yscale="log")
    for axis in (left, right):
        axis.legend()
        axis.grid(True, alpha=0.3)
    figure.tight_layout()
    figure.savefig(os.path.join(RESULTS, f"{PAGE}-bar.png"), dpi=110)
    plt.close(figure)


def plot_bounce(histories):
    figure, axis = plt.subplots(figsize=(6, 4))
    for scheme, style in (("stabilized", "-"), ("newmark", ":")):
        steps = [h for h in histories if h["scheme"] == scheme]
        axis.plot([1e3 * float(h["t"]) for h in steps], [float(h["total"]) / float(steps[0]["total"]) for h in steps],
                  style, label=scheme)
    axis.set(xlabel="t [ms]", ylabel="total energy / initial", yscale="log",
             title=f"a bar bouncing under gravity, {BOUNCE_STEPS} steps")
    save_figure(figure, axis, "bounce")


def plot_sphere(steps, sphere):
    r = next(r for r in sphere if r["support"] == "plane" and r["h"] == "0.2" and r["scheme"] == "stabilized" and float(r["v0"]) == 1000
             and round(float(r["contact_time_hertz"]) / float(r["dt"])) == 100)
    t_c, force = float(r["contact_time_hertz"]), float(r["peak_force_hertz"])
    figure, axis = plt.subplots(figsize=(6, 4))
    axis.plot([1e6 * float(h["t"]) for h in steps], [float(h["force"]) for h in steps], "o-", ms=2, label="ffeti (whole ball)")
    axis.plot([0, 1e6 * t_c], [force, force], "k--", lw=1, label="Hertz: peak force")
    axis.axvline(1e6 * t_c, color="k", ls=":", lw=1, label="Hertz: contact time")
    axis.set(xlabel="t [µs]", ylabel="force on the plane [N]", title="hemisphere on a rigid plane, 1 m/s")
    save_figure(figure, axis, "sphere")


def plot_slide(steps, slide):
    r = next(r for r in slide if r["dim"] == "2" and r["material"] == "rubber")
    v0, stop = float(r["v0"]), float(r["stop_time_exact"])
    figure, axis = plt.subplots(figsize=(6, 4))
    t = [float(h["t"]) for h in steps]
    axis.plot(t, [float(h["velocity"]) for h in steps], "o-", ms=3, label="block's mean velocity")
    end = max(t)
    axis.plot([0, stop, end], [v0, 0, 0], "k--", lw=1, label="exact: v0 - μ g t, then rest")
    axis.set(xlabel="t [s]", ylabel="velocity [m/s]", title="block sliding to rest (2D, 60 steps to the stop)")
    save_figure(figure, axis, "slide")


def mean_steps(rows, courant, projector):
    """'a to b' of the mean multiplications per step over the sizes at one c dt / h and projector."""
    values = [float(r["hessian_step_mean"]) for r in rows if r["courant"] == courant and r["projector"] == projector]
    low, high = min(values), max(values)
    return f"{low:.0f}" if round(low) == round(high) else f"{low:.0f} to {high:.0f}"


def static_of(rows):
    values = sorted({int(r["hessian_static"]) for r in rows})
    return f"{values[0]}" if len(values) == 1 else f"{values[0]} to {values[-1]}"


def render():
    bar, slide, run_row = read_csv(PAGE, "bar"), read_csv(PAGE, "slide"), read_csv(PAGE, "run")[0]
    plot_bar(read_csv(PAGE, "bar-history"), bar)
    plot_wave(read_csv(PAGE, "wave"))
    plot_slide(read_csv(PAGE, "slide-history"), slide)
    bounce = read_csv(PAGE, "bounce")
    sphere = read_csv(PAGE, "sphere")
    on_plane = [r for r in sphere if r["support"] == "plane"]
    on_block = [r for r in sphere if r["support"] == "block"]
    membranes = read_csv(PAGE, "membranes")
    weak = [r for r in membranes if r["series"] == "weak scaling"]
    longer = [r for r in membranes if r["series"] == "time step"]
    plot_sphere(read_csv(PAGE, "sphere-history"), sphere)
    plot_bounce(read_csv(PAGE, "bounce-history"))
    pairs = [r for r in bar if r["series"] == "two bars"]
    masses = [r for r in bar if r["series"] == "mass"]
    lumped20 = next(r for r in masses if r["mass"] == "lumped" and r["n"] == "20")
    consistent20 = next(r for r in masses if r["mass"] == "consistent" and r["order"] == "1" and r["n"] == "20")
    refinement = [r for r in bar if r["series"] in ("refinement", "ball")]
    courants = [r for r in bar if r["series"] == "time step"]
    stable = [r for r in refinement if r["scheme"] == "stabilized"]
    trapezoid = [r for r in refinement if r["scheme"] == "newmark"]
    finest = max((r for r in stable if r["dim"] == "2" and r["series"] == "refinement"), key=lambda r: int(r["n"]))
    steel = next(r for r in slide if r["material"] == "steel")
    rubber = [r for r in slide if r["material"] == "rubber"]
    lines = [
        "# Transient contact",
        "",
        "Generated by `scripts/benchmark.sh dynamics` (do not edit by hand) on:",
        machine_line(run_row),
        "",
        f"Contact with inertia (`edp/dynamics.idp`): Newmark's average acceleration, Keff = K + 4/dt² M",
        "set up once per time step size (its factorizations serve every step), each step's dual solve",
        "started from the last step's multipliers, lumped P1 masses, Total FETI. Two treatments of",
        "the contact: `stabilized` (the default), the contact-stabilized Newmark method of Deuflhard,",
        "Krause and Ertel (the predictor projected onto the admissible set in the mass norm by a",
        "second ffeti problem with M as its matrix; the contact force at the step's end only), and",
        "`newmark`, the trapezoidal rule for every force, contact included. Raw data:",
        f"[{PAGE}-bar.csv]({PAGE}-bar.csv), [{PAGE}-bar-history.csv]({PAGE}-bar-history.csv),",
        f"[{PAGE}-wave.csv]({PAGE}-wave.csv), [{PAGE}-bounce.csv]({PAGE}-bounce.csv), [{PAGE}-bounce-history.csv]({PAGE}-bounce-history.csv),",
        f"[{PAGE}-sphere.csv]({PAGE}-sphere.csv), [{PAGE}-sphere-history.csv]({PAGE}-sphere-history.csv),",
        f"[{PAGE}-slide.csv]({PAGE}-slide.csv), [{PAGE}-slide-history.csv]({PAGE}-slide-history.csv).",
        "",
        "## A bar striking a rigid wall",
        "",
        "`edp/bar-impact.edp`: an aluminium bar (E = 70 GPa, ρ = 2700 kg/m³, ν = 0, L = 0.1 m, a",
        "tenth of that high and deep) at v0 = 1 m/s touches the wall at t = 0. Exact (one-dimensional",
        "waves): contact for 2L/c, the wall pushing with ρcv0 per unit area all that time, the bar",
        "leaving at v0 with all its energy. n cells along the bar, 10 subdomains, dt = h/c; the",
        "contact time is the steps with a wall force, the mean force the impulse over that time, the",
        "rebound the bar's momentum over its mass 1.5 × 2L/c after the impact.",
        "",
        *markdown_table(refinement, BAR_COLUMNS),
        "",
        "The last row's wall is a rigid ball of radius 1000 L (`-wall ball`, `obstacleBall`'s rows).",
        "",
        f"Reading: the stabilized scheme converges to the exact impact at first order (n = {finest['n']}:",
        f"rebound {float(finest['rebound_velocity']) / float(finest['v0']):.3f} v0, energy "
        f"{float(finest['energy_change']):+.2%}); it never gains energy (largest gain over any step of this run",
        f"{max(float(r['energy_gain_max']) for r in stable):.0e}, round-off) and loses the part the",
        "projection takes out at each impact, which falls with h. The trapezoidal rule gains energy at",
        f"every impact (energy at the end {min(float(r['energy_change']) for r in trapezoid):+.0%} to "
        f"{max(float(r['energy_change']) for r in trapezoid):+.0%} of the initial):",
        "the wall force chatters between steps (left plot), so it is offered for comparison only. Its",
        "first contact interval ends after a step or two, the force having dropped to zero, so its",
        "contact time, force and rebound columns measure that interval, not the impact.",
        "Hessian multiplications per step stay bounded as h falls at a fixed c dt / h (both solves of",
        "a step counted: the projection and the step).",
        "",
        f"![wall force and energy]({PAGE}-bar.png)",
        "",
        "The velocity along the bar at chosen steps, read back from the VTU files the scene writes",
        f"for ParaView (`-vtk`, every {WAVE_EVERY} steps): the struck end stops, the front runs to the free",
        "end, and the reflected front brings the bar to +v0. The struck nodes keep their velocity",
        "before the impact while they touch the wall: the stabilized scheme updates velocities from",
        "the projected predictor, which already stands at the wall (an O(h) share of the bar's",
        "momentum; the rebound measured over the whole bar converges at first order, above).",
        "",
        f"![the wave along the bar]({PAGE}-wave.png)",
        "",
        "### The time step",
        "",
        "The same bar (2D, n = 40, stabilized) at c dt / h from 0.5 to 16: a longer step smears the",
        "wave front (the contact time and force lose accuracy) and makes Keff closer to the floating",
        "K, so each step's dual solve takes more multiplications; from c dt / h = 8 on the scene sets",
        "the step's problem up with the conjugate projector (below).",
        "",
        *markdown_table(courants, COURANT_COLUMNS),
        "",
        "### Lumped or consistent mass",
        "",
        "`-mass lumped` (the default) or `consistent`, `-order 1` or `2` (P2 takes the consistent mass:",
        "its vertex quadrature gives the mid-edge nodes no mass). The 2D bar, dt = h/c with h the node",
        "spacing:",
        "",
        *markdown_table(masses, MASS_COLUMNS),
        "",
        f"Reading: the consistent P1 mass is a little closer to the exact impact (rebound "
        f"{float(consistent20['rebound_velocity']) / float(consistent20['v0']):.3f} against "
        f"{float(lumped20['rebound_velocity']) / float(lumped20['v0']):.3f} v0 at n = 20) and costs more per step",
        f"({consistent20['hessian_per_step_max']} against {lumped20['hessian_per_step_max']} multiplications at most: its",
        "projection couples the nodes, the lumped one is nodewise). The lumped mass is the default:",
        "the cheaper step at the same order of accuracy. Neither gains energy.",
        "",
        "## Two bars meeting",
        "",
        "`-bars 2`: two such bars, [−L, 0] at +v0 and [0, L] at −v0, meet at x = 0; node-to-node rows",
        "between their ends (the left bar's the slaves), or with the right bar one cell finer per",
        "subdomain side (non-matching ends) node to segment (2D), node to face or mortar (3D), its end",
        "the master surface. Exact: the same contact time and force, each",
        "bar leaves at its opposite velocity, and the total momentum stays zero (the contact forces",
        "are internal).",
        "",
        *markdown_table(pairs, PAIR_COLUMNS),
        "",
        "## Repeated impacts",
        "",
        f"`-g {BOUNCE_G:g}`: the bar (2D, n = 20) falls back onto the wall under gravity and bounces",
        f"again; {BOUNCE_STEPS} steps. Total energy: kinetic, elastic and gravity's potential.",
        "",
        *markdown_table(bounce, BOUNCE_COLUMNS),
        "",
        f"![energy over repeated impacts]({PAGE}-bounce.png)",
        "",
        "Reading: the stabilized scheme never gains energy over the run (its largest gain is",
        "round-off) and loses a few percent at each impact at this coarse mesh (the projection",
        "takes out the normal velocity of the struck nodes); the trapezoidal rule gains at",
        "every impact and its bar ends far from the physics.",
        "",
        "## What a time step costs: the seed's membranes in time",
        "",
        "`edp/model-problem-dynamic.edp`: the model problem's load applied suddenly to the two",
        "membranes at rest (unit density, lumped masses), 40 time steps; the membranes swing past",
        "their static positions, closing and opening the contact. H/h = 16, subdomains added as h",
        "falls (weak scaling); beside each, the static problem's solve on the same meshes. Hessian",
        "multiplications per step (the projection's and the step's solves together):",
        "",
        *markdown_table(weak, MEMBRANE_COLUMNS),
        "",
        "The direct peer beside it (`-peer 1`): the same steps on the undivided membranes, each step's",
        "contact problem and projection by the primal-dual active set method with UMFPACK",
        "(`active-set.idp`), the time of the steps alone on both sides; the largest difference of",
        "the two runs' total energies over the steps, relative (tol = 1e-6), checks that both solve",
        "one problem:",
        "",
        *markdown_table(weak, PEER_COLUMNS),
        "",
        f"The peer takes {min(float(r['peer_time_per_step']) / float(r['time_per_step']) for r in weak):.0f} to "
        f"{max(float(r['peer_time_per_step']) / float(r['time_per_step']) for r in weak):.0f} times FETI's time per step, the gap widening with the size:",
        "each of its active set iterations factorizes a new KKT system (the contact rows change it),",
        "where FETI factorized Keff once before the first step and each step costs a few",
        "multiplications. Both give the same energies to well below tol.",
        "",
        "With longer steps Keff = K + 4/dt² M comes nearer the floating K (no coarse space in it),",
        "without and with the conjugate projector onto the subdomains' rigid modes on the gluing",
        "and Dirichlet rows (`fetiSetup(..., projector = \"conjugate\")`, F applied once to each mode",
        "at set-up):",
        "",
        *markdown_table(longer, STEP_COLUMNS),
        "",
        f"Reading: at c dt / h = 1 a step costs {min(float(r['hessian_step_mean']) for r in weak):.0f} to "
        f"{max(float(r['hessian_step_mean']) for r in weak):.0f} multiplications on average, flat as h falls and a",
        f"quarter of the static solve's ({min(int(r['hessian_static']) for r in weak)} to {max(int(r['hessian_static']) for r in weak)}).",
        "Without the projector a longer step costs more, and at c dt / h = 64 more than the static",
        f"solve ({mean_steps(longer, '64', 'none')} per step on average against {static_of(longer)}), since Keff's floating",
        "body is held only by its mass term; the projector takes that direction out of the iteration",
        f"({mean_steps(longer, '64', 'conjugate')} per step at c dt / h = 64, {mean_steps(longer, '16', 'conjugate')} at 16 against "
        f"{mean_steps(longer, '16', 'none')}), and the time per step follows",
        f"where the step is long; at c dt / h = 1 the count changes little ({mean_steps(longer, '1', 'conjugate')} against "
        f"{mean_steps(longer, '1', 'none')}) and the set-up's F applications and the",
        "projections per multiplication are a cost without a return. The scenes choose it from",
        "their data (`ffetiStepProjector`: from c dt / h = 8 on); the plugin's option stays off unless",
        "asked. The bar's and the block's rows above ran with that choice (the block at c dt / h",
        "of about 65: with the projector).",
        "",
        "## A hemisphere striking a plane",
        "",
        "`edp/sphere-impact-3d.edp`: the lower half of a ball (R = 10 mm; a polymer, E = 1 GPa,",
        "ν = 0.3, ρ = 1200 kg/m³; `meshes/hertz-sphere.geo`, a quarter model with sliding symmetry",
        "planes, 4 METIS parts) falls onto a rigid plane. Hertz's quasi-static theory of impact",
        "(Johnson, ch. 11) with the body's mass: contact time 2.87 (m²/(R E*² v))^(1/5), peak force",
        "(4/3) E* R^(1/2) d^(3/2) at the largest approach d = (15 m v²/(16 E* R^(1/2)))^(2/5), a rebound",
        "at v. At 1 m/s the contact lasts about 14 times the time a wave takes to cross the body.",
        "The last rows: onto an elastic block of the same material (`-block 1`,",
        "`meshes/hertz-sphere-block.geo`, its bottom held, 9 subdomains; mortar rows, the sphere's",
        "faces the slaves), Hertz with E* = E/(2(1 − ν²)).",
        "",
        *markdown_table(sphere, SPHERE_COLUMNS),
        "",
        f"![contact force against time]({PAGE}-sphere.png)",
        "",
        "Reading: on the plane the impact is "
        f"{min(float(r['contact_time']) / float(r['contact_time_hertz']) for r in on_plane):.2f} to "
        f"{max(float(r['contact_time']) / float(r['contact_time_hertz']) for r in on_plane):.2f} times Hertz's contact time with "
        f"{min(float(r['peak_force']) / float(r['peak_force_hertz']) for r in on_plane):.2f} to "
        f"{max(float(r['peak_force']) / float(r['peak_force_hertz']) for r in on_plane):.2f} times his peak force,",
        "whatever the time step and the speed (a tenth of the speed, more quasi-static, gives the",
        "same ratios): the difference is the discrete body's, not the time integration's. Halving",
        "the mesh size at the contact moves it little; the P1 tetrahedra of the coarse bulk (up to",
        "R/4) are the likely stiffness left (not measured here). The ball leaves at its speed to",
        "within a few tenths of a percent, the stabilized scheme losing a little energy and the",
        "trapezoidal rule gaining some. On the block, mortar rows between two elastic bodies: "
        f"{min(float(r['contact_time']) / float(r['contact_time_hertz']) for r in on_block):.3f} to "
        f"{max(float(r['contact_time']) / float(r['contact_time_hertz']) for r in on_block):.3f} of the contact time,",
        f"{min(float(r['peak_force']) / float(r['peak_force_hertz']) for r in on_block):.3f} to "
        f"{max(float(r['peak_force']) / float(r['peak_force_hertz']) for r in on_block):.3f} of the peak force.",
        "",
        "## A block sliding to rest under Coulomb friction",
        "",
        "`edp/sliding-block.edp`: a block (2a x a, a = 5 cm; E = 100 MPa, ρ = 1200 kg/m³, ν = 0.3)",
        "rests on a rigid floor under gravity (a static solve first), then starts along it at",
        "v0 = 0.5 m/s; μ = 0.3. Exact: it stops after v0/(μg) having travelled v0²/(2μg). Coulomb's law",
        "holds in each step on the slip since the last one (`fetiSetLoads` starts a load step).",
        "The `tresca` rows (`-law tresca`) give each bottom node a slip bound, μW over their number:",
        "while the block slides every node slips at its bound, and the same stop follows.",
        "The deceleration is the slope of the line fitted through the block's mean velocity while it",
        "slides (0.1 v0 to 0.9 v0), the stop time where that line crosses zero (the elastic block",
        "rocks as it slides, friction's moment about its centre, and its mean velocity wobbles by",
        "about 1e-3 v0 near the stop: a first crossing of zero would read the wobble); the distance",
        "is the mean displacement at the end of the run (1.5 times the stop time).",
        "",
        *markdown_table(slide, SLIDE_COLUMNS),
        "",
        f"![velocity against time]({PAGE}-slide.png)",
        "",
        f"Reading: the deceleration is μg and the block stops where and when it should: stop time",
        f"within {max(relative(r, 'stop_time', 'stop_time_exact') for r in rubber):.1e} and distance within "
        f"{max(relative(r, 'final_distance', 'stop_distance_exact') for r in rubber):.1e} at every time step tried, in 2D and 3D;",
        "it stays at rest after the stop (static friction; the plot). A step costs at most "
        f"{min(int(r['hessian_per_step_max']) for r in rubber)} to {max(int(r['hessian_per_step_max']) for r in rubber)}",
        "multiplications (the projection and the Coulomb fixed point's Tresca solves together). The",
        "scene sets its steps up with the conjugate projector (c dt / h of 65 to 200 here); one step",
        "stands out, the first of the 3D run in 15 steps "
        f"({max(int(r['hessian_per_step_max']) for r in rubber if r['dim'] == '3' and r['law'] == 'coulomb')} multiplications: the Coulomb fixed point from the",
        "static state, where every row starts to slip: loose warm Tresca solves of 1 to 3 multiplications",
        "report bounds nearly settled, and the ten times tighter solve after them moves the bounds by a",
        "fifth for hundreds of multiplications; traced in docs/log.md, 2026-12-07, twenty-fifth session).",
        "The steel row is what does not work",
        "yet: with steel's stiffness a step is about a hundred times the time a wave takes to cross",
        "an element, Keff is nearly the floating K (the block's rigid sliding held only by its mass",
        f"term), and a step's dual solve ends `{steel['status']}` (here with the conjugate projector, the",
        f"scene's choice: `{steel.get('projector', '')}`; without it as well, docs/log.md 2026-12-06): the dual",
        "operator is so nearly singular that round-off hides its curvature. The KKT residual stands at a",
        "floor far above tol, and the solve ends either at maxit (`max_iterations`, above the ceiling below",
        "which the stop test calls that stagnation) or on a direction whose curvature came out at most 0",
        "(`not_positive_definite`), whichever the solver's path meets first ([log](../log.md), 2026-12-07).",
        "",
        "## MPI, and what is not here yet",
        "",
        "Under MPI the bar gives the serial answer on 2 and 3 ranks (`ctest -R mpi_dynamics`); the",
        "sliding block and the hemisphere assemble every subdomain on every rank and are serial scenes.",
        "A run killed mid-way resumes from its state file with the uninterrupted run's answer and",
        "history (`bar-impact.edp -state FILE -resume 1`, `ctest -R edp_dynamics_resume`).",
        "Chosen steps go to ParaView as a time series (`bar-impact.edp -vtk PREFIX -every N`).",
        "Not yet: the conjugate projector, a direct peer, `ffeti-solve`'s dynamics section (issue 56).",
    ]
    save_page(f"{PAGE}.md", lines)


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--render", action="store_true", help="re-render the page from its CSVs, no run")
    if not parser.parse_args().render:
        begun = begin_run()
        write_csv(PAGE, "bar", bar_rows())
        write_csv(PAGE, "bar-history", bar_histories())
        write_csv(PAGE, "wave", wave_rows())
        bounce, bounce_history = bounce_rows()
        write_csv(PAGE, "bounce", bounce)
        write_csv(PAGE, "bounce-history", bounce_history)
        write_csv(PAGE, "membranes", membrane_rows())
        write_csv(PAGE, "sphere", sphere_rows())
        write_csv(PAGE, "sphere-history", sphere_history())
        write_csv(PAGE, "slide", slide_rows())
        write_csv(PAGE, "slide-history", slide_history())
        end_run(PAGE, begun)
    render()


if __name__ == "__main__":
    main()
