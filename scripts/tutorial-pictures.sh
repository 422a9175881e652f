#!/usr/bin/env bash
# Runs every lesson of the course kit (edp/tutorial/) as the tests do and copies the PNG
# files they produce into docs/tutorial/, so that the pages show what the lessons draw.
# Needs the build (scripts/setup.sh).
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
cd "${FFETI_BUILD:-$root/build}/edp-tests"
for lesson in "$root"/edp/tutorial/[0-9]*.edp; do
  name=$(basename "$lesson" .edp)
  "$root/tests/tutorial/run-lesson.sh" "$root" "$name" "$root/docs/tutorial" | tail -n 1
done
ls "$root"/docs/tutorial/*.png
