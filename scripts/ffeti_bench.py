"""Shared helpers of the benchmark drivers: run FreeFEM scripts, parse their result lines,
describe the machine."""
import os
import platform
import re
import subprocess
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
EDP = os.path.join(ROOT, "edp")
OUT = os.path.join(ROOT, "docs", "results")
MPI_ENV = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")


def run(script, *args, ranks=0, prefixes=("RESULT", "DIRECT", "RANK")):
    """Runs an .edp script (under mpirun with `ranks` > 0) and returns {prefix: [dict, ...]}
    of its key=value result lines, each with the process's peak resident memory as
    'process_peak_mb' (of FreeFEM alone; of mpirun, not its ranks, under MPI), and its whole
    standard output under 'output' (progress lines)."""
    command = ["FreeFem++-nw", "-v", "0", script, *map(str, args)]
    if ranks:
        command = ["mpirun", "--oversubscribe", "-np", str(ranks), "FreeFem++-mpi", *command[1:]]
    with tempfile.TemporaryFile(mode="w+") as output:
        process = subprocess.Popen(command, cwd=EDP, stdout=output, stderr=subprocess.DEVNULL, text=True, env=MPI_ENV)
        _, status, usage = os.wait4(process.pid, 0)
        process.returncode = os.waitstatus_to_exitcode(status)
        output.seek(0)
        text = output.read()
    if process.returncode != 0:
        raise subprocess.CalledProcessError(process.returncode, command, text)
    peak_mb = usage.ru_maxrss / 1024  # kB on Linux
    lines = {prefix: [] for prefix in prefixes}
    for line in text.splitlines():
        words = line.split()
        if words and words[0] in lines:
            fields = dict(kv.split("=", 1) for kv in words[1:] if "=" in kv)
            fields["process_peak_mb"] = f"{peak_mb:.0f}"
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
    cpu = "unknown CPU"
    try:
        with open("/proc/cpuinfo") as info:
            cpu = re.search(r"model name\s*:\s*(.*)", info.read()).group(1)
    except (OSError, AttributeError):
        pass
    memory = ""
    try:
        with open("/proc/meminfo") as info:
            memory = f", {int(info.readline().split()[1]) / 2**20:.0f} GiB"
    except (OSError, ValueError, IndexError):
        pass
    return f"{cpu}, {os.cpu_count()} cores{memory}, {platform.system()} {platform.release()}"


def save_page(name, lines):
    """Writes a generated page docs/results/<name>."""
    os.makedirs(OUT, exist_ok=True)
    with open(os.path.join(OUT, name), "w") as page:
        page.write("\n".join(lines))


def plot_cost_over_unknowns(runs, title, name, legend_columns=3):
    """Two log-log panels, Hessian multiplications and dual solve time against the unknowns,
    one line per case of `runs` ({label: [result, ...]}); rows without a multiplication (a
    scene with nothing to iterate) are left out. Saved as docs/results/<name>."""
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
