#!/usr/bin/env bash
# Field files (fem/write_fields.h, DOLFINx's XDMFFile with HDF5) written whole
# or not at all: on a full disk `hertz --xdmf` exits 1 naming the file, the
# previous NAME.xdmf and NAME.h5 are byte-identical and no temporary folder
# is left; a read-only folder is refused before any computation (exit 2).
# Both need a tmpfs mount (root); else skipped with a message.
set -u
source "$(dirname "$0")/lib.sh"
bin=$1; tmp=$3
rm -rf "$tmp"; mkdir -p "$tmp/full" "$tmp/readonly"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OPENBLAS_NUM_THREADS=1

# Sanity: the same run into a folder with room writes the pair.
expect 0 "" -- "$bin" -q hertz --model axi --refine 0 --xdmf "$tmp/ok.xdmf"
check '[[ -s $tmp/ok.xdmf && -s $tmp/ok.h5 ]]' "hertz --xdmf wrote no field pair"

full=$tmp/full
if mount -t tmpfs -o size=300k tmpfs "$full" 2>/dev/null; then
  echo previous > "$full/f.xdmf"; echo previous-h5 > "$full/f.h5"
  dd if=/dev/zero of="$full/filler" bs=4k 2>/dev/null
  expect 1 "f\.xdmf" -- "$bin" hertz --model axi --refine 0 --xdmf "$full/f.xdmf"
  check '[[ "$(cat "$full/f.xdmf")" == previous && "$(cat "$full/f.h5")" == previous-h5 ]]' \
    "full disk: a previous field file changed"
  check '[[ $(ls -A "$full" | wc -l) -eq 3 ]]' "full disk: temporary files left: $(ls -A "$full")"
  # Room for the temporary folder but not for the data: the failure comes later, in the writes.
  rm "$full/filler"; dd if=/dev/zero of="$full/filler" bs=4k count=60 2>/dev/null
  expect 1 "f\.xdmf" -- "$bin" hertz --model axi --refine 0 --xdmf "$full/f.xdmf"
  check '[[ "$(cat "$full/f.xdmf")" == previous && "$(cat "$full/f.h5")" == previous-h5 ]]' \
    "disk full during the writes: a previous field file changed"
  check '[[ $(ls -A "$full" | wc -l) -eq 3 ]]' "disk full during the writes: temporary files left: $(ls -A "$full")"
  umount "$full"
  mount -t tmpfs -o size=1M,ro tmpfs "$tmp/readonly"
  expect 2 "readonly" -- "$bin" hertz --model axi --refine 0 --xdmf "$tmp/readonly/f.xdmf"
  umount "$tmp/readonly"
else
  echo "SKIP: full-disk and read-only checks (cannot mount a tmpfs here; they need root)"
fi
exit $fail
