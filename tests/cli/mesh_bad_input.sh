#!/usr/bin/env bash
# Bad input to `rollcheck mesh` and `rollcheck run`: exit 2, a message naming
# the input, and nothing written.
set -u
source "$(dirname "$0")/lib.sh"
bin=$1; tmp=$3
rm -rf "$tmp"; mkdir -p "$tmp/in"; in=$tmp/in
expect 2 "radius.*nan" -- "$bin" mesh --body oloid --radius nan --out "$tmp/a.obj"
expect 2 "radius.*-1" -- "$bin" mesh --body oloid --radius -1 --out "$tmp/b.obj"
expect 2 "option --ratio.*> 0, got 0" -- "$bin" mesh --body roller --ratio 0 --out "$tmp/c.obj"
expect 2 "option --theta.*\(0, 180\) deg, got 0" -- "$bin" mesh --body roller --theta 0 --out "$tmp/c.obj"
expect 2 "option --points.*\[3, 100000\], got 200000" -- "$bin" mesh --body oloid --points 200000 --out "$tmp/c.obj"
expect 2 "option --size.*> 0 m, got 0" -- "$bin" mesh --body oloid --size 0 --out "$tmp/c.msh"
# Two coincident circles (theta nearly 0, no offset): the hull is flat.
expect 2 "flat or degenerate" -- "$bin" mesh --body roller --family centre-line --theta 1e-9 --offset 0 --out "$tmp/d.obj"
expect 2 "missing.obj.: does not exist" -- "$bin" mesh --mesh "$in/missing.obj" --out "$tmp/e.obj"
printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n' > "$in/open.obj"
expect 2 "open.obj.*(watertight|fewer than 4)" -- "$bin" mesh --mesh "$in/open.obj" --out "$tmp/f.obj"
printf 'v 0 0 x\n' > "$in/malformed.obj"
expect 2 "malformed.obj.*not a number" -- "$bin" mesh --mesh "$in/malformed.obj" --out "$tmp/g.obj"
printf '[scene]\nkind = "mesh"\nbody = "oloid"\nwibble = 3\n' > "$in/unknown_key.toml"
expect 2 "unknown_key.toml.*unknown key 'wibble'" -- "$bin" run "$in/unknown_key.toml"
printf '[scene\nkind = "mesh"\n' > "$in/malformed.toml"
expect 2 "malformed.toml.*malformed TOML" -- "$bin" run "$in/malformed.toml"
expect 2 "does not exist" -- "$bin" run "$in/none.toml"
printf '[scene]\nkind = "mesh"\n' > "$in/good.toml"
expect 2 "points.*integer" -- "$bin" run "$in/good.toml" --set points=many
expect 2 "unknown key .nope." -- "$bin" run "$in/good.toml" --set nope=1
# A closed but dented body: one vertex of an icosphere pulled to the centre.
"$bin" -q mesh --body sphere --subdivisions 1 --out "$in/sphere.off" || { echo "FAIL: sphere"; fail=1; }
awk 'NR==3 {print "0.1 0.1 0.1"; next} {print}' "$in/sphere.off" > "$in/dented.off"
expect 2 "dented.off.*not convex" -- "$bin" mesh --mesh "$in/dented.off" --out "$tmp/h.obj"
# Nothing was written for any failing call.
if ls -A "$tmp" | grep -v '^in$' | grep -q .; then echo "FAIL: output written on error:"; ls -A "$tmp"; fail=1; fi
if false | grep -qE '\.(obj|stl|ply|off|msh)$|\.tmp'; then echo "FAIL: output written on error:"; ls "$tmp"; fail=1; fi
# And the good path works through a case file with an override.
out=$("$bin" -q run "$(dirname "$0")/../../cases/mesh_oloid.toml" --set points=200 --set out="$tmp/ok.off" --json -) || { echo "FAIL: good case"; fail=1; }
grep -q '"convex": true' <<<"$out" || { echo "FAIL: good case not convex"; fail=1; }
[[ -s "$tmp/ok.off" ]] || { echo "FAIL: good case wrote nothing"; fail=1; }
exit $fail
