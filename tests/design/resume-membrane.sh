#!/usr/bin/env bash
# The membrane design loop stopped after 4 analyses and resumed from its history file
# reaches the same final design, bit for bit, as an uninterrupted run, and the resumed run
# analyses only the designs the stopped one had not reached.
# Usage: resume-membrane.sh SOURCE_DIR   (run where freefem++.pref points at the build)
set -euo pipefail
script="$1/edp/membrane-shape.edp"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
options=(-n 32 -Hh 16 -k 4 -maxiter 30)
value() { grep '^RESULT ' | tr ' ' '\n' | sed -n "s/^$1=//p"; }

whole=$(FreeFem++-nw -v 0 "$script" "${options[@]}" -history "$work/whole.history")
set +e
FreeFem++-nw -v 0 "$script" "${options[@]}" -history "$work/stopped.history" -stopafter 4 > "$work/stopped.log" 2>&1
stopped_status=$?
set -e
stopped_rows=$(head -n 1 "$work/stopped.history" | cut -d' ' -f1)
resumed=$(FreeFem++-nw -v 0 "$script" "${options[@]}" -history "$work/stopped.history" -resume 1)

failures=0
check() { if [ "$2" = "$3" ]; then echo "ok: $1: $2"; else echo "FAILED: $1: $2 (expected $3)"; failures=$((failures + 1)); fi; }
check "stopped run killed (SIGKILL)" "$stopped_status" 137
check "history rows when stopped" "$stopped_rows" 4
check "final design" "$(printf '%s\n' "$resumed" | value design)" "$(printf '%s\n' "$whole" | value design)"
check "steps" "$(printf '%s\n' "$resumed" | value steps)" "$(printf '%s\n' "$whole" | value steps)"
check "factorizations" "$(printf '%s\n' "$resumed" | value factorizations)" "$(printf '%s\n' "$whole" | value factorizations)"
steps=$(printf '%s\n' "$whole" | value steps)
check "analyses of the resumed run" "$(printf '%s\n' "$resumed" | value analyses_this_run)" "$((steps - 4))"
check "status" "$(printf '%s\n' "$resumed" | value status)" 0
[ "$failures" -eq 0 ] && echo "all checks passed" || { echo "$failures check(s) failed"; exit 1; }
