"""Shared helpers of the benchmark drivers: run FreeFEM scripts, parse their result lines,
describe the machine, and keep each measured table as raw data.

Every measured table of a results page goes through one path: its rows (dicts, one per
measurement, the values as the run printed them or as a driver computed them, full
precision) are written to docs/results/<page>-<table>.csv by write_csv, and the page's
Markdown table and plots are drawn from the rows read back from that file (markdown_table;
read_csv re-reads them, so a driver can re-render its page from the CSVs alone). Neither
pandas nor tabulate is installed from Debian here: markdown_table is the one small
formatter all drivers share. The run itself (machine, load, duration) is one more table,
<page>-run.csv (begin_run / end_run, machine_line).

FFETI_RESULTS overrides the output folder (to try a driver without touching docs/results)."""
import argparse
import csv
import datetime
import os
import platform
import re
import resource
import subprocess
import tempfile
import threading
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
EDP = os.path.join(ROOT, "edp")
# The readings (hand-written, docs/results/*-reading.md) stay in the repository's folder.
READINGS = os.path.join(ROOT, "docs", "results")
OUT = os.environ.get("FFETI_RESULTS", READINGS)
MPI_ENV = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")


class OverLimit(Exception):
    """A run stopped by run()'s limits: `what` is "time" (killed after `seconds`) or "memory"
    (under an address space limit, the process died by a signal or failed naming memory or an
    allocation)."""

    def __init__(self, what, seconds):
        super().__init__(f"{what} limit reached after {seconds:.0f} s")
        self.what, self.seconds = what, seconds


def run(script, *args, ranks=0, prefixes=("RESULT", "DIRECT", "RANK"), seconds=None, memory_mb=None):
    """Runs an .edp script (under mpirun with `ranks` > 0) and returns {prefix: [dict, ...]}
    of its key=value result lines, each with the process's peak resident memory as
    'process_peak_mb' (of FreeFEM alone; of mpirun, not its ranks, under MPI), and its whole
    standard output under 'output' (progress lines). Optional limits (OverLimit when reached):
    `seconds` of wall clock (the process is killed), `memory_mb` of address space (RLIMIT_AS,
    which the process's allocations then fail against: a bound on its virtual memory, which is at
    least its resident set)."""
    # FFETI_RUN_DIR: run from that folder instead (a build tree's edp-tests folder, whose
    # freefem++.pref loads that build's plugin rather than the installed one).
    run_dir = os.environ.get("FFETI_RUN_DIR")
    command = ["FreeFem++-nw", "-v", "0", os.path.join(EDP, script) if run_dir else script, *map(str, args)]
    if ranks:
        command = ["mpirun", "--oversubscribe", "-np", str(ranks), "FreeFem++-mpi", *command[1:]]
    with tempfile.TemporaryFile(mode="w+") as output:
        def limit_memory():
            size = int(memory_mb * 1024 * 1024)
            resource.setrlimit(resource.RLIMIT_AS, (size, size))

        started = time.time()
        process = subprocess.Popen(command, cwd=run_dir or EDP, stdout=output, stderr=subprocess.DEVNULL, text=True,
                                   env=MPI_ENV, preexec_fn=limit_memory if memory_mb else None)
        killer = threading.Timer(seconds, process.kill) if seconds else None
        if killer:
            killer.start()
        _, status, usage = os.wait4(process.pid, 0)
        if killer:
            killer.cancel()
        elapsed = time.time() - started
        if seconds and elapsed >= seconds:
            raise OverLimit("time", elapsed)
        process.returncode = os.waitstatus_to_exitcode(status)
        output.seek(0)
        text = output.read()
    # FreeFEM dies by a signal (a segmentation fault) when an allocation fails, or names it.
    if memory_mb and (process.returncode < 0 or (process.returncode != 0 and re.search("memory|alloc", text, re.I))):
        raise OverLimit("memory", elapsed)
    if process.returncode != 0:
        raise subprocess.CalledProcessError(process.returncode, command, text)
    peak_mb = usage.ru_maxrss / 1024  # kB on Linux: MB, unrounded
    lines = {prefix: [] for prefix in prefixes}
    for line in text.splitlines():
        words = line.split()
        if words and words[0] in lines:
            fields = dict(kv.split("=", 1) for kv in words[1:] if "=" in kv)
            fields["process_peak_mb"] = repr(peak_mb)
            lines[words[0]].append(fields)
    if not any(lines.values()):
        raise RuntimeError(f"no result line from {' '.join(command)}:\n{text[-2000:]}")
    lines["output"] = text
    return lines


def model_problem(n, ranks=0, **options):
    """One size of edp/model-problem.edp: its RESULT line with its RANK lines as 'ranks_detail'."""
    args = ["-n", n]
    for key, value in options.items():
        args += [f"-{key}", value]
    lines = run("model-problem.edp", *args, ranks=ranks)
    result = lines["RESULT"][0]
    result["ranks_detail"] = lines["RANK"]
    return result


def f(row, key):
    return float(row[key])


