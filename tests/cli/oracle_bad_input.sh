#!/usr/bin/env bash
# Bad input to `rollcheck oracle` and `rollcheck search`: exit 2 with a message
# naming the input, nothing written; ranges are the schema's bounds, and the
# resource guards stop a multi-GB trajectory before it is run; a body that
# never touches gives the documented "inf" scores, never NaN.
set -u
source "$(dirname "$0")/lib.sh"
bin=$1; source=$2; tmp=$3
rm -rf "$tmp"; mkdir -p "$tmp"
oloid=$source/meshes/reference/oloid_reference.obj
expect 2 "option --steps.*integer in \[1, 1e\+06\], got 0" -- "$bin" oracle --mesh "$oloid" --oracle approx --steps 0 --json "$tmp/a.json"
expect 2 "option --steps.*integer in \[1, 1e\+06\], got 0" -- "$bin" oracle --mesh "$oloid" --oracle rigid --steps 0 --json "$tmp/a.json"
expect 2 "option --steps.*got 2000000" -- "$bin" oracle --mesh "$oloid" --oracle approx --steps 2000000 --json "$tmp/a.json"
# Steps of the rigid-body oracle: 20000 s at dt 2 ms is 10^7 steps, beyond the work budget.
expect 2 "duration_s. / .dt_s. asks for 1e\+07 rigid-body time steps, more than the 1e\+06" -- "$bin" oracle --mesh "$oloid" --duration 20000 --sample-every 5 --runs 1 --json "$tmp/a.json"
expect 2 "option --sample-every.*got 0" -- "$bin" oracle --mesh "$oloid" --sample-every 0 --json "$tmp/a.json"
expect 2 "option --convergence-every.*got -1" -- "$bin" oracle --mesh "$oloid" --convergence-every -1 --json "$tmp/a.json"
expect 2 "option --basquin-exponent.*< 0" -- "$bin" oracle --mesh "$oloid" --basquin-exponent 0.1 --json "$tmp/a.json"
expect 2 "no step" -- "$bin" oracle --mesh "$oloid" --duration 0.001 --json "$tmp/b.json"
expect 2 "threshold.*-0.1" -- "$bin" oracle --mesh "$oloid" --threshold -0.1 --json "$tmp/c.json"
expect 2 "unknown metric 'xds'" -- "$bin" oracle --mesh "$oloid" --metrics cds,xds --json "$tmp/d.json"
expect 2 "need angular velocities" -- "$bin" oracle --mesh "$oloid" --oracle approx --metrics tds --json "$tmp/e.json"
expect 2 "unknown quirk 'nope'" -- "$bin" oracle --mesh "$oloid" --quirks nope=paper --json "$tmp/f.json"
expect 2 "paper' or 'corrected" -- "$bin" oracle --mesh "$oloid" --quirks doubled_mean_curvature=maybe --json "$tmp/f.json"
expect 2 "option --runs.*\[1, 5\], got 9" -- "$bin" oracle --mesh "$oloid" --runs 9 --json "$tmp/g.json"
expect 2 "Poisson" -- "$bin" oracle --mesh "$oloid" --poisson 0.7 --json "$tmp/h.json"
expect 2 "missing.obj.: does not exist" -- "$bin" oracle --mesh "$tmp/missing.obj" --json "$tmp/i.json"
expect 2 "oracle" -- "$bin" oracle --mesh "$oloid" --oracle magic --json "$tmp/j.json"
expect 2 "grid" -- "$bin" search --grid huge --json "$tmp/k.json"
expect 2 "validate-top.*-1" -- "$bin" search --validate-top -1 --json "$tmp/l.json"
expect 2 "option --points.*\[3, 100000\], got 2" -- "$bin" search --points 2 --json "$tmp/m.json"
expect 2 "option --steps.*got -1" -- "$bin" search --steps -1 --json "$tmp/n.json"
expect 2 "option --threads.*0 or in \[1, 256\], got 5000" -- "$bin" search --threads 5000 --json "$tmp/o.json"
if ls -A "$tmp" | grep -q .; then echo "FAIL: output written on error:"; ls -A "$tmp"; fail=1; fi

# A body that never touches (threshold 0: no centroid is below the ground):
# every score is the documented "inf", exit 0, and no NaN anywhere.
"$bin" -q oracle --mesh "$oloid" --paper-compat --threshold 0 --json "$tmp/never.json" || { echo "FAIL: threshold 0"; fail=1; }
for key in cds sds tds wds_vol wds_depth fds; do
  [[ $(jq -r ".$key" "$tmp/never.json") == inf ]] || { echo "FAIL: $key not inf when nothing touches"; fail=1; }
done
[[ $(jq -r '.contact.faces_with_contact' "$tmp/never.json") == 0 ]] || { echo "FAIL: faces with contact"; fail=1; }
if grep -qi nan "$tmp/never.json"; then echo "FAIL: NaN in JSON"; fail=1; fi
exit $fail
