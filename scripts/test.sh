#!/usr/bin/env bash
# Sets up (installs what is missing, builds) and runs every test: GoogleTest unit tests of
# the core and the .edp regression tests through FreeFEM.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
"$root/scripts/setup.sh"
cd "${FFETI_BUILD:-$root/build}"
ctest --output-on-failure -j "$(nproc)"
