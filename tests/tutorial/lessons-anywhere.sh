#!/usr/bin/env bash
# Every lesson copied out of the repository into an empty folder runs there as a student
# would after the README's set-up (the installed plugin, .idp library and meshes), and
# prints its LESSON line.
# Usage: lessons-anywhere.sh SOURCE_DIR   (after scripts/setup.sh has installed ffeti)
set -euo pipefail
source_dir=$1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
for lesson in "$source_dir"/edp/tutorial/0[1-8]*.edp; do
  name=$(basename "$lesson")
  mkdir "$work/${name%.edp}"
  cp "$lesson" "$work/${name%.edp}/"
  if (cd "$work/${name%.edp}" && FreeFem++-nw -v 0 "$name" > output.txt 2>&1) && grep -q '^LESSON' "$work/${name%.edp}/output.txt"; then
    echo "ok: $name runs from $work/${name%.edp}"
  else
    echo "FAILED: $name from an empty folder:"; tail -n 5 "$work/${name%.edp}/output.txt"; failures=$((failures + 1))
  fi
done
[ "$failures" -eq 0 ] && echo "all checks passed" || { echo "$failures lesson(s) failed"; exit 1; }
