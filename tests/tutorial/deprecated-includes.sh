#!/usr/bin/env bash
# A script written before the scene fragments moved to scenes/ still runs from any folder
# after the README's set-up: include "model-problem.idp" prints a deprecation line naming
# the new include and defines what it did.
# Usage: deprecated-includes.sh   (after scripts/setup.sh has installed ffeti)
set -euo pipefail
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
cat > old.edp <<'EDP'
include "ffeti.idp"
include "model-problem.idp"
seedModelData(8, 4)
cout << "subdomains " << S << endl;
EDP
FreeFem++-nw -v 0 old.edp > output.txt 2>&1 || { cat output.txt; exit 1; }
grep -q 'include "model-problem.idp" is deprecated; include "scenes/model-problem.idp"' output.txt \
  || { echo "FAILED: no deprecation line"; cat output.txt; exit 1; }
grep -q '^subdomains 8$' output.txt || { echo "FAILED: the old include did not define the scene"; cat output.txt; exit 1; }
echo "ok: include \"model-problem.idp\" runs, with a deprecation line"
