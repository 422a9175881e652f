#!/usr/bin/env bash
# The Newton loop of a gap design (edp/uniform-pressure.edp -optimizer newton) stopped after
# 4 analyses and resumed from its history (and the Hessians kept beside it) reaches the same
# final design, bit for bit, as an uninterrupted run, analysing only the designs the stopped
# run had not reached and computing no Hessian it had kept.
# Usage: resume-newton.sh SOURCE_DIR   (run where freefem++.pref points at the build)
set -euo pipefail
script="$1/edp/uniform-pressure.edp"
options=(-optimizer newton)
# The Hessians the stopped run kept (read before the resume appends to the file).
before_resume() { stopped_hessians=$(head -n 1 "$work/stopped.history.hessian" | cut -d' ' -f1); }
source "$(dirname "${BASH_SOURCE[0]}")/resume-common.sh"

for key in cost pressure_cv area_multiplier stationarity steps newton_steps hessians; do
  check "$key" "$(printf '%s\n' "$resumed" | value $key)" "$(printf '%s\n' "$whole" | value $key)"
done
steps=$(printf '%s\n' "$whole" | value steps)
hessians=$(printf '%s\n' "$whole" | value hessians)
check "analyses of the resumed run" "$(printf '%s\n' "$resumed" | value analyses_this_run)" "$((steps - 4))"
per_hessian=$(( $(printf '%s\n' "$whole" | value hessian_solves) / hessians ))
check "Hessian solves of the resumed run" "$(printf '%s\n' "$resumed" | value hessian_solves)" "$(( (hessians - stopped_hessians) * per_hessian ))"
check "status" "$(printf '%s\n' "$resumed" | value status)" 0
finish
