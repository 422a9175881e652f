#!/usr/bin/env bash
# Sets up (installs what is missing, builds, installs) and runs the main job: the seed's
# model problem for h = 1/64 .. 1/512 through FreeFEM. Extra arguments go to the script,
# e.g. -n 256 -tol 1e-6 -variant tfeti.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
"$root/scripts/setup.sh"
cd "$root/edp"
FreeFem++-nw -v 0 model-problem.edp "$@"
