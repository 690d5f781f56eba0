#!/usr/bin/env bash
# rollcheck fem-sds --slab-check on 2 ranks (label long: a 3D study of about
# a minute): the slices' reduction against a fuller model, a 3D slab of the
# 10 mm cylinder pressed on the plane, at two refinements: its middle within
# 2 % of the slices, the force and approach the slices', and its square ends
# below the middle.
set -u
source "$(dirname "$0")/lib.sh"
bin=$1; tmp=$3
rm -rf "$tmp"; mkdir -p "$tmp"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OPENBLAS_NUM_THREADS=1
mpirun -n 2 --oversubscribe "$bin" -q fem-sds --body cylinder --radius 0.01 --height 0.02 --sections 60 \
  --orientations 1 --fem-slices 3 --slab-check 1 --json "$tmp/slab.json" > "$tmp/slab.log" 2>&1 \
  || { echo "FAIL: slab run"; cat "$tmp/slab.log"; exit 1; }
/usr/bin/python3 - "$tmp" <<'PY' || fail=1
import json, sys
d = sys.argv[1]
slab = json.load(open(f"{d}/slab.json"))
assert slab["slab_checked_orientations"] == 1 and slab["slab_worst_peak_difference"] < 0.02, slab
levels = slab["per_orientation"][0]["slab"]
assert [l["refine"] for l in levels] == [0, 1] and levels[1]["dofs"] > levels[0]["dofs"]
for l in levels:
    middle = l["slice_peak_pa"][1]
    assert abs(l["force_n"] / 100 - 1) < 1e-3 and abs(l["approach_factor"] - 1) < 0.02, l
    assert abs(l["peak_difference_vs_slices"]) < 0.02 and max(l["end_peak_pa"]) < 0.8 * middle, l
    print(f"slab level {l['refine']}: {l['dofs']} DOFs, peak {100 * l['peak_difference_vs_slices']:+.2f} %, "
          f"largest slice difference {100 * l['max_slice_difference']:.2f} %, "
          f"ends {l['end_peak_pa'][0]:.4g}, {l['end_peak_pa'][1]:.4g} Pa < middle {middle:.4g} Pa")
PY
exit $fail
