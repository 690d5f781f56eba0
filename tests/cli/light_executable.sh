#!/usr/bin/env bash
# rollcheck, the fast executable (src/cli/light_session.cpp), loads no FEM
# library: neither gmsh nor DOLFINx nor PETSc is among the shared libraries
# its ELF header names (readelf -d), while rollcheck-fem beside it names all
# three. (A unity batch that put the geometry layer's one gmsh caller,
# tetrahedralize.cpp, beside functions rollcheck calls once made it load
# gmsh and its dependencies: 133 libraries and about 0.2 s at each start.)
#   light_executable.sh ROLLCHECK SOURCE_DIR TMP_DIR
set -u
source "$(dirname "$0")/lib.sh"
bin=$1; tmp=$3
rm -rf "$tmp"; mkdir -p "$tmp"
fem=$(dirname "$bin")/rollcheck-fem
needed() { readelf -d "$1" | sed -n 's/.*(NEEDED).*\[\(.*\)\]/\1/p'; }
light=$(needed "$bin"); heavy=$(needed "$fem")
for lib in libgmsh libdolfinx libpetsc; do
  check '! grep -q "^$lib" <<<"$light"' "rollcheck names $lib: $(tr '\n' ' ' <<<"$light")"
  check 'grep -q "^$lib" <<<"$heavy"' "rollcheck-fem does not name $lib (is the test reading the header?)"
done
# A FEM score runs in rollcheck-fem in either spelling of its option
# (`--score=fem-sds` once stayed in rollcheck and failed with exit 1): the
# command line, refused for its grid, was handed over if PETSc was loaded.
for score in "--score fem-sds" "--score=fem-sds" "--score=fem-sds-template"; do
  LD_DEBUG=libs "$bin" search $score --grid bogus > "$tmp/ld.log" 2>&1
  check 'grep -q "libpetsc" "$tmp/ld.log"' "search $score stayed in rollcheck"
done
LD_DEBUG=libs "$bin" search --score=sds --grid bogus > "$tmp/ld.log" 2>&1
check '! grep -q "libpetsc" "$tmp/ld.log"' "search --score=sds went to rollcheck-fem"
exit $fail
