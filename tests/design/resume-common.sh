# Sourced by the resume tests: one design loop run whole, then stopped (killed) after 4
# analyses and resumed from its history; `check` compares, `finish` reports.
# The sourcing test sets script and options, and may define before_resume (it runs after
# the stopped run, before the resume: to read what the stopped run left behind).
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
value() { grep '^RESULT ' | tr ' ' '\n' | sed -n "s/^$1=//p"; }
failures=0
check() { if [ "$2" = "$3" ]; then echo "ok: $1: $2"; else echo "FAILED: $1: $2 (expected $3)"; failures=$((failures + 1)); fi; }
finish() { [ "$failures" -eq 0 ] && echo "all checks passed" || { echo "$failures check(s) failed"; exit 1; }; }

whole=$(FreeFem++-nw -v 0 "$script" "${options[@]}" -history "$work/whole.history")
set +e
FreeFem++-nw -v 0 "$script" "${options[@]}" -history "$work/stopped.history" -stopafter 4 > "$work/stopped.log" 2>&1
stopped_status=$?
set -e
stopped_rows=$(head -n 1 "$work/stopped.history" | cut -d' ' -f1)
if declare -F before_resume >/dev/null; then before_resume; fi
resumed=$(FreeFem++-nw -v 0 "$script" "${options[@]}" -history "$work/stopped.history" -resume 1)
check "stopped run killed (SIGKILL)" "$stopped_status" 137
check "history rows when stopped" "$stopped_rows" 4
