#!/usr/bin/env bash
# The lessons' exercises as their pages write them: each command runs to its LESSON line.
# Exercise 2 of lesson 5 (a copy of multibody.idp with block 1 ten times softer in scenes/
# beside the lesson) once stopped with "triangles was reverse" when drawing the deformed blocks.
# Usage: exercises.sh SOURCE_DIR   (run where the tests' freefem++.pref is)
set -euo pipefail
source_dir=$1
lessons="$source_dir/edp/tutorial"
source "$(dirname "${BASH_SOURCE[0]}")/scratch-folder.sh"
failures=0
exercise() {  # exercise NAME LESSON ARGS...
  local name=$1 lesson=$2
  shift 2
  if FreeFem++-nw -v 0 "$lesson" "$@" > out.txt 2>&1 && grep -q '^LESSON' out.txt; then
    echo "ok: $name"
  else
    echo "FAILED: $name"; tail -n 4 out.txt; failures=$((failures + 1))
  fi
}
exercise "lesson 1: -pressure 2.5" "$lessons/01-obstacle.edp" -pressure 2.5
exercise "lesson 1: -m 64" "$lessons/01-obstacle.edp" -m 64
for args in "-N 4 -m 8" "-N 4 -m 16" "-N 8 -m 16"; do
  # shellcheck disable=SC2086
  exercise "lesson 2: $args" "$lessons/02-two-membranes.edp" $args
done
exercise "lesson 3: -n 256" "$lessons/03-accuracy.edp" -n 256
exercise "lesson 5: -parts 4" "$lessons/05-several-bodies.edp" -parts 4
mkdir scenes
sed 's/^real\[int\] E = \[210e3, 70e3, 110e3\];/real[int] E = [210e3, 7e3, 110e3];/' "$source_dir/edp/scenes/multibody.idp" > scenes/multibody.idp
grep -q '7e3, 110e3' scenes/multibody.idp || { echo "FAILED: lesson 5, exercise 2: multibody.idp's E line changed"; exit 1; }
cp "$lessons/05-several-bodies.edp" .
exercise "lesson 5: block 1 ten times softer (a copy of multibody.idp in scenes/ beside the lesson)" 05-several-bodies.edp
rm -r scenes 05-several-bodies.edp
exercise "lesson 6: -k 6" "$lessons/06-sensitivity.edp" -k 6
exercise "lesson 7: -start 0.1" "$lessons/07-shape-optimization.edp" -start 0.1
exercise "lesson 7: -amax 0.02" "$lessons/07-shape-optimization.edp" -amax 0.02
# Lesson 7's exercise 4 runs a scene: its -check makes the exit status the test.
for args in "-m 4 -check 0.02" "-m 4 -cost pressure -check 0.02"; do
  # shellcheck disable=SC2086
  if FreeFem++-nw -v 0 "$source_dir/edp/uniform-pressure-3d.edp" $args -history exercise-3d.history > out.txt 2>&1 \
     && grep -q '^RESULT .* status=0' out.txt; then
    echo "ok: lesson 7, exercise 4: uniform-pressure-3d.edp $args"
  else
    echo "FAILED: lesson 7, exercise 4: uniform-pressure-3d.edp $args"; tail -n 4 out.txt; failures=$((failures + 1))
  fi
done
exercise "lesson 9: -pull 0.9" "$lessons/09-friction.edp" -pull 0.9
exercise "lesson 9: -onestep 1" "$lessons/09-friction.edp" -onestep 1
exercise "lesson 9: -mu 0.2" "$lessons/09-friction.edp" -mu 0.2
exercise "lesson 10: -n 8" "$lessons/10-three-dimensions.edp" -n 8
exercise "lesson 10: -n 32" "$lessons/10-three-dimensions.edp" -n 32
exercise "lesson 10: -n 16 -Hh 4" "$lessons/10-three-dimensions.edp" -n 16 -Hh 4
exercise "lesson 12: -angle 0" "$lessons/12-friction-3d.edp" -angle 0
exercise "lesson 12: -angle 90" "$lessons/12-friction-3d.edp" -angle 90
exercise "lesson 12: -pull 0.7" "$lessons/12-friction-3d.edp" -pull 0.7
exercise "lesson 12: -pull 0.8" "$lessons/12-friction-3d.edp" -pull 0.8
exercise "lesson 12: -pull 0.9" "$lessons/12-friction-3d.edp" -pull 0.9
exercise "lesson 12: -pull 0.99" "$lessons/12-friction-3d.edp" -pull 0.99
grep -q 'status_pull=converged' out.txt || { echo "FAILED: lesson 12 -pull 0.99 did not converge"; failures=$((failures + 1)); }
exercise "lesson 12: -pull 1.1" "$lessons/12-friction-3d.edp" -pull 1.1
# The status by its name, as the lesson's page writes it (it once printed "failed").
grep -q 'status_pull=infeasible' out.txt || { echo "FAILED: lesson 12 -pull 1.1 names no infeasible status"; failures=$((failures + 1)); }
exercise "lesson 12: -m 8" "$lessons/12-friction-3d.edp" -m 8
exercise "lesson 11: -m2 6" "$lessons/11-solids-in-contact.edp" -m2 6
exercise "lesson 11: -swap 1" "$lessons/11-solids-in-contact.edp" -swap 1
exercise "lesson 11: -m 12 -m2 8" "$lessons/11-solids-in-contact.edp" -m 12 -m2 8
exercise "lesson 13: -n 80" "$lessons/13-impact.edp" -n 80
exercise "lesson 13: -courant 4" "$lessons/13-impact.edp" -courant 4
exercise "lesson 14: -start -1" "$lessons/14-lug.edp" -start -1
[ "$failures" -eq 0 ] && echo "all checks passed" || { echo "$failures exercise(s) failed"; exit 1; }
