#!/usr/bin/env bash
# Snapshot of the machine-independent counts every test prints (RESULT and LESSON lines:
# Hessian multiplications, iterations, statuses, active sets, energies), times dropped, one
# sorted file. Take one before a refactoring and one after: `diff` must show nothing.
# Usage: count-snapshot.sh OUT [ctest arguments]   (needs the build, scripts/setup.sh)
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
out=$(realpath -m "$1")
shift
cd "${FFETI_BUILD:-$root/build}"
ctest -V -j "$(nproc)" -E fuzz "$@" 2>&1 \
  | grep -E '^[0-9]+: .*(RESULT|LESSON|hessian=|outer=)' \
  | sed -E 's/ [a-z_]*(time|seconds|wall)[a-z_]*=[^ ]*//g; s/ tmp\.[A-Za-z0-9]+//g' \
  | sed -E 's/^[0-9]+: //' | sort > "$out"
echo "$(wc -l < "$out") lines of counts in $out"
