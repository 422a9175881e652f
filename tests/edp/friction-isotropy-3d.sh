#!/usr/bin/env bash
# Isotropic friction in 3D: edp/cattaneo-mindlin-3d.edp turned about the normal by 30 degrees
# with its load (-angle 30) is the same problem in a turned frame, while the contact rows'
# tangent pair stays (e_x, e_y) (the block's top has normal e_z): Q then lies at 30 degrees to
# t1 and each friction force has both components. With friction discs (not a square of the
# two components' bounds) the answer must be the first one turned: the same stick and slip
# rows, c/a, a, P and ||sum of the friction forces|| as the scene unturned, to the solver's
# tolerance (tol = 1e-6; the rows' states may flip only for a row at its bound, and then c/a
# moves by that row's share, far more than 1e-3).
# Usage: friction-isotropy-3d.sh SOURCE_DIR   (run where freefem++.pref points at the build)
set -euo pipefail
source_dir=$1
script="$source_dir/edp/cattaneo-mindlin-3d.edp"
args=(-h 0.5 -q 0.6 -meshes "$source_dir/meshes")
source "$source_dir/tests/mpi/result-keys.sh"

straight=$(FreeFem++-nw -v 0 "$script" "${args[@]}" | result)
turned=$(FreeFem++-nw -v 0 "$script" "${args[@]}" -angle 30 | result)
[ -n "$straight" ] && [ -n "$turned" ] || { echo "no RESULT line"; exit 1; }
for line in "$straight" "$turned"; do
  [ "$(value "$line" status)" = converged ] || { echo "FAILED: status $(value "$line" status)"; exit 1; }
done
same_keys "turned by 30 degrees" "$straight" "$turned" couples sticking slipping
close_keys "turned by 30 degrees" "$straight" "$turned" 1e-3 stick_ratio a c
close_keys "turned by 30 degrees" "$straight" "$turned" 1e-5 P Q tangential_force
# The friction forces' sum lies along the turned Q (balance_error compares it as a vector).
awk -v e="$(value "$turned" balance_error)" 'BEGIN { exit !(e < 1e-5) }' \
  && echo "ok: turned: sum of the friction forces along Q (error $(value "$turned" balance_error))" \
  || { echo "FAILED: turned: balance error $(value "$turned" balance_error)"; failures=$((failures + 1)); }
[ "$failures" -eq 0 ] && echo "all checks passed" || { echo "$failures check(s) failed"; exit 1; }
