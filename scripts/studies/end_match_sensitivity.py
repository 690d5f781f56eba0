#!/usr/bin/python3
"""How the whole-body check's end prediction under the coarse body's load
rule depends on where the end model meets the rule (d_m, `--end-match`),
from one run's JSON, without solving again:

    scripts/studies/end_match_sensitivity.py CHECK.json [D ...]

D in units of the locus's b at the end (default 2 3 4 6 8 16 32). For each
compared (not singular) end: the end model's reading over its centre-line
pressure interpolated at d (both levels, as the check does at d_m), times
the slice at the coarse body's q at d, taken as the run's slice at d_m
scaled by sqrt(q(d) / q(d_m)) (line Hertz at fixed R: an approximation
away from d_m; exact at d = d_m, where it reproduces the check), against
the whole body's reading. Needs `rollcheck whole-body --share-rule
coarse-body --json CHECK.json` (docs/methods/whole-body.md).
"""
import json
import math
import sys


def interpolate(points, x, column):
    for a, b in zip(points, points[1:]):
        if a[0] <= x <= b[0]:
            t = (x - a[0]) / (b[0] - a[0])
            return (1 - t) * a[column] + t * b[column]
    raise SystemExit(f"x = {x:.4g} m lies outside the line")


def main():
    if len(sys.argv) < 2:
        raise SystemExit(__doc__)
    check = json.load(open(sys.argv[1]))
    rule = check.get("coarse_body_share")
    if not rule:
        raise SystemExit(f"{sys.argv[1]}: not a run of --share-rule coarse-body")
    distances = [float(d) for d in sys.argv[2:]] or [2, 3, 4, 6, 8, 16, 32]
    planes = rule["planes_x_m_peak_pa_load_n_per_m"]
    length = check["ruling"]["length_m"]
    print("| end | d / b | d (um) | ratio, levels | its change | rule q (N/m) | predicted (MPa) | whole body (MPa) | body / predicted - 1 |")
    print("|---|---|---|---|---|---|---|---|---|")
    for end in check["ends"]:
        if end["end_model_singular"] or end["rule_match_distance_m"] is None:
            continue
        d_m = end["rule_match_distance_m"]
        inward = 1 if end["position_m"] < 0.5 * length else -1
        q_at = lambda d: interpolate(planes, end["position_m"] + inward * d, 2)
        acute = end["compared"].startswith("near-edge")
        body = end["body_near_edge_peak_pa"] if acute else end["body_edge_pa"]
        unit = d_m / check.get("end_match_over_half_width", 4)  # the locus's b at the end (4: the default)
        for over_b in distances:
            d = over_b * unit
            ratios = [(l["end_peak_pa"] if acute else l["edge_pressure_pa"])
                      / interpolate(l["centre_line_x_m_pressure_pa"], -d, 1) for l in end["end_model_levels"]]
            change = (ratios[-1] - ratios[-2]) / max(ratios[-1], 1) if len(ratios) > 1 else float("nan")
            predicted = ratios[-1] * end["slice_peak_pa"] * math.sqrt(q_at(d) / q_at(d_m))
            print(f"| {end['position_m'] / length:.2f} | {over_b:g} | {1e6 * d:.1f} | "
                  f"{', '.join(f'{r:.4f}' for r in ratios)} | {100 * change:+.2f} % | {q_at(d):.0f} | "
                  f"{predicted / 1e6:.2f} | {body / 1e6:.2f} | {100 * (body / predicted - 1):+.2f} % |")


if __name__ == "__main__":
    main()
