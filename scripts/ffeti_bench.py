"""Shared helpers of the benchmark drivers: run FreeFEM scripts, parse their result lines,
describe the machine."""
import os
import platform
import re
import subprocess

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
EDP = os.path.join(ROOT, "edp")
OUT = os.path.join(ROOT, "docs", "results")
MPI_ENV = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")


def run(script, *args, ranks=0, prefixes=("RESULT", "DIRECT", "RANK")):
    """Runs an .edp script (under mpirun with `ranks` > 0) and returns {prefix: [dict, ...]}
    of its key=value result lines."""
    command = ["FreeFem++-nw", "-v", "0", script, *map(str, args)]
    if ranks:
        command = ["mpirun", "--oversubscribe", "-np", str(ranks), "FreeFem++-mpi", *command[1:]]
    text = subprocess.run(command, cwd=EDP, capture_output=True, text=True, check=True, env=MPI_ENV).stdout
    lines = {prefix: [] for prefix in prefixes}
    for line in text.splitlines():
        words = line.split()
        if words and words[0] in lines:
            lines[words[0]].append(dict(kv.split("=", 1) for kv in words[1:] if "=" in kv))
    if not any(lines.values()):
        raise RuntimeError(f"no result line from {' '.join(command)}:\n{text[-2000:]}")
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
