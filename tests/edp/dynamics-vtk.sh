#!/usr/bin/env bash
# bar-impact.edp -vtk: one VTU file per subdomain at step 0 and every -every steps, each with
# the displacement and velocity point data, and a PVD time series listing exactly those files
# (ParaView opens it). The velocity read back from step 0's files is the initial -v0.
# Usage: dynamics-vtk.sh SOURCE_DIR   (run where freefem++.pref points at the build)
set -euo pipefail
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
FreeFem++-nw -v 0 "$1/edp/bar-impact.edp" -n 20 -vtk "$work/bar" -every 20 | grep -q '^RESULT .*status=converged'
python3 - "$work" <<'PY'
import base64, re, struct, sys, xml.dom.minidom
work = sys.argv[1]
sets = xml.dom.minidom.parse(f"{work}/bar.pvd").getElementsByTagName("DataSet")
files = sorted(d.getAttribute("file") for d in sets)
expected = sorted(f"bar-s{s}-k{k}.vtu" for s in range(10) for k in (0, 20, 40, 60))
assert files == expected, f"PVD lists {files}"
for name in expected:
    text = open(f"{work}/{name}").read()
    for field in ("displacement", "velocity"):
        assert f'Name="{field}" NumberOfComponents="3"' in text, f"{name}: no {field}"
velocity = re.search(r'Name="velocity" NumberOfComponents="3" format="binary"\s*>\s*(\S+)', open(f"{work}/bar-s3-k0.vtu").read())
raw = base64.b64decode(velocity.group(1))
values = struct.unpack(f"<{struct.unpack('<I', raw[:4])[0] // 8}d", raw[4:4 + struct.unpack('<I', raw[:4])[0]])
assert all(abs(values[i] + 1) < 1e-12 for i in range(0, len(values), 3)), values[:6]
print("all checks passed")
PY
