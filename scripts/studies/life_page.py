#!/usr/bin/python3
"""Writes docs/results/life.md from `rollcheck life --json`.

usage: life_page.py LIFE.json "ROLLCHECK --version LINE" > docs/results/life.md
"""
import json
import sys
from pathlib import Path

from robustness_page import fmt  # the results pages' one number format


def load(x):
    return f"{x:.4g}"


def flips_text(c):
    seen = []
    for f in c["flips"]:
        t = f"{f['choice']} {f['from']} -> {f['to']}"
        if t not in seen:
            seen.append(t)
    return "; ".join(seen[:4]) + (f"; {len(seen) - 4} more" if len(seen) > 4 else "") if seen else "-"


def subsurface_section(s):
    out = ["## The FEM slice against the closed form\n",
           f"One plane-strain slice, R = {fmt(s['slice_radius_m'])} m, q = {fmt(s['slice_load_n_per_m'])} N/m",
           "(the cylinder's at 5000 N), P2; stresses over the Hertz p0 and b of the load it carries.\n",
           "| refine | elements across b | dofs | largest shear / p0 | its depth / b | orthogonal shear / p0 | its depth / b | its offset / b |",
           "|---|---|---|---|---|---|---|---|"]
    for l in s["levels"]:
        out.append(f"| {l['refine']} | {l['elements_across_b']:.0f} | {l['dofs']} | {l['max_shear_over_p0']:.4f} | "
                   f"{l['max_shear_depth_over_b']:.4f} | {l['orthogonal_shear_over_p0']:.4f} | "
                   f"{l['orthogonal_shear_depth_over_b']:.4f} | {l['orthogonal_shear_offset_over_b']:.4f} |")
    out.append(f"| closed form | | | {s['closed_max_shear_over_p0']:.4f} | {s['closed_max_shear_depth_over_b']:.4f} | "
               f"{s['closed_orthogonal_shear_over_p0']:.4f} | {s['closed_orthogonal_shear_depth_over_b']:.4f} | "
               f"{s['closed_orthogonal_shear_offset_over_b']:.4f} |\n")
    out.append(f"The life integrals scale the closed-form field by the finest level's ratios: largest shear "
               f"{s['max_shear_ratio']:.4f}, orthogonal shear {s['orthogonal_shear_ratio']:.4f} (a factor common "
               f"to every body, which cancels from every life ratio: the slice verifies the field, it does not "
               f"change a ratio).\n")
    return out


def quadrature_section(d):
    """The oloid / cylinder life at the loop's quadrature and at half of it."""
    rows = d.get("quadrature_convergence", [])
    if not rows:
        return []
    out = ["## Convergence of the loop's quadrature\n",
           f"The oloid / cylinder Lundberg-Palmgren life (orthogonal shear) at the default cell, at "
           f"{d['samples_per_loop']} samples a loop and {d['pieces']} pieces a ruling, and at half of both "
           "(the loop rolled again):\n",
           "| load N | life ratio | at half the quadrature | change |", "|---|---|---|---|"]
    for q in rows:
        change = "-" if q["change"] is None else f"{100 * q['change']:+.2f} %"
        out.append(f"| {load(q['load_n'])} | {fmt(q['oloid_over_cylinder_life'])} | "
                   f"{fmt(q['oloid_over_cylinder_life_half_quadrature'])} | {change} |")
    out.append("")
    return out


def untested_section(d):
    """Why the comparisons that cannot be tested cannot, each reason once with its loads."""
    reasons = {}
    for c in d["comparisons"]:
        if c["untested_because"]:
            reason = c["untested_because"].rsplit(" at ", 1)[0]
            reasons.setdefault(reason, set()).add(load(c["load_n"]))
    if not reasons:
        return []
    out = ["Why a comparison *cannot be tested*:\n"]
    for reason, loads in reasons.items():
        out.append(f"- at {', '.join(sorted(loads, key=float))} N: {reason}.")
    return out + [""]


def governs(life):
    """Which part governs the life over the edge radii computed, in brief."""
    if life["interior_governs_from_edge_radius_over_radius"] is None:
        return "the ends, at every r_e"
    if life["rows"][0]["end_over_interior"] < 1:
        return "the interior, at every r_e"
    return "the ends below, the interior above"


