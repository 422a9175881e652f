#!/usr/bin/env bash
# The 3D lug's design loop (edp/lug-opt-3d.edp, a coarse mesh, 6 variables, 8 IPOPT
# iterations) cuts the true peak stress by 20 % at equal volume (-check 0.2: the run fails
# otherwise), and stopped after 4 analyses and resumed from its history file it reaches the
# same final design, bit for bit, as an uninterrupted run, analysing only the designs the
# stopped run had not reached.
# Usage: resume-lug.sh SOURCE_DIR   (run where freefem++.pref points at the build)
set -euo pipefail
script="$1/edp/lug-opt-3d.edp"
options=(-size 4 -parts 6 -pinParts 1 -k 6 -maxiter 8 -check 0.2)
source "$(dirname "${BASH_SOURCE[0]}")/resume-common.sh"

check "final design" "$(printf '%s\n' "$resumed" | value design)" "$(printf '%s\n' "$whole" | value design)"
check "steps" "$(printf '%s\n' "$resumed" | value steps)" "$(printf '%s\n' "$whole" | value steps)"
check "true maximum" "$(printf '%s\n' "$resumed" | value true_max)" "$(printf '%s\n' "$whole" | value true_max)"
check "remeshes" "$(printf '%s\n' "$resumed" | value remeshes)" "$(printf '%s\n' "$whole" | value remeshes)"
steps=$(printf '%s\n' "$whole" | value steps)
check "analyses of the resumed run" "$(printf '%s\n' "$resumed" | value analyses_this_run)" "$((steps - 4))"
finish
