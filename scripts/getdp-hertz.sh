#!/usr/bin/env bash
# The GetDP example of docs/getdp.md end to end, in a scratch folder: gmsh meshes
# meshes/hertz-pair.geo, GetDP assembles and post-processes (getdp/hertz.pro), ffeti-solve
# solves (getdp/hertz.json). Prints ffeti-solve's RESULT line and renders the von Mises view
# in gmsh (off screen, xvfb) into docs/getdp-vonmises.png and docs/getdp-vonmises-contact.png.
# Needs the build (scripts/setup.sh); installs xvfb if missing.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
solver=${FFETI_SOLVE:-${FFETI_BUILD:-$root/build}/ffeti-solve}
as_root=()
[ "$(id -u)" -eq 0 ] || as_root=(sudo)
command -v xvfb-run >/dev/null || "${as_root[@]}" apt-get install -y -qq xvfb >/dev/null
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
cp "$root/getdp/hertz.pro" "$root/getdp/hertz.json" .
gmsh -2 -format msh22 -v 0 "$root/meshes/hertz-pair.geo" -o hertz.msh
getdp hertz.pro -msh hertz.msh -setstring solver "$solver" -solve Hertz -v 1 | grep '^RESULT'
render() {  # OUT SCALE TX TY
  xvfb-run -a gmsh -setstring out "$1" -setnumber scale "$2" -setnumber tx "$3" -setnumber ty "$4" \
    "$root/getdp/render-views.geo" >/dev/null 2>&1
  cp "$1" "$root/docs/"
  echo "wrote docs/$1"
}
render getdp-vonmises.png 1 0 0
render getdp-vonmises-contact.png 8 50 -25  # the contact point at the centre, 8 times closer