def rims_section(d):
    r = d["rims"]
    at = r["rim_study_edge_radius_over_radius"]
    t = r["end_table"]
    cell = ", ".join(f"{k} {v}" for k, v in r["cell"].items())
    out = ["## The rounded rim ends\n",
           f"At one cell ({cell}), {r['model']} ({r['criterion']}), with the rims rounded to an edge radius",
           f"r_e (a fraction of the body's r1: {', '.join(fmt(x) for x in r['edge_radius_over_radius'])}; "
           f"the rim study's finish is {fmt(at)}).",
           f"Assumed: {r['assumptions']}; the end patch is {fmt(r['zone_over_half_width'])} b long.",
           f"End table ({t['interior_angle_deg']} deg end models): rho = "
           + ", ".join(f"{fmt(y)} at R / r_e = {fmt(x)}" for x, y in zip(t['r_over_edge_radius'], t['end_over_line_hertz']))
           + f"; from {t['source']}.\n",
           f"| body | load N | L10 with ends / without (r_e = {fmt(at)} r1) | ends outside the table | L10 / cylinder's, "
           "without ends | with ends | which governs | interior from r_e / r1 |",
           "|---|---|---|---|---|---|---|---|"]
    for x in r["lives"]:
        row = next((y for y in x["rows"] if y["edge_radius_over_radius"] == at), None)
        if row is None:
            out.append(f"| {x['body']} | {load(x['load_n'])} | - | - | - | - | not a rolling loop | - |")
            continue
        out.append(f"| {x['body']} | {load(x['load_n'])} | {fmt(row['life_with_over_without_ends'])} | "
                   f"{row['ends_outside_table']} of {row['ends']} | {fmt(x['interior_life_ratio_to_cylinder'])} | "
                   f"{fmt(row['life_ratio_to_cylinder_with_ends'])} | {governs(x)} | "
                   f"{fmt(x['interior_governs_from_edge_radius_over_radius'])} |")
    out.append("")
    return out


def main(argv):
    if len(argv) != 3:
        sys.exit(__doc__)
    d = json.loads(Path(argv[1]).read_text())
    out = ["# Rolling-contact fatigue life over the loop\n",
           "> Generated by `scripts/studies/life.sh` (`rollcheck life --json results/life/life.json`,",
           "> then `scripts/studies/life_page.py`); do not edit by hand.",
           f"> Made by: {argv[2]}; {d['wall_s']:.0f} s on the machine that made it.\n",
           "Method: [life](../methods/life.md). A life ratio is the first body's L10 life (in loops) over the",
           "cylinder's at the same load and steel: above 1 the first body lives longer. A verdict is *robust*",
           "when every cell of the grid ranks the two bodies alike; else it names the choices along which the",
           "ranking flips. \"inf\": the cylinder (or the body) never reaches the fatigue limit.\n"]
    out += subsurface_section(d["subsurface"])
    out.append("## Load-life exponent\n")
    out.append(f"Derived (c + 1 - h) / (2 e) = {d['load_life_exponent_derived']:.4f}; measured from the")
    out.append(f"Lundberg-Palmgren integral at {', '.join(fmt(x) for x in d['exponent_loads_n'])} N "
               "(direct quadrature over absolute depth):\n")
    out.append("| body | exponent | direct / tabulated integral - 1 |")
    out.append("|---|---|---|")
    for e in d["load_life_exponents"]:
        out.append(f"| {e['body']} | {e['load_life_exponent']:.4f} | {e['direct_over_tabulated_minus_one']:.2e} |")
    out.append("\n## Life ratios against the cylinder\n")
    grid = ", ".join(f"{k} ({', '.join(d['grid'][k])})" for k in d["grid_order"])
    out.append(f"Grid: {grid}. Loads: {', '.join(load(x) for x in d['loads_n'])} N.\n")
    out.append("A range is over the cells of the grid where the ratio is defined (both bodies roll a whole loop, "
               "and not both lives are infinite): `cells` of the grid's in the JSON.\n")
    out.append("| comparison | load N | model | criterion | verdict | life ratio min | life ratio max | flips |")
    out.append("|---|---|---|---|---|---|---|---|")
    for c in d["comparisons"]:
        out.append(f"| {c['name']} | {load(c['load_n'])} | {c['model']} | {c['criterion']} | {c['verdict']} | "
                   f"{fmt(c['life_ratio_min'])} | {fmt(c['life_ratio_max'])} | {flips_text(c)} |")
    out.append("")
    out += untested_section(d)
    out += rims_section(d)
    out += quadrature_section(d)
    out.append("## Dang Van check\n")
    out.append(f"The Dang Van stress of a pass peaks at {d['dang_van_peak_over_p0']:.4f} p0, "
               f"{d['dang_van_peak_depth_over_b']:.3f} b deep (alpha = {d['constants']['dang_van_alpha']}).")
    out.append("For a line-contact pass it is that multiple of p0, so its largest value over the grid over its "
               "value at the 1.5 GPa limit contact stress is the largest p0 over 1.5 GPa: a multiaxial view of the "
               "same peak, not independent evidence.\n")
    out.append("| body | load N | Dang Van / limit |")
    out.append("|---|---|---|")
    for x in d["dang_van"]:
        out.append(f"| {x['body']} | {load(x['load_n'])} | {fmt(x['max_over_limit'])} |")
    print("\n".join(out))


if __name__ == "__main__":
    main(sys.argv)
