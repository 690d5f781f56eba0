#!/usr/bin/python3
"""Writes docs/results/whole-body.md from the JSON of scripts/studies/whole_body.sh
(`mpirun -n 2 rollcheck whole-body --json`: the 10 mm cylinder at the defaults).

usage: whole_body_page.py CYLINDER.json "ROLLCHECK --version LINE" > docs/results/whole-body.md
"""
import sys

from results_page import load, num, page_main, pct, table


def stations_section(j):
    L = j["ruling"]["length_m"]
    out = ["Stations along the ruling: the line load of the contact locus's rule and the whole body's own, the",
           "slices' peak (plane strain at the rule's q and the station's R) and the whole body's:\n"]
    rows = [[f"{st['position_m'] / L:.4f}", f"{st['radius_m']:.6g}", f"{st['rule_load_n_per_m']:.1f}",
             pct(st["load_difference"]), f"{st['slice_peak_pa'] / 1e6:.2f}", f"{st['body_peak_pa'] / 1e6:.2f}",
             pct(st["peak_difference"]), pct(st["peak_difference_at_body_load"])] for st in j["stations"]]
    out += table(["station s / L", "R (m)", "q locus (N/m)", "q body / locus - 1", "slice p (MPa)", "body p (MPa)",
                  "body / slice - 1", "the same at the body's q"], rows)
    return out


def ends_section(j):
    out = [f"The ends: the end model (a rim end on a block {j['ends'][0]['end_model_depth_over_half_width']:.1f} b "
           f"deep, the `{j['end_depth']}` depth, on the {j['ends'][0]['end_model_mesh']} mesh) at each end's q and R, "
           "its edge over the interior times the slice's peak there, against the whole body's edge:\n"]
    rows = []
    for name, e in zip(("start", "end"), j["ends"]):
        levels = ", ".join(f"{lv['edge_pressure_pa'] / lv['far_peak_pa']:.4f}" if lv.get("edge_pressure_pa")
                           else "-" for lv in e["end_model_levels"])
        model = ("singular" if e["end_model_singular"] else
                 f"{num(e['end_model_end_to_interior'], '.4f')} ({'converged' if e['end_model_converged'] else 'NOT converged'}, "
                 f"{pct(e['end_model_change'])} at the last level; levels {levels})")
        rows.append([name, f"{e['interior_angle_deg']:.2f}", f"{e['load_n_per_m']:.0f}", model,
                     num(e["predicted_edge_pa"] and e["predicted_edge_pa"] / 1e6, ".2f"),
                     f"{e['body_edge_pa'] / 1e6:.2f}", f"{e['body_edge_to_interior']:.4f}", pct(e["difference"])])
    out += table(["end", "interior angle (deg)", "q (N/m)", "end model edge / interior", "predicted edge (MPa)",
                  "body edge (MPa)", "body edge / its interior", "body / predicted - 1"], rows)
    return out


def body(path):
    j = load(path)
    r, m, wb = j["ruling"], j["mesh"], j["whole_body"]
    lines = [f"## The 10 mm cylinder (L = {1e3 * r['length_m']:.0f} mm, F = {j['normal_load_n']:g} N, steel, "
             f"b = {1e6 * r['half_width_m']:.1f} um, b/L = {r['half_width_over_length']:.2g})\n",
             f"Whole body mesh: {m['node_planes']} node planes x {m['section_nodes']} nodes, {m['dofs']} DOFs, "
             f"contact elements {1e6 * m['contact_element_m']:.2f} um, end layers {1e6 * m['end_layer_m']:.2f} um; "
             f"{wb['load_steps']} load steps, reaction {wb['reaction_n']:.3f} N, centre of pressure "
             f"{wb['centre_of_pressure']:.6f} L. Share rule: `{j['share_rule']}`.\n"]
    lines += stations_section(j) + ends_section(j)
    return lines + [f"**Verdict**: {j['verdict']}\n",
                    "## The oloid, other meshes and load rules\n",
                    "The oloid at `--direction 67.5` under each share rule (the locus's, `sections`, `coarse-body`)",
                    "and the cylinder with only its end layers thinned are runs too long for this page's script:",
                    "their tables, with the commands verbatim and the versions that made them, are in",
                    "[notes](../notes/whole-body-tables.md) (not regenerated)."]


def main(argv):
    page_main(argv, __doc__, "The whole-body check: results", "whole_body.sh [ROLLCHECK] [OUT_DIR]",
              "`mpirun -n 2 rollcheck whole-body --json F`, the cylinder at the defaults",
              "[whole body](../methods/whole-body.md). All runs on 2 ranks", body)

if __name__ == "__main__":
    main(sys.argv)
