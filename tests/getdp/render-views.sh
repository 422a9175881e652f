#!/usr/bin/env bash
# getdp/render-views.geo run from another folder, as docs/getdp.md's reader would: relative
# paths are the caller's (a missing file is an error that names it, with a non-zero exit
# status), and the picture is drawn there, not beside the .geo file. The drawing itself needs
# an X server: with xvfb-run installed the Hertz example's von Mises view is rendered and
# must not be blank.
# Usage: render-views.sh SOURCE_DIR FFETI_SOLVE. Exit 77 (skipped) without GetDP.
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
geo=$source_dir/getdp/render-views.geo
failures=0

if gmsh -0 -setstring mesh missing.msh "$geo" > missing.out 2>&1; then  # -0: parse only, no display
  echo "FAILED: a missing mesh file was not an error"; failures=$((failures + 1))
elif grep -q "the mesh file $work/missing.msh does not exist" missing.out; then
  echo "ok: a missing mesh file is an error naming $work/missing.msh"
else
  echo "FAILED: the message does not name $work/missing.msh:"; cat missing.out; failures=$((failures + 1))
fi

if command -v xvfb-run >/dev/null; then
  cp "$source_dir/getdp/hertz.pro" "$source_dir/getdp/hertz.json" .
  gmsh -2 -format msh22 -v 0 "$source_dir/meshes/hertz-pair.geo" -o hertz.msh
  getdp hertz.pro -msh hertz.msh -setstring solver "$ffeti_solve" -solve Hertz -v 1 | grep -q '^RESULT.*status_name=converged'
  before=$(ls "$source_dir/getdp")
  xvfb-run -a gmsh -setstring out picture.png "$geo" > render.out 2>&1 || { cat render.out; exit 1; }
  [ "$(ls "$source_dir/getdp")" = "$before" ] || { echo "FAILED: wrote into $source_dir/getdp"; failures=$((failures + 1)); }
  colours=$(python3 - <<'PY'
import zlib, struct
data = open("picture.png", "rb").read()
chunks, pos = {}, 8
while pos < len(data):
    length, kind = struct.unpack(">I4s", data[pos:pos + 8])
    chunks.setdefault(kind, b"")
    chunks[kind] += data[pos + 8:pos + 8 + length]
    pos += 12 + length
print(len(set(zlib.decompress(chunks[b"IDAT"]))))
PY
)
  # A blank picture is white with a colour bar: a handful of byte values; a stress field many.
  if [ "$colours" -gt 100 ]; then echo "ok: the von Mises view drawn in $work ($colours distinct bytes)"
  else echo "FAILED: picture.png looks blank ($colours distinct bytes)"; failures=$((failures + 1)); fi
else
  echo "note: xvfb-run is not installed; the drawing was not tried (apt-get install xvfb)"
fi
exit $failures
