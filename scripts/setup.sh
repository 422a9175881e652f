#!/usr/bin/env bash
# Sets ffeti up on Debian 12: installs the Debian packages that are missing, configures,
# builds and installs the plugin, its .idp library and ffeti-solve (the file-driven front end
# for gmsh/GetDP), and tells FreeFEM where the plugin is.
# Idempotent: a second run only rebuilds what changed.
#   FFETI_PREFIX   install prefix (default /usr/local)
#   FFETI_BUILD    build folder (default <checkout>/build)
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
prefix=${FFETI_PREFIX:-/usr/local}
build=${FFETI_BUILD:-$root/build}

packages=(build-essential cmake freefem++ libfreefem++-dev gmsh libeigen3-dev
          libsuitesparse-dev liblapack-dev libopenmpi-dev openmpi-bin libgtest-dev getdp libgmsh-dev nlohmann-json3-dev
          ghostscript gnuplot-nox xvfb)
missing=()
for package in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed" || missing+=("$package")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "ffeti setup: installing ${missing[*]}"
  as_root=()
  [ "$(id -u)" -eq 0 ] || as_root=(sudo)
  "${as_root[@]}" apt-get update -qq
  DEBIAN_FRONTEND=noninteractive "${as_root[@]}" apt-get install -y -qq "${missing[@]}" >/dev/null
fi

cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release -DCMAKE_INSTALL_PREFIX="$prefix" >/dev/null
cmake --build "$build" -j "$(nproc)"

# Install and register with FreeFEM, so that `load "ffeti"` and `include "ffeti.idp"` work
# from any folder. Debian's /etc/freefem++.pref points to folders that do not exist; the
# block below adds the real ones (Debian's plugins and .idp files) and ours.
if [ -w "$prefix" ] || [ "$(id -u)" -eq 0 ]; then
  cmake --install "$build" >/dev/null
  pref=/etc/freefem++.pref
  [ -w "$pref" ] || pref="$HOME/.freefem++.pref"
  touch "$pref"
  sed -i '/^# >>> ffeti >>>$/,/^# <<< ffeti <<<$/d' "$pref"
  cat >> "$pref" <<PREF
# >>> ffeti >>>
loadpath += "/usr/lib/freefem++"
loadpath += "$prefix/lib/ffeti"
includepath += "/usr/include/freefem++/idp"
includepath += "$prefix/share/ffeti/idp"
# <<< ffeti <<<
PREF
  echo "ffeti setup: installed under $prefix, registered in $pref"
else
  echo "ffeti setup: $prefix is not writable; use the build tree with"
  echo "  export FF_LOADPATH=\"$build;/usr/lib/freefem++\" FF_INCLUDEPATH=\"$root/edp;/usr/include/freefem++/idp\""
fi
