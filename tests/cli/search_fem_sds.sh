#!/usr/bin/env bash
# `mpirun -n 2 rollcheck search --grid quick --score fem-sds`: the family
# table over whole loops of real rolling. Its structure (a row per genome of
# the quick grid under `genomes`, the three references, the cylinder's ratios
# 1, rows that could not roll a loop saying why), its consistency (the grid's
# own (90, 1, 1) genome and the preprint's body are one body: the same
# scores), every scored row converged, the mirror genomes (theta, 180 - theta)
# scoring alike under FEM-SDS, the cylinder's FEM-SDS at its even-side value
# (tests/study/loop_scores/test_study_fem_sds.cpp derives it), the continuum value's closed form
# for the cylinder and its convergence, and the folder written whole.
set -u
source "$(dirname "$0")/lib.sh"
bin=$1; tmp=$3
rm -rf "$tmp"; mkdir -p "$tmp"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OPENBLAS_NUM_THREADS=1
mpirun -n 2 --oversubscribe "$bin" search --grid quick --score fem-sds --out "$tmp/family" --json "$tmp/family.json" \
  > "$tmp/log" 2>&1 || { echo "FAIL: family run"; cat "$tmp/log"; exit 1; }
for f in family.json table.md family.png; do
  [[ -s "$tmp/family/$f" ]] || { echo "FAIL: $tmp/family/$f missing"; fail=1; }
done
grep -q '| rank | body (theta, d, rho) |' "$tmp/log" || { echo "FAIL: no Markdown table on the log"; fail=1; }
/usr/bin/python3 - "$tmp/family.json" <<'PY' || fail=1
import json, math, sys
f = json.load(open(sys.argv[1]))
genomes, refs = f["genomes"], {r["kind"]: r for r in f["references"]}
assert len(genomes) == 45 and set(refs) == {"paper (90, 1, 1)", "oloid", "cylinder"}, (len(genomes), list(refs))
cylinder = refs["cylinder"]
assert cylinder["scored"] and cylinder["faces"] == refs["oloid"]["faces"], (cylinder["faces"], refs["oloid"]["faces"])
assert all(v == 1 for v in cylinder["over_cylinder"].values()), cylinder["over_cylinder"]
# Even contact of the side (r = 1 m, h = 2 m, n sections; tests/study/loop_scores/test_study_fem_sds.cpp): 2n side triangles of
# area (chord 2 sin(pi / n)) x h / 2 = 2 sin(pi / n), 2n cap triangles of area sin(2 pi / n) / 2.
n = cylinder["faces"] // 4
side, cap = math.sin(math.pi / n) * 2.0, 0.5 * math.sin(2 * math.pi / n)
total = 2 * n * (side + cap)
even = (2 * n * side * (1 / (2 * n) - side / total) ** 2 + 2 * n * cap * (cap / total) ** 2) / total
assert abs(cylinder["fem_sds"] / even - 1) < 1e-3, (cylinder["fem_sds"], even)
rows = genomes + list(refs.values())
for r in rows:
    if r["scored"]:
        assert r["fem_sds_status"] == "converged", r
        assert abs(r["fem_sds_table_change"]) < 0.01 and abs(r["fem_sds_sample_change"]) < 0.01, r
        assert r["singular_samples"] == 0 and r["fem_sds"] > 0 and r["uniformity"] > 0, r
    else:
        assert "rim lifts" in r["why_not"] or "cannot roll" in r["why_not"], r
        assert "fem_sds" not in r
unscored = [r for r in genomes if not r["scored"]]
assert 0 < len(unscored) < 45, len(unscored)
own = next(r for r in genomes if (r["theta_deg"], r["offset"], r["ratio"]) == (90, 1, 1))
paper = refs["paper (90, 1, 1)"]
for key in ("point_hertz_sds", "line_hertz_sds", "fem_sds", "uniformity"):
    assert abs(own[key] / paper[key] - 1) < 1e-9, (key, own[key], paper[key])
by_genome = {(r["theta_deg"], r["offset"], r["ratio"]): r for r in genomes if r["scored"]}
for (theta, d, rho), r in by_genome.items():
    mirror = by_genome.get((180 - theta, d, rho))
    if mirror:
        assert abs(r["fem_sds"] / mirror["fem_sds"] - 1) < 1e-3, (theta, d, rho)
        assert abs(r["fem_sds_continuum"] / mirror["fem_sds_continuum"] - 1) < 1e-3, (theta, d, rho)
# The continuum value (docs/methods/fem-sds.md): the cylinder's closed form r / L = 0.5, every
# scored row's within 1 % of its value at half the resolution.
assert abs(cylinder["fem_sds_continuum"] - 0.5) < 2e-4, cylinder["fem_sds_continuum"]
for r in rows:
    if r["scored"]:
        assert r["fem_sds_continuum"] > 0 and abs(r["fem_sds_continuum_change"]) < 0.01, r
        assert r["fem_sds_continuum_status"] == "converged" and abs(r["fem_sds_continuum_table_change"]) < 0.01, r
print(f"{len(rows)} bodies, {len(unscored)} genomes lift a rim; cylinder FEM-SDS {cylinder['fem_sds']:.6g} "
      f"(even side {even:.6g}); oloid FEM / cylinder {refs['oloid']['over_cylinder']['fem_sds']:.3g}")
PY
exit $fail
