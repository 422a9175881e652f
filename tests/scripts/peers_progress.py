"""The direct peers benchmark's bookkeeping (scripts/three_dimensions_peers.py), with a fake
solve in place of FreeFEM: a peer that ends without an answer (energy 0) is a "failed" row, not
the reference, and runs no larger size (the 2026-12-07 run of the page died dividing by such an
energy after 90 minutes); every size done is in the progress file, and a run started again
takes the sizes done from it and runs only the others."""
import os
import sys
import tempfile
import types

sys.path.insert(0, os.path.join(sys.argv[1], "scripts"))
# The bookkeeping needs no plotting: a stand-in keeps the test free of matplotlib.
sys.modules.setdefault("matplotlib", types.ModuleType("matplotlib"))
sys.modules.setdefault("matplotlib.pyplot", types.ModuleType("matplotlib.pyplot"))
import ffeti_bench  # noqa: E402

ffeti_bench.OUT = tempfile.mkdtemp()
import three_dimensions_peers as peers  # noqa: E402

calls = []


def solve(size, *flags, **options):
    """FETI, UMFPACK (options feti=0) or MUMPS (a flag); UMFPACK gives no answer at size 16."""
    solver = "MUMPS" if flags else ("UMFPACK" if options.get("feti") == 0 else "FETI")
    calls.append((size, solver))
    energy = "0" if (solver == "UMFPACK" and size == 16) else "-1.5"
    return dict(problem="cubes", size=str(size), unknowns=str(1000 * size), time_total="1.0", process_peak_mb="10",
                energy=energy, active="5", status="converged")


def fail(message):
    print("FAILED:", message)
    sys.exit(1)


rows = peers.measure_problem("cubes", [8, 16, 32], solve, {}, dict(feti=0), [])
status = {(r["size"], r["solver"]): r["status"] for r in rows}
if status.get(("16", "UMFPACK")) != "failed":
    fail(f"UMFPACK's zero energy at size 16 is not a failed row: {status}")
if (32, "UMFPACK") in calls:
    fail("a failed peer ran a larger size")
feti16 = next(r for r in rows if r["size"] == "16" and r["solver"] == peers.FETI)
if feti16.get("energy_reference_solver") != "MUMPS":
    fail(f"FETI at size 16 compared with {feti16.get('energy_reference_solver')!r}, not MUMPS")

calls.clear()
again = peers.measure_problem("cubes", [8, 16, 32], solve, {}, dict(feti=0), peers.read_progress())
if calls:
    fail(f"a run with every size in its progress file solved again: {calls}")
if [(r["size"], r["solver"], r["status"]) for r in again] != [(r["size"], r["solver"], r["status"]) for r in rows]:
    fail("the rows read back from the progress file differ from the run's")

os.remove(ffeti_bench.csv_path(peers.PAGE, peers.PROGRESS))
peers.record_progress([r for r in rows if r["size"] == "8"])
calls.clear()
peers.measure_problem("cubes", [8, 16, 32], solve, {}, dict(feti=0), peers.read_progress())
if (8, "FETI") in calls or (16, "FETI") not in calls or (32, "UMFPACK") in calls:
    fail(f"an interrupted run did not go on from its progress file: {calls}")
print("ok: failed peers and the progress file")
