# Sourced by the GetDP tests (arguments SOURCE_DIR FFETI_SOLVE): the skip without GetDP
# (exit 77, which ctest reports as skipped), the tests' freefem++.pref from the folder ctest
# runs them in, MPI allowed as root (CI runs as root), and a scratch folder removed on exit.
source_dir=$1
ffeti_solve=$2
command -v getdp >/dev/null || { echo "SKIPPED: getdp is not installed (apt-get install getdp)"; exit 77; }
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
pref=$PWD/freefem++.pref
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
