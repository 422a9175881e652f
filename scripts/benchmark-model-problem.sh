#!/usr/bin/env bash
# Benchmark of the seed's model problem: numerical scalability, what accuracy costs,
# solver variants, and the direct-solver floor. Writes docs/results/model-problem.md and
# its plots. Takes a few minutes on 2 cores. Not a test: it measures and reports.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
"$root/scripts/setup.sh"
dpkg-query -W -f='${Status}' python3-matplotlib 2>/dev/null | grep -q "install ok installed" || {
  as_root=(); [ "$(id -u)" -eq 0 ] || as_root=(sudo)
  "${as_root[@]}" apt-get install -y -qq python3-matplotlib >/dev/null
}
/usr/bin/python3 "$root/scripts/model_problem_benchmark.py" "$@"
