#!/usr/bin/env bash
# Memory errors and undefined behaviour, in two independent ways:
# 1. AddressSanitizer + UndefinedBehaviorSanitizer: the core and the plugin built with both
#    (build-asan/), the unit tests run, then .edp scenes through FreeFEM with the sanitized
#    plugin. FreeFEM is not instrumented, so the ASan runtime is preloaded; for the FreeFEM
#    processes leak detection is off and alloc_dealloc_mismatch is off, both reporting
#    FreeFEM's own code (its environment parsing frees with delete what libstdc++ allocated
#    with malloc), not the plugin's.
# 2. valgrind memcheck: the released plugin (build/) on .edp scenes, every memory error and
#    every definite leak an error, FreeFEM's own leaks suppressed (tests/valgrind-freefem.supp
#    says which and why).
# Installs valgrind if missing. About 10 minutes on 2 cores (most of it the sanitized build).
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
"$root/scripts/setup.sh"
if ! command -v valgrind >/dev/null; then
  as_root=(); [ "$(id -u)" -eq 0 ] || as_root=(sudo)
  "${as_root[@]}" apt-get install -y -qq valgrind >/dev/null
fi
# Scenes: contact through FETI-1 and Total FETI, node-to-segment contact, obstacles,
# sensitivities and adjoints, bad input caught by try, friction (Coulomb, Tresca, load
# steps), three dimensions (elasticity, the cubes, node to face and mortar, the ball, their
# sensitivities), 3D friction on discs (mortar base, node to node), mortar sensitivities,
# new gaps on kept factorizations, the 3D elasticity cubes (shared symbolic analyses).
scenes=("$root/edp/example.edp"
        "$root/tests/edp/elastic-contact.edp"
        "$root/tests/edp/bad-input.edp"
        "$root/tests/edp/sensitivity-membrane.edp"
        "$root/tests/edp/sensitivity-elastic.edp -scene 0"
        "$root/tests/edp/sensitivity-elastic.edp -scene 1"
        "$root/edp/uniform-pressure.edp -m 8 -k 6 -gradcheck 1e-5 -cost pressure"
        "$root/edp/block-on-slope.edp -check 1"
        "$root/edp/block-on-slope.edp -law tresca -check 1"
        "$root/edp/cattaneo-mindlin.edp -h 0.4 -meshes $root/meshes -check 0.05"
        "$root/tests/edp/elasticity-3d.edp"
        "$root/edp/model-problem-3d.edp -n 8 -Hh 4 -tol 1e-8 -check 1e-8"
        "$root/tests/edp/patch-test-3d.edp"
        "$root/tests/edp/sensitivity-3d-faces.edp"
        "$root/edp/hertz-sphere.edp -h 0.2 -block 1 -meshes $root/meshes -check 0.1"
        "$root/edp/hertz-indenter.edp -h 0.2 -meshes $root/meshes -check 0.05"
        "$root/edp/block-on-slope-3d.edp -base 2 -theta 15 -phi 30 -mu 0.5 -check 1"
        "$root/edp/block-shear.edp -dim 3 -mode slip -check 1"
        "$root/tests/edp/sensitivity-3d-mortar.edp"
        "$root/tests/edp/gap-resolve.edp"
        "$root/edp/cubes-elasticity-3d.edp -n 8 -check 1")
label() { local script=${1%% *}; echo "$(basename "$script")${1#"$script"}"; }
failures=0
log=$(mktemp)
trap 'rm -f "$log"' EXIT

echo "== AddressSanitizer + UndefinedBehaviorSanitizer"
asan="$root/build-asan"
cmake -S "$root" -B "$asan" -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_CXX_FLAGS="-fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=all" >/dev/null
cmake --build "$asan" -j "$(nproc)" >/dev/null
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
if ASAN_OPTIONS=detect_leaks=1 "$asan/tests/ffeti_unit_tests" >"$log" 2>&1; then
  echo "ok: unit tests ($(grep -o '[0-9]* tests from [0-9]* test suites ran' "$log"))"
else
  echo "FAILED: unit tests"; grep -E "ERROR|runtime error|FAILED" -A8 "$log" | head -40; failures=$((failures + 1))
fi
for scene in "${scenes[@]}"; do
  # shellcheck disable=SC2086  # a scene is a script and its arguments
  if (cd "$asan/edp-tests" && LD_PRELOAD=$(gcc -print-file-name=libasan.so) \
        ASAN_OPTIONS=detect_leaks=0:alloc_dealloc_mismatch=0 FreeFem++-nw -v 0 $scene >"$log" 2>&1) &&
     ! grep -qE "AddressSanitizer|runtime error" "$log"; then
    echo "ok: sanitized $(label "$scene")"
  else
    echo "FAILED: sanitized $scene"; grep -E "ERROR|runtime error" -A12 "$log" | head -40; failures=$((failures + 1))
  fi
done

echo "== valgrind memcheck"
for scene in "${scenes[@]}"; do
  # shellcheck disable=SC2086
  if (cd "$root/build/edp-tests" && valgrind --error-exitcode=3 --leak-check=full --show-leak-kinds=definite \
        --errors-for-leak-kinds=definite --num-callers=30 --suppressions="$root/tests/valgrind-freefem.supp" \
        FreeFem++-nw -v 0 $scene >"$log" 2>&1); then
    echo "ok: memcheck $(label "$scene"): $(grep -o 'ERROR SUMMARY: .*' "$log")"
  else
    echo "FAILED: memcheck $scene"; grep -E "Invalid|uninitialised|definitely lost|ERROR SUMMARY" -A10 "$log" | head -40
    failures=$((failures + 1))
  fi
done
[ "$failures" -eq 0 ] && echo "memory check: clean" || { echo "memory check: $failures failure(s)"; exit 1; }
