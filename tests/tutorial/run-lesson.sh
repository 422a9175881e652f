#!/usr/bin/env bash
# Runs one lesson as a student would with FreeFem++-nw, checks that every picture it drew
# (EPS of a field, gnuplot script of a graph) also came out as the PNG file its page shows,
# and checks the figures the page quotes.
# Usage: run-lesson.sh SOURCE_DIR LESSON [PICTURES_DIR] [RANKS]   (LESSON e.g. 01-obstacle; run
# where the tests' freefem++.pref is; PICTURES_DIR: where the PNG files go, default (or ""):
# a scratch folder; RANKS: run under mpirun -np RANKS FreeFem++-mpi instead)
set -euo pipefail
source_dir=$1
lesson=$2
pictures=${3:-}
ranks=${4:-}
source "$(dirname "${BASH_SOURCE[0]}")/scratch-folder.sh"
if [ -n "$ranks" ]; then
  export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
  run=(mpirun --oversubscribe -np "$ranks" FreeFem++-mpi -nw)
else
  run=(FreeFem++-nw)
fi
"${run[@]}" -v 0 "$source_dir/edp/tutorial/$lesson.edp" > output.txt 2>&1 || { cat output.txt; exit 1; }
grep '^LESSON' output.txt
for drawn in *.eps *.gp; do   # a field's EPS or a graph's gnuplot script
  [ -e "$drawn" ] || continue
  [ -s "${drawn%.*}.png" ] || { echo "FAILED: the lesson wrote $drawn but no PNG"; exit 1; }
  if [ -n "$pictures" ]; then cp "${drawn%.*}.png" "$pictures/"; fi
done
python3 "$source_dir/tests/tutorial/compare_lesson.py" "$source_dir/docs/tutorial/$lesson.md" output.txt
