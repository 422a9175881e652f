#!/usr/bin/env bash
# Runs a gradient test script (GRADIENT and RESULT lines) in one process and under mpirun
# with 2 and 3 ranks and checks that the sensitivities do not depend on the rank count: the
# same classification and Hessian multiplications, direct and adjoint gradients equal to
# 1e-10 relative.
# Usage: compare-sensitivity-ranks.sh SCRIPT [ARGS...]   (run where freefem++.pref points at the build)
set -euo pipefail
script=$1
shift
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1

# "i direct adjoint" per design variable, then the RESULT line's counts.
summary() { sed -n 's/^GRADIENT i=\([0-9]*\) direct=\([^ ]*\) adjoint=\([^ ]*\) .*/\1 \2 \3/p'; }
counts() { grep '^RESULT ' | tr ' ' '\n' | grep -E '^(sens_hessian_total|adjoint_hessian|sens_strong)='; }

serial_out=$(FreeFem++-nw -v 0 "$script" "$@")
serial=$(printf '%s\n' "$serial_out" | summary)
[ -n "$serial" ] || { echo "no GRADIENT lines from the serial run"; exit 1; }
failures=0
for ranks in 2 3; do
  out=$(mpirun --oversubscribe -np "$ranks" FreeFem++-mpi -v 0 "$script" "$@")
  parallel=$(printf '%s\n' "$out" | summary)
  if [ "$(printf '%s\n' "$serial_out" | counts)" = "$(printf '%s\n' "$out" | counts)" ]; then
    echo "ok: $ranks ranks: $(printf '%s\n' "$out" | counts | tr '\n' ' ')"
  else
    echo "FAILED: $ranks ranks: counts $(printf '%s\n' "$out" | counts | tr '\n' ' ')"; failures=$((failures + 1))
  fi
  if paste <(printf '%s\n' "$serial") <(printf '%s\n' "$parallel") | awk '
       function rel(a, b) { d = a - b; if (d < 0) d = -d; s = a < 0 ? -a : a; return d <= 1e-10 * s }
       NF != 6 || !rel($2, $5) || !rel($3, $6) { bad = 1; print "FAILED: variable " $1 ": " $0 }
       END { exit bad }'; then
    echo "ok: $ranks ranks: gradients equal to 1e-10"
  else
    failures=$((failures + 1))
  fi
done
[ "$failures" -eq 0 ] && echo "all checks passed" || { echo "$failures check(s) failed"; exit 1; }
