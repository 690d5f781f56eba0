#!/usr/bin/env bash
# Builds the Debian package (CPack, in build/) and, with --check, installs it
# with dpkg, runs `rollcheck validate` from a scratch folder with the
# installed binary and removes the package again (root; this changes the
# machine's /usr while it runs, so it is not part of the test suite).
#   bash scripts/setup/deb.sh [--check]
set -euo pipefail
here=$(cd "$(dirname "$0")/../.." && pwd)
(cd "$here/build" && cpack -G DEB > cpack.log)
deb=$(ls "$here"/build/rollcheck_*_amd64.deb)
echo "built $deb"
[[ ${1:-} == --check ]] || exit 0
if dpkg -s rollcheck > /dev/null 2>&1; then
  echo "rollcheck is installed already; not replacing it" >&2; exit 2
fi
scratch=$(mktemp -d)
trap 'dpkg -r rollcheck > /dev/null 2>&1 || true; rm -rf "$scratch"' EXIT
dpkg -i "$deb" > "$scratch/dpkg.log"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OPENBLAS_NUM_THREADS=1
(cd "$scratch" && /usr/bin/rollcheck validate --json validate.json > validate.log 2>&1) \
  || { tail -20 "$scratch/validate.log"; exit 1; }
tail -1 "$scratch/validate.log" | head -1
grep -E "checks passed" "$scratch/validate.log"
