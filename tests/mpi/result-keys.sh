# Shared by the rank comparisons: read a RESULT line's keys and compare two lines key by key.
# Source it; `failures` counts what did not match.
failures=0
result() { grep '^RESULT ' | head -n 1; }
value() { printf '%s\n' "$1" | tr ' ' '\n' | sed -n "s/^$2=//p"; }
# same_keys LABEL SERIAL PARALLEL KEY...: equal as printed.
same_keys() {
  local label=$1 serial=$2 parallel=$3 key
  shift 3
  for key in "$@"; do
    if [ "$(value "$serial" "$key")" = "$(value "$parallel" "$key")" ]; then
      echo "ok: $label: $key = $(value "$parallel" "$key")"
    else
      echo "FAILED: $label: $key = $(value "$parallel" "$key"), serial $(value "$serial" "$key")"
      failures=$((failures + 1))
    fi
  done
}
# close_keys LABEL SERIAL PARALLEL TOLERANCE KEY...: equal to TOLERANCE relative.
close_keys() {
  local label=$1 serial=$2 parallel=$3 tolerance=$4 key
  shift 4
  for key in "$@"; do
    if awk -v a="$(value "$serial" "$key")" -v b="$(value "$parallel" "$key")" -v t="$tolerance" \
         'BEGIN { d = a - b; if (d < 0) d = -d; s = a < 0 ? -a : a; exit !(d <= t * s) }'; then
      echo "ok: $label: $key = $(value "$parallel" "$key") (serial $(value "$serial" "$key"))"
    else
      echo "FAILED: $label: $key = $(value "$parallel" "$key"), serial $(value "$serial" "$key")"
      failures=$((failures + 1))
    fi
  done
}
