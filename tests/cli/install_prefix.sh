#!/usr/bin/env bash
# `cmake --install` into a temporary prefix: the installed executable runs
# `validate` from another working folder, on the installed default cases,
# scripts and reference meshes (not the source tree's), and its checks pass.
#   install_prefix.sh ROLLCHECK SOURCE_DIR TMP_DIR
set -u
source "$(dirname "$0")/lib.sh"
bin=$1; tmp=$3
build=$(cd "$(dirname "$bin")/../.." && pwd)
rm -rf "$tmp"; mkdir -p "$tmp/work"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OPENBLAS_NUM_THREADS=1
cmake --install "$build" --prefix "$tmp/prefix" > "$tmp/install.log" 2>&1 || { cat "$tmp/install.log"; exit 1; }
check '[[ -x $tmp/prefix/bin/rollcheck && -x $tmp/prefix/bin/rollcheck-fem && -d $tmp/prefix/share/rollcheck/cases/default ]]' "installed layout"
check '[[ -f $tmp/prefix/share/rollcheck/meshes/reference/oloid_reference.obj ]]' "reference meshes installed"
cd "$tmp/work"
"$tmp/prefix/bin/rollcheck" validate --json validate.json > validate.log 2>&1
rc=$?
check '[[ $rc -eq 0 ]]' "installed validate exit $rc"
check 'grep -q "checks passed, 0 failed" validate.log' "installed validate checks"
check '[[ -f results/report/report.html ]]' "report written under the working folder"
check 'grep -rqF "$tmp/prefix/share/rollcheck/cases/default/" results/cases' "cases not taken from the prefix"
[[ $fail -ne 0 ]] && tail -20 validate.log
exit $fail
