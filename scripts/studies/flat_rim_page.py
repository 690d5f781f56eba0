#!/usr/bin/python3
"""Writes docs/results/flat-rim.md from the JSON of scripts/studies/flat_rim.sh
(`rollcheck flat-rim --json`: the vertex on both counter-faces,
vertex_rigid.json and vertex_steel.json, and the flattest ends on the rigid
plane, end_A_rigid.json).

usage: flat_rim_page.py OUT_DIR "ROLLCHECK --version LINE" > docs/results/flat-rim.md
"""
import sys

from results_page import load, page_main, pct, table


def gpa(x):
    return f"{x / 1e9:.3f}"


def levels_peaks(r):
    return ", ".join(gpa(level["peak_pressure_pa"]) for level in r["levels"])


def vertex_section(out_dir):
    out = ["## Measured: the finished oloid at its vertex (r1 = 10 mm, F = 800 N, r_e = 0.4 mm)\n",
           "`rollcheck flat-rim [--counter-face steel] --json F` (the defaults are this case), one process.",
           "The peak at each grid level (the last in bold), its change when the cells halve and when the window",
           "doubles, where it sits along the ruling from the end P (x'), where the contact starts, and the peak",
           "over line Hertz at the end's q with R = r_e:\n"]
    rows = []
    for face in ("rigid", "steel"):
        r = load(out_dir / f"vertex_{face}.json")
        last = r["levels"][-1]
        peaks = [gpa(level["peak_pressure_pa"]) for level in r["levels"]]
        peaks[-1] = f"**{peaks[-1]}**"
        rows.append([face, f"{r['end_line_load_n_per_m']:.0f}", f"{1e6 * r['half_width_m']:.1f}", ", ".join(peaks),
                     pct(r["last_change"]), pct(r["window_change"]), f"{1e3 * last['peak_along_m']:.2f}",
                     f"{1e3 * last['contact_start_m']:.3f}", pct(last["window_load_change"], 1),
                     f"{last['balanced_end_line_load_n_per_m']:.0f}", gpa(r["line_hertz_peak_pa"]),
                     f"{r['peak_pressure_pa'] / r['line_hertz_peak_pa']:.3f}",
                     "yes" if r["converged"] else "NO"])
    out += table(["counter-face", "q(P) of the locus (N/m)", "b (um)", "peak (GPa) per level", "cells halved",
                  "window doubled", "peak at x' (mm)", "contact from x' (mm)", "window's load vs the locus's",
                  "rule's q(P) after balance (N/m)", "line Hertz at P, R = r_e (GPa)", "peak / that", "converged"],
                 rows)
    rigid = load(out_dir / "vertex_rigid.json")
    out += [f"At the window's far station the pressure is line Hertz's at its q and R within "
            f"{pct(rigid['far_line_hertz_error'])} (rigid). The finish lifts the apex off the ground "
            f"({1e6 * rigid['end_lift_m']:.1f} um at P): the contact starts "
            f"{1e3 * rigid['levels'][-1]['contact_start_m']:.2f} mm inside the ruling and the peak sits "
            f"{1e3 * rigid['levels'][-1]['peak_along_m']:.2f} mm from P.\n"]
    return out


def ends_section(out_dir):
    out = ["## The loop's flattest ends (rigid plane)\n",
           "`rollcheck flat-rim --end-angle A --json F`: the oloid's loop end of section angle A, at the vertex's",
           "settings (each a node of the rim loop's flat-rim table), one process:\n"]
    rows = []
    for angle in (160, 170, 180):
        r = load(out_dir / (f"end_{angle}_rigid.json" if angle < 180 else "vertex_rigid.json"))
        rows.append([f"{r['end_interior_angle_deg']:.1f}" + (" (the vertex)" if angle == 180 else ""),
                     f"{r['centre_of_pressure']:.4f}", f"{r['end_line_load_n_per_m']:.0f}",
                     f"{1e3 * r['end_sheet_radius_m']:.3f}", gpa(r["peak_pressure_pa"]), gpa(r["line_hertz_peak_pa"]),
                     f"{r['peak_pressure_pa'] / r['line_hertz_peak_pa']:.3f}", pct(r["last_change"]),
                     pct(r["window_change"]), "yes" if r["converged"] else "NO"])
    out += table(["interior angle (deg)", "c from the end", "q at the end (N/m)", "hull's R at the end (mm)",
                  "peak (GPa)", "line Hertz at R = max(R, r_e) (GPa)", "peak / line Hertz", "cells halved",
                  "window doubled", "converged"], rows)
    out += ["The peak grows towards the vertex: the vertex is the loop's largest end. Its ratio to line Hertz",
            "need not: line Hertz at R = max(R, r_e) has a kink where the hull's R passes r_e, so the loop's",
            "flat-rim table interpolates the peak, not the ratio.\n"]
    return out


def history():
    return ["## Checked against fuller models\n",
            "The flat-rim tables of whole loops on both counter-faces (from `rollcheck rim --body oloid`), the",
            "check against the FEM end model and the check against the whole loaded ruling are runs too long",
            "for this page's script: their tables,",
            "with the commands verbatim and the versions that made them, are in",
            "[notes](../notes/flat-rim-tables.md) (not regenerated), the whole-ruling check under",
            "[checked against the whole ruling](../notes/flat-rim-tables.md#checked-against-the-whole-ruling-the-window-against-a-fuller-model).\n"]


def main(argv):
    page_main(argv, __doc__, "Flat rims: results", "flat_rim.sh [ROLLCHECK] [OUT_DIR]",
              "`rollcheck flat-rim` at the vertex on both counter-faces and at the flattest ends",
              "[flat rim](../methods/flat-rim.md)",
              lambda out_dir: vertex_section(out_dir) + ends_section(out_dir) + history())

if __name__ == "__main__":
    main(sys.argv)
