#!/usr/bin/env bash
# A transient run (edp/bar-impact.edp, a bar bouncing under gravity, both schemes) killed
# after step 120 and resumed from its state file gives the uninterrupted run's RESULT line
# and history file byte for byte; a history line written after the last state (killed
# between the two writes) is dropped on resume.
# Usage: resume-dynamics.sh SOURCE_DIR   (run where freefem++.pref points at the build)
set -euo pipefail
script="$1/edp/bar-impact.edp"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
check() { if [ "$2" = "$3" ]; then echo "ok: $1"; else echo "FAILED: $1: $2 (expected $3)"; failures=$((failures + 1)); fi; }
for scheme in stabilized newmark; do
  options=(-g 2e4 -n 20 -steps 300 -scheme "$scheme")
  whole=$(FreeFem++-nw -v 0 "$script" "${options[@]}" -history "$work/whole.csv" | grep '^RESULT ')
  [ -n "$whole" ] || { echo "FAILED: no RESULT line from the whole run ($scheme)"; exit 1; }
  set +e
  FreeFem++-nw -v 0 "$script" "${options[@]}" -history "$work/stopped.csv" -state "$work/state" -stopafter 120 \
    > "$work/stopped.log" 2>&1
  stopped=$?
  set -e
  check "$scheme: stopped run killed (SIGKILL)" "$stopped" 137
  check "$scheme: history lines when stopped" "$(wc -l < "$work/stopped.csv")" 122
  echo "121,0,0,0,0,0,0,0" >> "$work/stopped.csv"   # as if killed after the history line, before the state
  resumed=$(FreeFem++-nw -v 0 "$script" "${options[@]}" -history "$work/stopped.csv" -state "$work/state" -resume 1 \
            | grep '^RESULT ')
  check "$scheme: RESULT line of the resumed run" "$resumed" "$whole"
  if cmp -s "$work/whole.csv" "$work/stopped.csv"; then same=yes; else same=no; fi
  check "$scheme: history of the resumed run" "$same" yes
  rm -f "$work"/*.csv "$work/state"
done
[ "$failures" -eq 0 ] && echo "all checks passed" || { echo "$failures check(s) failed"; exit 1; }