def machine():
    """CPU, cores, memory and system of this machine, as one row (dict)."""
    cpu = "unknown CPU"
    try:
        with open("/proc/cpuinfo") as info:
            cpu = re.search(r"model name\s*:\s*(.*)", info.read()).group(1)
    except (OSError, AttributeError):
        pass
    memory = ""
    try:
        with open("/proc/meminfo") as info:
            memory = repr(int(info.readline().split()[1]) / 2**20)
    except (OSError, ValueError, IndexError):
        pass
    return {"cpu": cpu, "cores": os.cpu_count(), "memory_gib": memory,
            "system": f"{platform.system()} {platform.release()}"}


def load_average():
    """The 1-minute load average (/proc/loadavg), or '' where there is none."""
    try:
        with open("/proc/loadavg") as file:
            return file.read().split()[0]
    except (OSError, IndexError):
        return ""


def begin_run():
    """What a driver notes as its run starts: the time and the machine's load (other work)."""
    return {"started": time.time(), "load_at_start": load_average()}


def end_run(page, begun, table="run"):
    """Writes the run's own row, docs/results/<page>-<table>.csv (a part of a page run alone
    names its own table): the machine, the date, the whole run in seconds and the load
    average at its start and end; returns it read back."""
    row = dict(machine(), date=datetime.datetime.now().isoformat(timespec="seconds"),
               elapsed_s=repr(time.time() - begun["started"]), load_at_start=begun["load_at_start"],
               load_at_end=load_average())
    return write_csv(page, table, [row])[0]


def machine_line(run_row):
    """The page's machine line, from its run row: the machine, the whole run and the load
    it ran under (the 1-minute load average; on a shared machine other work slows times)."""
    memory = f", {float(run_row['memory_gib']):.0f} GiB" if run_row.get("memory_gib") else ""
    line = f"{run_row['cpu']}, {run_row['cores']} cores{memory}, {run_row['system']}."
    if run_row.get("elapsed_s"):
        elapsed = float(run_row["elapsed_s"])
        line += f" Whole run: {elapsed:.{0 if elapsed >= 10 else 1}f} s."
    if run_row.get("load_at_start"):
        line += (f" Load average (1 min) {float(run_row['load_at_start']):.1f} as the run started, "
                 f"{float(run_row['load_at_end']):.1f} as it ended, on {run_row['cores']} cores")
        line += (": other work shared the machine, so times are those of a loaded machine."
                 if float(run_row["load_at_start"]) >= 0.5 else ".")
    return line


def run_machine(run_row):
    """The machine a part of a page ran on (its run row's processor): a part re-run on its own
    may have run on another machine than the page's whole run, whose line the header holds."""
    return run_row.get("cpu") or "an unrecorded machine"


def own_run_words(page, table, otherwise):
    """Which run a table comes from: `otherwise` (the page's run), or its own later run recorded
    in docs/results/<page>-<table>.csv (end_run with that table)."""
    if not os.path.exists(csv_path(page, table)):
        return otherwise
    own = read_csv(page, table)[0]
    return (f"a run of this table on its own on {run_machine(own)} ({own['date']}, {float(own['elapsed_s']):.0f} s, "
            f"load average {float(own['load_at_start']):.1f} as it started), after the page's run")


def forget_run(page, table):
    """A page's full run measures every part itself: the record of an earlier run of a part on
    its own (end_run with that table) no longer applies, and goes."""
    if os.path.exists(csv_path(page, table)):
        os.remove(csv_path(page, table))


def csv_path(page, table):
    return os.path.join(OUT, f"{page}-{table}.csv")


def write_csv(page, table, rows):
    """Writes one measured table to docs/results/<page>-<table>.csv: one line per row (dict),
    the columns the union of the rows' keys in first-seen order (empty where a row has no
    such key), values as given (the run's printed text, or a driver's float written by repr:
    full precision); list and dict values (per-rank details) are not written. Returns the
    rows read back from the file, to render and plot from."""
    os.makedirs(OUT, exist_ok=True)
    columns = []
    for row in rows:
        columns += [key for key, value in row.items() if key not in columns and not isinstance(value, (list, dict))]
    with open(csv_path(page, table), "w", newline="") as file:
        writer = csv.DictWriter(file, fieldnames=columns, restval="", extrasaction="ignore")
        writer.writeheader()
        for row in rows:
            writer.writerow({key: repr(value) if isinstance(value, float) else value for key, value in row.items()})
    return read_csv(page, table)


def read_csv(page, table):
    """The rows of docs/results/<page>-<table>.csv as dicts of strings ('' where empty)."""
    with open(csv_path(page, table), newline="") as file:
        return list(csv.DictReader(file))


def cell(row, spec):
    """One table cell of a row: spec a key (its text as written; '-' when empty), a (key,
    format spec) pair (the number formatted, e.g. ".3f", ".1e", ".1%"; '-' when empty) or a
    function of the row returning the cell's text."""
    if callable(spec):
        return str(spec(row))
    key, number_format = spec if isinstance(spec, tuple) else (spec, None)
    text = row.get(key, "")
    if text == "":
        return "-"
    return format(float(text), number_format) if number_format else str(text)


