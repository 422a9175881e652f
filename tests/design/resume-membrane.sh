#!/usr/bin/env bash
# The membrane design loop stopped after 4 analyses and resumed from its history file
# reaches the same final design, bit for bit, as an uninterrupted run, and the resumed run
# analyses only the designs the stopped one had not reached.
# Usage: resume-membrane.sh SOURCE_DIR   (run where freefem++.pref points at the build)
set -euo pipefail
script="$1/edp/membrane-shape.edp"
options=(-n 32 -Hh 16 -k 4 -maxiter 30)
source "$(dirname "${BASH_SOURCE[0]}")/resume-common.sh"

check "final design" "$(printf '%s\n' "$resumed" | value design)" "$(printf '%s\n' "$whole" | value design)"
check "steps" "$(printf '%s\n' "$resumed" | value steps)" "$(printf '%s\n' "$whole" | value steps)"
check "factorizations" "$(printf '%s\n' "$resumed" | value factorizations)" "$(printf '%s\n' "$whole" | value factorizations)"
steps=$(printf '%s\n' "$whole" | value steps)
check "analyses of the resumed run" "$(printf '%s\n' "$resumed" | value analyses_this_run)" "$((steps - 4))"
check "status" "$(printf '%s\n' "$resumed" | value status)" 0
finish
