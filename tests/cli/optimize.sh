#!/usr/bin/env bash
# rollcheck optimize: a tiny search (approximate oracle, CDS, 60 points per
# circle) writes the JSON with its keys, the start's and the optimum's meshes,
# the sweeps' plot and the rendered view of both bodies (PNG files); with
# --matched-resolution the optimum's hull (optimum.obj) has about the start's
# face count; a bad box (min > max, a start outside it) exits 2 naming the key.
set -u
source "$(dirname "$0")/lib.sh"
bin=$1; tmp=$3
rm -rf "$tmp"; mkdir -p "$tmp"
export OPENBLAS_NUM_THREADS=1
"$bin" -q optimize --points 60 --max-evaluations 12 --sweep-points 3 --threads 1 --json "$tmp/optimize.json" \
  --out "$tmp/out" > "$tmp/run.log" 2>&1 || { echo "FAIL: tiny optimize run"; cat "$tmp/run.log"; exit 1; }
/usr/bin/python3 - "$tmp/optimize.json" "$tmp/out" <<'PY' || fail=1
import json, os, sys
r = json.load(open(sys.argv[1]))
for key in ["score", "oracle", "family", "mesh", "box", "start", "start_value", "noise", "optimum",
            "verdict_at_start", "derivatives_at_start", "derivatives_at_optimum", "sweeps", "search",
            "score_evaluations", "oracle_runs", "wall_s"]:
    assert key in r, key
assert r["start"] == [90, 1, 1] and r["score"] == "cds" and r["oracle"] == "approx"
assert r["mesh"]["points_per_circle"] == 60 and r["mesh"]["matched_resolution"] == "points"
assert r["mesh"]["optimum"]["points"] == 60 and r["mesh"]["target_faces"] is None
best = r["optimum"]
for key in ["x", "value", "displacement_from_start", "distance_from_start_box_units", "beats_start",
            "significance_threshold", "theta_deg", "offset", "ratio"]:
    assert key in best, key
assert best["value"] <= r["start_value"]
assert r["search"]["evaluations"] <= 12
assert [s["parameter"] for s in r["sweeps"]] == ["theta_deg", "offset", "ratio"]
assert r["verdict_at_start"] in ["not stationary", "local minimum", "local maximum", "saddle", "undetermined"]
assert json.load(open(os.path.join(sys.argv[2], "optimize.json"))) == r
for name in ["start.obj", "optimum.obj"]:
    assert os.path.getsize(os.path.join(sys.argv[2], name)) > 0, name
faces = sum(1 for line in open(os.path.join(sys.argv[2], "start.obj")) if line.startswith("f "))
assert faces == r["mesh"]["start"]["faces"], (faces, r["mesh"]["start"])
for name in ["sweeps.png", "optimum.png"]:
    with open(os.path.join(sys.argv[2], name), "rb") as f:
        assert f.read(8) == b"\x89PNG\r\n\x1a\n", name + " is not a PNG"
print("optimum", best["x"], best["value"], "from", r["start_value"])
PY
"$bin" -q optimize --points 60 --max-evaluations 12 --sweep-points 3 --threads 1 --matched-resolution \
  --json "$tmp/matched.json" --out "$tmp/matched" > "$tmp/matched.log" 2>&1 \
  || { echo "FAIL: optimize --matched-resolution"; cat "$tmp/matched.log"; exit 1; }
/usr/bin/python3 - "$tmp/matched.json" "$tmp/matched/optimum.obj" <<'PY' || fail=1
import json, sys
mesh = json.load(open(sys.argv[1]))["mesh"]
assert mesh["matched_resolution"] == "faces" and mesh["points_per_circle"] == 60, mesh
assert mesh["start"] == {"points": 60, "faces": mesh["target_faces"]}, mesh
faces = sum(1 for line in open(sys.argv[2]) if line.startswith("f "))
assert faces == mesh["optimum"]["faces"], (faces, mesh)
assert abs(faces - mesh["target_faces"]) <= 0.01 * mesh["target_faces"], (faces, mesh)
print("matched optimum", mesh["optimum"], "target", mesh["target_faces"])
PY
# --derivatives start: the gradient and Hessian at the start only, the optimum's skipped (with why), fewer scores.
"$bin" -q optimize --points 60 --max-evaluations 12 --sweep-points 3 --threads 1 --derivatives start \
  --json "$tmp/start.json" > "$tmp/start.log" 2>&1 || { echo "FAIL: optimize --derivatives start"; cat "$tmp/start.log"; exit 1; }
[[ $(jq -r --slurpfile both "$tmp/optimize.json" '(.verdict_at_start | type) == "string"
     and .derivatives_at_optimum.verdict == null and .derivatives_at_optimum.note == "not computed: --derivatives start"
     and .score_evaluations < $both[0].score_evaluations' "$tmp/start.json") == true ]] \
  || { echo "FAIL: --derivatives start: the start's verdict, none at the optimum, fewer scores than both"; fail=1; }
# FEM-SDS: every body's loop status is counted (a score with its convergence); the search and sweeps alone.
"$bin" -q optimize --score fem-sds --oracle rolling --family centre-line --points 60 --max-evaluations 3 \
  --replicates 2 --sweep-points 2 --derivatives none --json "$tmp/fem.json" > "$tmp/fem.log" 2>&1 \
  || { echo "FAIL: fem-sds optimize"; cat "$tmp/fem.log"; fail=1; }
check_json "FEM-SDS loops counted by status, one per body scored; no derivatives" \
  '.fem_sds_loops.scored > 0 and ([.fem_sds_loops.by_status[]] | add) == .fem_sds_loops.scored
   and (.fem_sds_loops.by_status.converged // 0) > 0
   and .derivatives_at_start.note == "not computed: --derivatives none"' "$tmp/fem.json"
for args in "--theta-min 150:theta_min_deg" "--offset-max 0.6:offset_start" "--ratio-start 2:ratio_start" \
            "--theta-min 0:theta_min_deg" "--replicates 1:replicates" "--score uniformity:uniformity" \
            "--derivatives some:--derivatives"; do
  "$bin" -q optimize ${args%%:*} > "$tmp/bad.log" 2>&1; rc=$?
  if [[ $rc -ne 2 ]] || ! grep -q -- "${args#*:}" "$tmp/bad.log"; then
    echo "FAIL: optimize ${args%%:*} gave exit $rc without '${args#*:}':"; cat "$tmp/bad.log"; fail=1
  fi
done
exit $fail