def markdown_table(rows, columns):
    """The Markdown lines of a table: columns a list of (header, cell spec) (see cell), one
    line per row (rows as read back by write_csv / read_csv)."""
    lines = ["| " + " | ".join(header for header, _ in columns) + " |", "|" + "---|" * len(columns)]
    lines += ["| " + " | ".join(cell(row, spec) for _, spec in columns) + " |" for row in rows]
    return lines


# The whole scene's phases as the scenes print them (edp/ffeti-phases.idp), in the order they
# run: (header, key). time_coarse is part of the plugin's set-up; time_scene is their sum.
PHASES = [("assembly", "time_assembly"), ("plugin set-up", "time_plugin_setup"), ("factorization", "time_factor"),
          ("dual solve", "time_solve"), ("recovery", "time_recovery")]


def phase_table(rows, first=(("n", "n"),)):
    """The Markdown lines of a per-phase table: the columns `first`, then each phase's seconds
    (the coarse problem's among the plugin's set-up), the whole scene, each phase's share of
    it and the process's peak memory."""
    columns = list(first) + [(f"{label} [s]", (key, ".2f")) for label, key in PHASES[:2]]
    columns += [("of which coarse [s]", ("time_coarse", ".3f"))]
    columns += [(f"{label} [s]", (key, ".3f" if key == "time_recovery" else ".2f")) for label, key in PHASES[2:]]
    columns += [("whole scene [s]", ("time_scene", ".2f")),
                ("shares: " + " / ".join(label for label, _ in PHASES),
                 lambda r: " / ".join(f"{100 * f(r, key) / f(r, 'time_scene'):.0f} %" for _, key in PHASES)),
                ("peak MB", ("process_peak_mb", ".0f"))]
    return markdown_table(rows, columns)


def span(values, number_format="", unit=""):
    """'a to b' (or 'a' when all equal) of the smallest and largest of values, formatted."""
    low, high = format(min(values), number_format), format(max(values), number_format)
    return f"{low}{unit}" if low == high else f"{low} to {high}{unit}"


def listing(values, number_format=""):
    """'a, b, c' of values, formatted."""
    return ", ".join(format(v, number_format) for v in values)


def save_page(name, lines):
    """Writes a generated page docs/results/<name> (rendered from its CSVs)."""
    os.makedirs(OUT, exist_ok=True)
    with open(os.path.join(OUT, name), "w") as page:
        page.write("\n".join(lines))


def plot_cost_over_unknowns(runs, title, name, legend_columns=3):
    """Two log-log panels, Hessian multiplications and dual solve time against the unknowns,
    one line per case of `runs` ({label: [row, ...]}, rows as read back from a CSV); rows
    without a multiplication (a scene with nothing to iterate) are left out. Saved as
    docs/results/<name>."""
    import matplotlib.pyplot as plt  # the drivers choose the backend first

    fig, axes = plt.subplots(1, 2, figsize=(11, 5.4))
    for k, (label, rows) in enumerate(runs.items()):
        rows = [r for r in rows if f(r, "hessian") > 0]
        unknowns = [f(r, "primal") for r in rows]
        style = "o-" if k < 10 else "s--"  # the colour cycle has 10 colours: past it, another line style
        axes[0].loglog(unknowns, [f(r, "hessian") for r in rows], style, label=label)
        axes[1].loglog(unknowns, [f(r, "time_solve") for r in rows], style, label=label)
    axes[0].set_ylabel("Hessian multiplications")
    axes[1].set_ylabel("dual solve time [s]")
    for ax in axes:
        ax.set_xlabel("unknowns")
        ax.grid(True, which="both", alpha=0.3)
    # Below the panels: inside, the legend hid the lowest lines (the glued cases).
    handles, labels = axes[0].get_legend_handles_labels()
    fig.legend(handles, labels, loc="lower center", ncol=legend_columns, fontsize=7, frameon=False)
    fig.suptitle(title)
    fig.tight_layout(rect=(0, 0.14, 1, 1))
    fig.savefig(os.path.join(OUT, name), dpi=110)
    plt.close(fig)


def measure_and_render(doc, measure, render, parts=None):
    """A driver's command line: measure() then render() the page, or with --render only
    render() it from the CSVs, or with --only NAME the part `parts[NAME]` (a function that
    measures one table and writes its own run row) alone, the other tables kept; `doc` (the
    driver's docstring) describes it."""
    parser = argparse.ArgumentParser(description=doc.split("\n")[0])
    parser.add_argument("--render", action="store_true", help="redraw the page from the CSVs alone")
    if parts:
        parser.add_argument("--only", choices=sorted(parts), help="measure this part alone, keep the other tables")
    options = parser.parse_args()
    if getattr(options, "only", None):
        parts[options.only]()
    elif not options.render:
        measure()
    render()
