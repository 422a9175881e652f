#!/usr/bin/env bash
# The Newton loop of a gap design (edp/uniform-pressure.edp -optimizer newton) stopped after
# 4 analyses and resumed from its history (and the Hessians kept beside it) reaches the same
# final design, bit for bit, as an uninterrupted run, analysing only the designs the stopped
# run had not reached and computing no Hessian it had kept.
# Usage: resume-newton.sh SOURCE_DIR   (run where freefem++.pref points at the build)
set -euo pipefail
script="$1/edp/uniform-pressure.edp"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
options=(-optimizer newton)
value() { grep '^RESULT ' | tr ' ' '\n' | sed -n "s/^$1=//p"; }

whole=$(FreeFem++-nw -v 0 "$script" "${options[@]}" -history "$work/whole.history")
set +e
FreeFem++-nw -v 0 "$script" "${options[@]}" -history "$work/stopped.history" -stopafter 4 > "$work/stopped.log" 2>&1
stopped_status=$?
set -e
stopped_rows=$(head -n 1 "$work/stopped.history" | cut -d' ' -f1)
stopped_hessians=$(head -n 1 "$work/stopped.history.hessian" | cut -d' ' -f1)
resumed=$(FreeFem++-nw -v 0 "$script" "${options[@]}" -history "$work/stopped.history" -resume 1)

failures=0
check() { if [ "$2" = "$3" ]; then echo "ok: $1: $2"; else echo "FAILED: $1: $2 (expected $3)"; failures=$((failures + 1)); fi; }
check "stopped run killed (SIGKILL)" "$stopped_status" 137
check "history rows when stopped" "$stopped_rows" 4
for key in cost pressure_cv area_multiplier stationarity steps newton_steps hessians; do
  check "$key" "$(printf '%s\n' "$resumed" | value $key)" "$(printf '%s\n' "$whole" | value $key)"
done
steps=$(printf '%s\n' "$whole" | value steps)
hessians=$(printf '%s\n' "$whole" | value hessians)
check "analyses of the resumed run" "$(printf '%s\n' "$resumed" | value analyses_this_run)" "$((steps - 4))"
per_hessian=$(( $(printf '%s\n' "$whole" | value hessian_solves) / hessians ))
check "Hessian solves of the resumed run" "$(printf '%s\n' "$resumed" | value hessian_solves)" "$(( (hessians - stopped_hessians) * per_hessian ))"
check "status" "$(printf '%s\n' "$resumed" | value status)" 0
[ "$failures" -eq 0 ] && echo "all checks passed" || { echo "$failures check(s) failed"; exit 1; }
