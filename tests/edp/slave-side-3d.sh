#!/usr/bin/env bash
# Which body is the slave must not decide the answer (issue 53, item 4): edp/cattaneo-mindlin-3d.edp
# (a sphere sheared on a block, node to face, Coulomb discs) on a coarser mesh than its default,
# Q/(mu P) = 0.6.
# - The block's flat normal whichever body is the slave: the sphere as slave with
#   contactNormal="master", the block as slave with contactNormal="slave". c/a must agree
#   within BOUND_FLAT (relative) and each lie within 0.1 of Mindlin's.
# - contactNormal="average" with either body as slave: the rows' normals are the same lines
#   (the average of the two surfaces' normals does not depend on which is the slave), so c/a
#   must agree within BOUND_AVERAGE; only the slave nodes and the faces they meet differ.
# - The default (contactNormal="flatter") with either body as slave: the same rows as the
#   block's normal above, so the same c/a to BOUND_SAME (the master's default took the
#   sphere's normal with the block as slave: 16.6 % off Mindlin's).
# Measured (h = 0.2): c/a 0.7129 and 0.7029 (1.4 % apart; 3.2 % and 4.6 % off Mindlin's),
# average 0.7001 and 0.6827 (2.5 %); the sphere's normal with the block as slave is 16.6 % off
# Mindlin's, 14 % from the sphere as slave (docs/results/friction.md, "Which body is the
# slave"), so the bounds of 5 % tell the two apart. (h = 0.5 put the block as slave at 9.9 %,
# at the edge of the 0.1 bound: a row more or less in the stick zone moves c/a by a few %.)
# Usage: slave-side-3d.sh SOURCE_DIR   (run where freefem++.pref points at the build)
set -euo pipefail
source_dir=$1
script="$source_dir/edp/cattaneo-mindlin-3d.edp"
args=(-h 0.2 -q 0.6 -meshes "$source_dir/meshes")
BOUND_FLAT=0.05
BOUND_AVERAGE=0.05
BOUND_SAME=1e-9
source "$source_dir/tests/mpi/result-keys.sh"

solve() { FreeFem++-nw -v 0 "$script" "${args[@]}" "$@" | result; }
sphere_master=$(solve -slave sphere -normal master)
block_slave=$(solve -slave block -normal slave)
sphere_average=$(solve -slave sphere -normal average)
block_average=$(solve -slave block -normal average)
sphere_default=$(solve -slave sphere)
block_default=$(solve -slave block)
failures=0
for line in "$sphere_master" "$block_slave" "$sphere_average" "$block_average" "$sphere_default" "$block_default"; do
  [ -n "$line" ] || { echo "FAILED: no RESULT line"; exit 1; }
  [ "$(value "$line" status)" = converged ] || { echo "FAILED: status $(value "$line" status)"; exit 1; }
done
# agree NAME BOUND LINE1 LINE2: c/a of both within BOUND (relative).
agree() {
  local a b
  a=$(value "$3" stick_ratio) b=$(value "$4" stick_ratio)
  if awk -v a="$a" -v b="$b" -v r="$2" 'BEGIN { d = a - b; if (d < 0) d = -d; exit !(d <= r * a) }'; then
    echo "ok: $1: c/a $a and $b"
  else
    echo "FAILED: $1: c/a $a and $b differ by more than $2"; failures=$((failures + 1))
  fi
}
for line in "$sphere_master" "$block_slave"; do
  if awk -v e="$(value "$line" stick_ratio_error)" 'BEGIN { exit !(e <= 0.1) }'; then
    echo "ok: slave $(value "$line" slave), normal $(value "$line" normal): c/a error $(value "$line" stick_ratio_error) against Mindlin's"
  else
    echo "FAILED: slave $(value "$line" slave), normal $(value "$line" normal): c/a error $(value "$line" stick_ratio_error) against Mindlin's"
    failures=$((failures + 1))
  fi
done
agree "the block's normal, either body as slave" "$BOUND_FLAT" "$sphere_master" "$block_slave"
agree "the averaged normal, either body as slave" "$BOUND_AVERAGE" "$sphere_average" "$block_average"
agree "the default with the sphere as slave, against its master's normal" "$BOUND_SAME" "$sphere_master" "$sphere_default"
agree "the default with the block as slave, against its own normal" "$BOUND_SAME" "$block_slave" "$block_default"
[ "$failures" -eq 0 ] && echo "all checks passed" || { echo "$failures check(s) failed"; exit 1; }
